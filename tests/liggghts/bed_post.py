#!/usr/bin/python3
"""Bed height and solid fraction of a settled bed of spheres, the same for both codes.

usage: bed_post.py liggghts <dump file>     (LIGGGHTS dump custom with id radius x y z vx vy vz)
       bed_post.py ours     <particles.h5>  (our HDF5 output; the last snapshot is used)
       options: --area A [m^2] (default 1.6e-3 = 40 mm x 40 mm), --floor z0 [m] (default 0),
                --rho [kg/m^3] (default 2500, for the kinetic energy)

Definitions (independent of the random packing of the top surface):
  solid fraction phi = particle volume inside the slab z0 + [0.2 h, 0.8 h] (exact sphere-slab
                       intersection volumes) / slab volume (A * 0.6 h)
  bed height h       = total particle volume / (A * phi)
h and phi depend on each other; the pair is found by fixed-point iteration.
Prints RESULT lines: particles, bed_height, solid_fraction, kinetic_energy (translational, J),
ke_per_particle_over_mgd (kinetic energy per particle / (m g d) with the mean m and d).
"""
import sys
import numpy as np


def read_liggghts_dump(path):
    """Last snapshot of a LIGGGHTS/LAMMPS 'dump custom' text file -> dict of columns."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[start].split()[2:]
    n = int(lines[start - 5])  # ITEM: NUMBER OF ATOMS / n / ITEM: BOX BOUNDS / 3 lines
    data = np.loadtxt(lines[start + 1:start + 1 + n], ndmin=2)
    if data.shape[0] != n:
        sys.exit("bed_post.py: truncated dump %s" % path)
    d = {c: data[:, i] for i, c in enumerate(cols)}
    return (np.column_stack([d["x"], d["y"], d["z"]]), d["radius"],
            np.column_stack([d["vx"], d["vy"], d["vz"]]))


def read_ours(path):
    import h5py
    with h5py.File(path, "r") as f:
        snaps = f["snapshots"]
        keys = sorted(k for k in snaps.keys() if "complete" in snaps[k].attrs)
        if not keys:
            sys.exit("bed_post.py: no complete snapshot in %s" % path)
        g = snaps[keys[-1]]
        return (np.asarray(g["position"], float), np.asarray(g["radius"], float),
                np.asarray(g["velocity"], float))


def slab_volume(zc, r, a, b):
    """Exact volume of spheres (centres zc, radii r) between the planes z = a and z = b."""
    t1 = np.clip(a - zc, -r, r)
    t2 = np.clip(b - zc, -r, r)
    prim = lambda t: np.pi * (r * r * t - t ** 3 / 3.0)
    return np.sum(prim(t2) - prim(t1))


def main(argv):
    opts = {"--area": 1.6e-3, "--floor": 0.0, "--rho": 2500.0}
    args = []
    i = 0
    while i < len(argv):
        if argv[i] in opts:
            opts[argv[i]] = float(argv[i + 1]); i += 2
        else:
            args.append(argv[i]); i += 1
    if len(args) != 2 or args[0] not in ("liggghts", "ours"):
        sys.exit(__doc__)
    pos, rad, vel = (read_liggghts_dump if args[0] == "liggghts" else read_ours)(args[1])
    area, z0, rho = opts["--area"], opts["--floor"], opts["--rho"]
    zc = pos[:, 2] - z0
    vtot = np.sum(4.0 / 3.0 * np.pi * rad ** 3)

    phi = 0.6
    h = vtot / (area * phi)
    for _ in range(200):
        phi = slab_volume(zc, rad, 0.2 * h, 0.8 * h) / (area * 0.6 * h)
        hn = vtot / (area * phi)
        if abs(hn - h) < 1e-13:
            h = hn
            break
        h = hn
    else:
        sys.exit("bed_post.py: bed height iteration did not converge")

    mass = rho * 4.0 / 3.0 * np.pi * rad ** 3
    ke = 0.5 * np.sum(mass * np.sum(vel * vel, axis=1))
    ke_rel = ke / len(rad) / (np.mean(mass) * 9.81 * 2.0 * np.mean(rad))
    print("RESULT particles %d" % len(rad))
    print("RESULT bed_height %.6g" % h)
    print("RESULT solid_fraction %.6g" % phi)
    print("RESULT kinetic_energy %.6g" % ke)
    print("RESULT ke_per_particle_over_mgd %.6g" % ke_rel)


if __name__ == "__main__":
    main(sys.argv[1:])
