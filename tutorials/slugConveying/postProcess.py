#!/usr/bin/env python3
"""slugConveying: measure the slug of a run, check it and draw it.

Reads (the case directory given as the argument):
  particles.h5: the particle snapshots (every writeInterval);
  postProcessing/drivingGradient.dat: the driving gradient and the pipe's balance, every step;
  constant/: the beads' density and diameter, g, the pipe (domain: length L, diameter D).
Measured on every snapshot t >= t_stats (the slug's quasi-steady motion):
  the solid fraction of 50 slices along the pipe (20 mm; the beads' volume by centre over the
      slice's share of the mesh's volume, 5.4004e-3 m^3, the 16-facet pipe's);
  the slug: the longest run of slices whose fluid fraction is below 0.55 (Lethe's threshold),
      taken periodically; its length, its front (the downstream end) and its rear;
  u_p: the mean axial velocity of the beads in the slug;
  the solids mass flow W = sum(m u_x) / L [kg/s];
  the slug velocity u_slug: the slope of a straight-line fit of the front's position, unwrapped
      across the periodic ends, against time (the rear's slope is printed beside it).
Checks (CHECK lines; exit 1 on a FAIL):
  slug_velocity: u_slug against Lavrinec et al.'s correlation (Powder Technol. 375, 2020),
      u_slug = 0.967 u_p + 0.5 sqrt(g D), within 10 %: a relation for the developed slug, so
      with -short (the first 0.3 s, while the slug still sheds more at its rear than it picks up
      at its front) it is printed, not checked;
  held_velocity: the gas's mean velocity that constant/drivingGradient holds (its `average`:
      superficial or interstitial) at Ubar, within 0.5 %, over the window;
  momentum_balance: the pipe's time-mean balance over the window, rho_f G V = the gas's wall
      shear + the beads' wall forces + the rate of change of the beads' momentum (from the
      first and last snapshots of the window; the gas's is held fixed by the drive), within 1 %;
  particle_count: every snapshot holds the beads inserted at the start (none is lost: the pipe
      is closed, periodic along x);
  slug_present: a slug exists in every snapshot of the window.
Printed beside Lethe's published figures (their example: slug 1.30 m/s, beads in the slug
0.83 m/s, solids mass flow 1.40 kg/s, slug length 0.47 m).
Pictures: slugConveying.png (the pipe from the side at six times, beads coloured by axial
velocity; the solid-fraction map along the pipe against time; the front's position; the
driving gradient) and slugConveying.gif (the side view, every snapshot).
Usage: postProcess.py <case> [t_stats] [-short]   (t_stats default 2 s)
"""
import math
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "tools"))
import foamcase as fc  # noqa: E402

THRESHOLD = 0.55          # fluid fraction below which a slice is slug (Lethe's post-processing)
SLICE = 0.02              # [m] slice length
MESH_VOLUME_PER_M = 5.4004286e-3   # [m^3/m] the mesh's cross-section (checkMesh: total volume / L)
LETHE = {"slug velocity": 1.30, "bead velocity in slug": 0.83, "solids mass flow": 1.40, "slug length": 0.47}
TOL_SLUG, TOL_BALANCE = 10.0, 1.0


def case_parameters(case):
    dem = fc.read_dict(os.path.join(case, "constant/demProperties"))
    dom = fc.sub_dict(dem, "domain")
    lo, hi = np.array(fc.vector(dom, "min")), np.array(fc.vector(dom, "max"))
    beads = fc.sub_dict(fc.sub_dict(dem, "materials"), "beads")
    d = fc.scalar(fc.sub_dict(fc.sub_dict(dem, "slug"), "diameter"), "value")
    tr = fc.read_dict(os.path.join(case, "constant/transportProperties"))
    g = np.array(fc.vector(fc.read_dict(os.path.join(case, "constant/g")), "value"))
    return {"L": hi[0] - lo[0], "x0": lo[0], "D": hi[1] - lo[1], "rho_p": fc.scalar(beads, "density"),
            "d": d, "rho_f": fc.scalar(tr, "rho"), "g": float(np.linalg.norm(g))}


def slug_of(fraction):
    """(start, length) in slices of the longest periodic run of fraction-of-fluid < THRESHOLD,
    or None."""
    inside = fraction < THRESHOLD
    n = len(inside)
    if inside.all():
        return 0, n
    if not inside.any():
        return None
    s = int(np.argmin(inside))          # a slice outside: runs cannot wrap past it
    best, run, start = (0, 0), 0, 0
    for k in range(1, n + 1):
        i = (s + k) % n
        if inside[i]:
            if run == 0:
                start = i
            run += 1
            if run > best[1]:
                best = (start, run)
        else:
            run = 0
    return best


def measure(case, par):
    nslice = int(round(par["L"] / SLICE))
    vp = math.pi / 6 * par["d"] ** 3
    mp = par["rho_p"] * vp
    slice_volume = MESH_VOLUME_PER_M * par["L"] / nslice
    rows, snaps = [], []
    for t, x, v in fc.snapshots(case):
        k = np.clip(((x[:, 0] - par["x0"]) / par["L"] * nslice).astype(int), 0, nslice - 1)
        solid = np.bincount(k, minlength=nslice) * vp / slice_volume
        fluid = 1.0 - solid
        s = slug_of(fluid)
        if s is None:
            rows.append((t, len(x), np.nan, np.nan, np.nan, np.nan, mp * v[:, 0].sum() / par["L"], v[:, 0].mean()))
        else:
            start, n = s
            in_slug = ((k - start) % nslice) < n
            rear = par["x0"] + start * SLICE
            front = rear + n * SLICE
            rows.append((t, len(x), n * SLICE, front, rear, v[in_slug, 0].mean(),
                         mp * v[:, 0].sum() / par["L"], v[:, 0].mean()))
        snaps.append((t, x, v, solid))
    return np.array(rows), snaps, mp


def unwrap(x, period):
    out = np.array(x, dtype=float)
    for i in range(1, len(out)):
        step = out[i] - out[i - 1]
        out[i:] -= period * np.round(step / period)
    return out


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else "."
    t_stats = float(sys.argv[2]) if len(sys.argv) > 2 else 2.0
    short = "-short" in sys.argv[3:]
    par = case_parameters(case)
    rows, snaps, mp = measure(case, par)
    checks = fc.Checks()
    t = rows[:, 0]
    w = t >= t_stats - 1e-9
    n0 = int(rows[0, 1])
    if w.sum() < 3:
        checks.missing("slug_velocity", f"fewer than 3 snapshots after t = {t_stats} s")
        return 1
    present = np.isfinite(rows[w, 2])
    checks.within("slug_present", float(present.mean()), 1.0, 1.0, note=f"share of the {w.sum()} snapshots "
                  f"from {t_stats} s with a slug (fluid fraction < {THRESHOLD} over a run of slices)")
    ww = w & np.isfinite(rows[:, 2])
    front = unwrap(rows[ww, 3], par["L"])
    rear = unwrap(rows[ww, 4], par["L"])
    tt = t[ww]
    u_slug = np.polyfit(tt, front, 1)[0] if len(tt) > 2 else np.nan
    u_rear = np.polyfit(tt, rear, 1)[0] if len(tt) > 2 else np.nan
    u_p = rows[ww, 5].mean()
    length = rows[ww, 2].mean()
    W = rows[w, 6].mean()
    corr = 0.967 * u_p + 0.5 * math.sqrt(par["g"] * par["D"])
    print(f"window {t_stats:g}-{t[-1]:g} s, {w.sum()} snapshots:")
    print(f"  slug velocity (front) {u_slug:.3f} m/s (rear {u_rear:.3f} m/s); Lethe {LETHE['slug velocity']} m/s")
    print(f"  bead velocity in the slug {u_p:.3f} m/s; Lethe {LETHE['bead velocity in slug']} m/s")
    print(f"  solids mass flow {W:.3f} kg/s; Lethe {LETHE['solids mass flow']} kg/s")
    print(f"  slug length {length:.3f} m (std {rows[ww, 2].std():.3f}); Lethe {LETHE['slug length']} m")
    print(f"  Lavrinec et al. 2020: 0.967 u_p + 0.5 sqrt(g D) = {corr:.3f} m/s")
    if short:
        print(f"  slug velocity {u_slug:.3f} m/s against the correlation's {corr:.3f} m/s: "
              f"{100 * (u_slug / corr - 1):+.1f} %, not checked: the slug is still forming (the full run checks it)")
    else:
        checks.relative("slug_velocity", u_slug, corr, TOL_SLUG,
                        note="the front's speed against Lavrinec et al.'s correlation at the measured u_p")

    b = fc.table(os.path.join(case, "postProcessing/drivingGradient.dat"))
    bw = (b[:, 0] >= t[ww][0] - 1e-9) & (b[:, 0] <= t[ww][-1] + 1e-9)
    drive, walls, pwalls = b[bw, 3].mean(), b[bw, 8].mean(), b[bw, 12].mean()
    span = t[ww][-1] - t[ww][0]
    i0, i1 = np.where(ww)[0][[0, -1]]
    dPdt = mp * n0 * (rows[i1, 7] - rows[i0, 7]) / span
    imbalance = (drive + walls + pwalls - dPdt) / drive
    print(f"  pipe balance over {t[ww][0]:g}-{t[ww][-1]:g} s: rho_f G V {drive:.5g} N = gas wall shear {-walls:.5g} N "
          f"+ beads' wall forces {-pwalls:.5g} N + beads' momentum change {dPdt:.4g} N; imbalance {100 * imbalance:+.3f} %; "
          f"mean gradient {b[bw, 1].mean():.5g} Pa/m, superficial gas velocity {b[bw, 2].mean():.4f} m/s")
    checks.deviation("momentum_balance", abs(imbalance), TOL_BALANCE,
                     note="drive = gas wall shear + beads' wall forces + beads' momentum change, time mean")
    drive_dict = fc.read_dict(os.path.join(case, "constant/drivingGradient"))
    ubar = float(np.linalg.norm(fc.vector(drive_dict, "Ubar")))
    average = re.search(r"\baverage\s+(\w+)\s*;", drive_dict)
    interstitial = bool(average) and average.group(1) == "interstitial"
    held = b[bw, 14].mean() if interstitial else b[bw, 2].mean()
    checks.relative("held_velocity", held, ubar, 0.5, note=f"the gas's mean {'interstitial' if interstitial else 'superficial'}"
                    f" velocity over the window (constant/drivingGradient; superficial {b[bw, 2].mean():.4f} m/s)")
    counts = rows[:, 1]
    checks.within("particle_count", float(counts.min()), n0, n0, note=f"every snapshot from 0 to {t[-1]:g} s "
                  f"holds {int(counts.max())} at most, {n0} at the start")
    draw(case, par, rows, snaps, b, t_stats, u_slug)
    return 1 if checks.failed else 0


def side_view(ax, par, x, v, vmax):
    keep = np.abs(x[:, 1]) < 0.5 * par["d"] * 3          # a slab through the axis, three beads thick
    ax.scatter(x[keep, 0], 1e3 * x[keep, 2], c=v[keep, 0], s=1.5, cmap="viridis", vmin=0, vmax=vmax,
               linewidths=0, rasterized=True)
    ax.set_xlim(par["x0"], par["x0"] + par["L"])
    ax.set_ylim(-500 * par["D"], 500 * par["D"])
    ax.set_aspect(1e-3 * 3)


def draw(case, par, rows, snaps, b, t_stats, u_slug):
    vmax = 2.5
    fig = plt.figure(figsize=(12, 9))
    picks = np.linspace(0, len(snaps) - 1, 6).astype(int)
    for j, i in enumerate(picks):
        ax = fig.add_axes([0.06, 0.90 - 0.075 * j, 0.55, 0.065])
        t, x, v, _ = snaps[i]
        side_view(ax, par, x, v, vmax)
        ax.set_yticks([])
        ax.text(1.01, 0.5, f"t = {t:.2f} s", transform=ax.transAxes, va="center", fontsize=8)
        if j < 5:
            ax.set_xticklabels([])
    ax.set_xlabel("x [m] (side view, a slab 15 mm thick through the axis; colour: axial velocity 0-2.5 m/s)")
    ax = fig.add_axes([0.70, 0.52, 0.27, 0.43])
    solid = np.array([s[3] for s in snaps])
    ts = [s[0] for s in snaps]
    im = ax.imshow(solid, aspect="auto", origin="lower", cmap="magma_r", vmin=0, vmax=0.65,
                   extent=[par["x0"], par["x0"] + par["L"], ts[0], ts[-1]])
    fig.colorbar(im, ax=ax, label="solid fraction of the slice")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("t [s]")
    ax.set_title("the slug along the pipe", fontsize=9)
    ax = fig.add_axes([0.06, 0.07, 0.40, 0.38])
    ok = np.isfinite(rows[:, 3])
    ax.plot(rows[ok, 0], unwrap(rows[ok, 3], par["L"]), "k.-", lw=0.8, label="front")
    ax.plot(rows[ok, 0], unwrap(rows[ok, 4], par["L"]), ".-", color="tab:blue", lw=0.8, label="rear")
    ax.axvspan(rows[0, 0], t_stats, color="0.9")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("position, unwrapped [m]")
    ax.set_title(f"slug front and rear (front {u_slug:.2f} m/s from {t_stats:g} s)", fontsize=9)
    ax.legend(fontsize=8)
    ax = fig.add_axes([0.56, 0.07, 0.40, 0.38])
    ax.plot(b[:, 0], b[:, 1], lw=0.6, color="tab:purple")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("driving gradient [Pa/m]", color="tab:purple")
    ax2 = ax.twinx()
    ax2.plot(rows[:, 0], rows[:, 6], "r.-", lw=0.8)
    ax2.set_ylabel("solids mass flow [kg/s]", color="tab:red")
    ax.set_title("the drive that holds 3 m/s, and the solids flow", fontsize=9)
    out = os.path.join(case, "slugConveying.png")
    fig.savefig(out, dpi=100)
    plt.close(fig)
    print(f"wrote {out}")

    fig, ax = plt.subplots(figsize=(9, 1.8))

    def frame(snap):
        t, x, v, _ = snap
        ax.clear()
        side_view(ax, par, x, v, vmax)
        ax.set_yticks([])
        ax.set_title(f"t = {t:.2f} s (colour: axial velocity 0-{vmax} m/s)", fontsize=8)
    fc.write_gif(os.path.join(case, "slugConveying.gif"), fig, snaps, frame)

if __name__ == "__main__":
    sys.exit(main())
