"""Check the settled column (glass and steel beads) against random-packing references and draw it.

Solid fraction of the bed: particle volume inside the slab 0.2 h < z < 0.8 h (sphere-slab
intersections counted exactly) over the slab's volume, with the bed height h from the total
particle volume, h = V / (A phi), iterated. Reference: poured frictional spheres lie between
random loose packing (0.55) and random close packing (0.64); a column 16 diameters wide has a
lower fraction near its wall, so the bed average sits in the lower half of that range.
Checks: phi in [0.55, 0.64]; the bed at rest (kinetic energy per particle below 1e-3 of
m g d); no particle lost. Exits non-zero on any FAIL."""
import os
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import EllipseCollection
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
import foamcase as fc  # noqa: E402


def cap_volume(r, h):
    """Volume of a sphere of radius r below a plane at height h above its bottom (0..2r)."""
    h = np.clip(h, 0.0, 2.0 * r)
    return np.pi * h * h * (3.0 * r - h) / 3.0


def slab_volume(z, r, lo, hi):
    """Volume of each sphere (centre z, radius r) between the planes z = lo and z = hi."""
    return cap_volume(r, hi - (z - r)) - cap_volume(r, lo - (z - r))


def main(path, png):
    with h5py.File(path, "r") as f:
        snaps = sorted(k for k in f["snapshots"] if "complete" in f["snapshots"][k].attrs)
        first, last = f["snapshots"][snaps[0]], f["snapshots"][snaps[-1]]
        x = last["position"][...]
        v = last["velocity"][...]
        r = last["radius"][...]
        n0 = int(first.attrs["n"])
        t = float(last.attrs["time"])
        kind = last["type"][...]
    rho = np.where(kind == 0, 2500.0, 7800.0)   # glass, steel (materials in demProperties order)
    g, column_radius = 9.81, 0.025
    area = np.pi * column_radius ** 2
    volume = 4.0 / 3.0 * np.pi * r ** 3
    h = 2.0 * np.mean(x[:, 2])
    for _ in range(20):
        phi = slab_volume(x[:, 2], r, 0.2 * h, 0.8 * h).sum() / (area * 0.6 * h)
        h = volume.sum() / (area * phi)
    mass = rho * volume
    ke = 0.5 * (mass * (v ** 2).sum(axis=1)).sum() / len(r)
    ke_scale = np.mean(mass) * g * 2.0 * np.mean(r)
    steel_height = np.mean(x[kind == 1, 2]) / np.mean(x[kind == 0, 2])

    checks = fc.Checks()
    print(f"t = {t:.3g} s: {len(r)} particles, bed height {1000 * h:.1f} mm, solid fraction {phi:.4f}")
    checks.within("solid_fraction", phi, 0.55, 0.64)
    checks.within("kinetic_energy_per_particle_over_mgd", ke / ke_scale, 0.0, 1e-3)
    checks.within("particles_kept", len(r), n0, n0)
    print(f"mean height of steel over mean height of glass: {steel_height:.3f} (no segregation: 1)")

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 6), gridspec_kw={"width_ratios": [1, 1.2]})
    front = x[:, 1] < 0.0
    d = 2000 * r[front]
    colours = np.where(kind[front] == 0, "#6fa8dc", "#555555")
    sc = EllipseCollection(d, d, np.zeros_like(d), units="xy", offsets=1000 * x[front][:, [0, 2]],
                           offset_transform=ax1.transData, facecolors=colours, edgecolors="k", linewidths=0.2)
    ax1.add_collection(sc)
    ax1.set_aspect("equal")
    ax1.set_xlim(-26, 26)
    ax1.set_ylim(0, max(60, 1100 * h))
    ax1.set_xlabel("x [mm]")
    ax1.set_ylabel("z [mm]")
    ax1.set_title(f"front half, t = {t:.2f} s\nglass (blue), steel (grey)")
    edges = np.linspace(0.0, 1.2 * h, 25)
    prof = [slab_volume(x[:, 2], r, a, b).sum() / (area * (b - a)) for a, b in zip(edges[:-1], edges[1:])]
    ax2.step(prof, 1000 * edges[:-1], where="post", label="measured")
    ax2.axvspan(0.55, 0.64, color="green", alpha=0.15, label="random loose to close packing")
    ax2.axhline(1000 * h, color="k", ls="--", lw=0.8, label=f"bed height {1000 * h:.1f} mm")
    ax2.set_xlim(0, 0.75)
    ax2.set_xlabel("solid fraction [-]")
    ax2.set_ylabel("z [mm]")
    ax2.set_title(f"bed solid fraction {phi:.3f}")
    ax2.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print(f"wrote {png}")
    return 1 if checks.failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
