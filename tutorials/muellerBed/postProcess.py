#!/usr/bin/env python3
"""muellerBed: the time-mean void-fraction profiles of each run at Mueller et al.'s MR lines,
compared with the measured profiles; the bed checks of each run; muellerBed.png.

Reads, per run directory (runs/U<u>_<drag>_<voidFraction>):
  the last time directory's alphaMean (fieldAverage of alpha from the statistics start, every
      fluid step): the cell values, averaged over the depth x (2 cells), interpolated linearly in
      z between the cell layers to the MR lines z = 16.4 and 31.2 mm: a profile across the width y
      at the cell centres (12 points, 3.67 mm apart);
  postProcessing/: the pressure drop, the momentum balance and the particle means (as
      fluidisedBed);
  data/exp_U<u>_z<z>.dat: Mueller et al.'s MR profiles, digitised from the papers' figures (the
      files' headers give the source), x [mm] from the left wall (our y), void fraction.
Writes profiles/<run>_z<z>.dat (y [mm], time-mean void fraction) and muellerBed.png.
Compares, per run and line (INFO lines): the mean of the profile over the width, the mean in the
core (17 < y < 27 mm) and near the walls (the outer 5 mm), each against the measured, and the RMS
difference at the measured points (the simulated profile interpolated to them; the measured
points nearer the wall than the first cell centre compared with that centre's value).
Checks per run (CHECK lines; exit 1 on a FAIL): the mean pressure drop over the statistics
window, less the bed's momentum change, against the buoyant weight per area, 3 %; the gas
momentum balance at every step, 1 %; the force the fluid received against what the particles
felt, over the window, 0.1 % (they differ only by beta times the particles' velocity change
within a fluid step, which averages out); and the profiles: the RMS difference from the measured profile at
most 0.1, the spread of the published CFD-DEM simulations of this bed around the measurement
(Mueller et al.'s own DEM runs 0.08-0.1 below the MR data in the core at 16.4 mm; sediFoam's and
CFDEM's comparisons, within a few hundredths to 0.1): a run outside it is wrong, not merely
imprecise.
Usage: postProcess.py <t_stats> <run directory>...
"""
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

LINES = (16.4, 31.2)            # [mm] the MR lines' heights
CORE, WALL = (17.0, 27.0), 5.0  # [mm]
TOL_DP, TOL_MOMENTUM, TOL_EXCHANGE, TOL_RMS = 3.0, 1.0, 0.1, 0.1


def experiment(u, z):
    path = os.path.join(here, "data", f"exp_U{u:g}_z{z:g}.dat")
    return np.loadtxt(path, comments="#") if os.path.exists(path) else None


def profiles(run):
    """{z: (y [mm], void fraction)} from the last alphaMean, and that time."""
    for tw, name in reversed(fc.time_dirs(run)):
        path = os.path.join(run, name, "alphaMean")
        if os.path.exists(path):
            break
    else:
        raise SystemExit(f"postProcess.py: no alphaMean in {run}")
    nx, ny, nz = fc.block_cells(run)
    a = fc.internal_field(path).reshape(nz, ny, nx).mean(axis=2)
    bed = fc.case_bed(run, "seeds")
    lo, hi = bed["lo"], bed["hi"]
    zc = lo[2] + (np.arange(nz) + 0.5) * (hi[2] - lo[2]) / nz
    yc = 1e3 * (lo[1] + (np.arange(ny) + 0.5) * (hi[1] - lo[1]) / ny)
    out = {}
    for z in LINES:
        out[z] = (yc, np.array([np.interp(z * 1e-3, zc, a[:, j]) for j in range(ny)]))
    return out, tw


def compare(y, a, exp):
    """mean, core, wall of (simulation, experiment) and the RMS difference at the measured x."""
    xe, ae = exp[:, 0], exp[:, 1]
    at = np.interp(xe, y, a)             # flat beyond the first and last cell centres
    width = 44.0
    core = (xe > CORE[0]) & (xe < CORE[1])
    wall = (xe < WALL) | (xe > width - WALL)
    ycore = (y > CORE[0]) & (y < CORE[1])
    ywall = (y < WALL) | (y > width - WALL)
    return {"mean": (a.mean(), ae.mean()), "core": (a[ycore].mean(), ae[core].mean()),
            "wall": (a[ywall].mean(), ae[wall].mean()), "rms": float(np.sqrt(np.mean((at - ae) ** 2)))}


def main():
    t_stats = float(sys.argv[1])
    runs = sys.argv[2:]
    os.makedirs("profiles", exist_ok=True)   # in the working directory: the tutorial's (Allrun), a sweep's case
    checks = fc.Checks()
    results = {}
    for run in runs:
        name = os.path.basename(os.path.normpath(run))
        # the gas velocity: from the variant's name (U0.6_...), else the case's inlet (a sweep's case)
        m = re.match(r"U([0-9.]+)_", name) or re.search(r"inletVelocity\s+uniform\s+\(0 0 ([0-9.eE+-]+)\)",
                                                        open(os.path.join(run, "0", "U")).read())
        u = float(m.group(1))
        bed = fc.case_bed(run, "seeds")
        w_a = bed["v_p"] * (bed["rho_p"] - bed["rho_f"]) * bed["g"] / bed["area"]
        t, dp = fc.bed_pressure_drop(run, bed)
        win = t >= t_stats - 1e-12
        dp_m, vz = fc.bed_momentum_change(run, bed, t[win][0], t[win][-1])
        t_mb, rel = fc.momentum_residual(run)
        pb = fc.particle_balance(run, bed, t_stats)
        pm = fc.table(os.path.join(run, "postProcessing/particles.dat"))
        h = 2.0 * (pm[pm[:, 0] >= t_stats, 4].mean() - bed["lo"][2])
        prof, tw = profiles(run)
        results[name] = (u, prof)
        print(f"INFO {name}: {bed['n']} particles, W/A = {w_a:.2f} Pa; statistics {t_stats:g} - {t[-1]:g} s; "
              f"mean dP {dp[win].mean():.2f} Pa ({100 * (dp[win].mean() / w_a - 1):+.2f} %), bed momentum change "
              f"{dp_m:+.2f} Pa, walls carry {100 * pb['walls'] / pb['weight']:.2f} % of the weight; "
              f"bed height 2<z> {1e3 * h:.1f} mm; worst gas momentum residual {100 * rel.max():.3f} %")
        checks.relative(f"{name}_dP_mean", dp[win].mean() - dp_m, w_a, TOL_DP)
        checks.at_most(f"{name}_momentum_percent", 100 * rel.max(), TOL_MOMENTUM)
        checks.at_most(f"{name}_exchange_percent", 100 * abs(pb["given"] / pb["fluid"] - 1), TOL_EXCHANGE)
        for z in LINES:
            y, a = prof[z]
            out = os.path.join("profiles", f"{name}_z{z:g}.dat")
            np.savetxt(out, np.column_stack([y, a]), fmt="%.6f",
                       header=f"muellerBed {name}: time-mean void fraction (alphaMean, {t_stats:g} - {tw:g} s) across the "
                              f"width at z = {z:g} mm, averaged over the depth\ny [mm] from the left wall, void fraction [-]")
            exp = experiment(u, z)
            if exp is None:
                continue
            c = compare(y, a, exp)
            print(f"INFO {name} z = {z:g} mm: mean {c['mean'][0]:.3f} (MR {c['mean'][1]:.3f}), core {c['core'][0]:.3f} "
                  f"(MR {c['core'][1]:.3f}), walls {c['wall'][0]:.3f} (MR {c['wall'][1]:.3f}), RMS difference {c['rms']:.3f}")
            if not name.endswith("_clumps"):   # the measurement is of the seeds, not of dumbbells
                checks.at_most(f"{name}_z{z:g}_rms", c["rms"], TOL_RMS)
    draw(results)
    return 1 if checks.failed else 0


def draw(results):
    us = sorted({u for u, _ in results.values()})
    fig, axes = plt.subplots(len(LINES), len(us), figsize=(5.5 * len(us), 7.5), squeeze=False)
    for j, u in enumerate(us):
        for i, z in enumerate(LINES):
            ax = axes[i][j]
            exp = experiment(u, z)
            if exp is not None:
                ax.plot(exp[:, 0], exp[:, 1], "ko", ms=4, label="MR (Mueller et al.)")
            for name, (ur, prof) in sorted(results.items()):
                if ur == u:
                    y, a = prof[z]
                    ax.plot(y, a, "-", marker=".", label=(name.split("_", 1) + [name])[1].replace("_", ", "))
            ax.set_xlim(0, 44)
            ax.set_ylim(0.3, 0.9)
            ax.set_title(f"U = {u:g} m/s, z = {z:g} mm", fontsize=10)
            ax.set_xlabel("y [mm]")
            ax.set_ylabel("time-mean void fraction")
            ax.legend(fontsize=7)
    fig.suptitle("muellerBed: time-mean void fraction across the bed at the MR lines", fontsize=11)
    fig.tight_layout()
    out = "muellerBed.png"
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    sys.exit(main())
