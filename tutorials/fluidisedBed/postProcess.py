#!/usr/bin/env python3
"""fluidisedBed: check a run of the Goldschmidt bed and draw its pictures.

Reads (case directory given as the argument):
  postProcessing/pInlet|pOutlet/<start>/surfaceFieldValue.dat: area-averaged kinematic pressure
      p/rho_f on the inlet (bottom) and the outlet (top), every fluid step;
  postProcessing/momentumBalance.dat: the solver's momentum balance of the fluid, every step;
  particles.h5: particle snapshots (every writeInterval);
  the last time directory's alphaMean (fieldAverage of alpha over the statistics window);
  constant/: rho_f, rho_p, g, the domain (cross-section A, height H).
Measured, over the statistics window t >= t_stats (the bubbling regime):
  dP(t) = rho_f (p_in - p_out) - rho_f |g| H: the bed's pressure drop [Pa] (p keeps the
      hydrostatic part of the gas column, rho_f |g| H = 5.3 Pa here);
  its time mean, its standard deviation and its dominant frequency (the peak of the power
      spectrum of dP - mean, f > 0.2 Hz);
  the bed height h = 2 <z> of each snapshot (the height of a uniform bed with the same centre of
      mass) and its time mean; h95, the height below which 95 % of the particles are (printed);
  the momentum balance's relative residual |residual| / (its largest term) at every
      fluid step of the run (from t = 0).
Checks (CHECK lines; exit 1 on a FAIL):
  dP_mean:     mean dP, less the bed's momentum change over the window per area and time
               (M (<v_z>(end) - <v_z>(start)) / (A T), <v_z> the mean particle velocity of
               postProcessing/particles.dat: the particles' momentum balance is dP A = W +
               M d<v_z>/dt, which a window of a few bubble periods does not average out; printed
               beside the raw mean), against the buoyant weight per area
               W/A = N V_p (rho_p - rho_f) |g| / A, 3 %: in a fluidised bed the gas carries the
               whole bed;
  momentum_percent: the largest relative residual over the run, 1 %: the pressure drop equals
               the force the particles give the fluid plus the gas's weight and acceleration;
  exchange_percent: the mean force the fluid receives from the particles (at the end of each
               fluid step, with the new fluid velocity) against the mean force the particles felt
               during the DEM steps (postProcessing/particles.dat), over the window: the particles
               feel the drag coefficient the fluid received with that new velocity, so the two
               differ only by beta times the particles' velocity change within a fluid step, which
               averages out (0.006 % in the short variant; beta evaluated again with the new slip
               had left 2.5 % in the full run), 0.1 %; the particles' own balance (fluid +
               walls - weight - M dv/dt) is printed;
  expansion:   mean h against h_0 = N V_p / (0.6 A), the height of the bed packed at a solid
               fraction of 0.6, within [1.05, 2.0]: above 1.05 the bed has expanded beyond a
               packing; below 2 it is a dense bed (h_0 is 150 mm, the column 450 mm);
  dP_std:      std(dP) / (W/A) within [0.02, 0.5]: bubbles make the bed's pressure drop
               fluctuate by several per cent of its mean (a bubble-free expanded bed would stay
               at about W/A; half of W/A would be slugging or a failing bed);
  dP_frequency_over_natural: the dominant frequency (the peak of the Hann-windowed power
               spectrum) against Baskakov et al.'s natural frequency of a bed,
               f_n = (1/2 pi) sqrt(g / h_mf) at h_mf = h_0 (1.3 Hz for the full bed, 2.0 Hz for
               the short one), within [0.5, 4] f_n: the bed's pressure oscillates at its own
               mass-on-a-gas-spring frequency and its bubbles' (dominant frequencies grow with
               1/sqrt(bed height), 1-4 Hz in beds a few tenths of a metre deep: van Ommen et al.
               2011, the review of pressure time series; Falkowski & Brown 2004); below the band
               is the start-up's drift, far above it step-to-step numerical noise;
  lid_percent: the time-mean share of the beads whose centres lie within 1.5 d of the lid, at
               most 0.5 %: a bubbling bed throws single beads up now and then, but a layer that
               stays there is pressed against the lid by the gas (its drag exceeds its weight),
               and the lid then carries part of the gas's push: 1 % of the bed pinned there
               adds about 2 % to dP (a full run with 7.6 % pinned read +17 %).
Pictures: <case>/fluidisedBed.png (dP(t); particles coloured by speed at six times; the
time-mean solid fraction map 1 - alphaMean, averaged over the depth x; the momentum balance's
residual) and <case>/fluidisedBed.gif (the particles, every snapshot).
Usage: postProcess.py <case> [t_stats]   (t_stats default 1 s)
       postProcess.py --window <case> <t0> <t1>   the pressure statistics of a window only
       postProcess.py --coarse-graining <cg1 run> <run> ...   after each run's own check (which
           writes postProcessing/bedSummary.json): CHECK <run>_vs_<cg1 run>_dP_mean, the mean
           pressure drop per buoyant weight against the cg-1 run's, 3 %; INFO the expansion, the
           fluctuation's size and its dominant frequency of each against cg 1
"""
import json
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
import foamcase as fc  # noqa: E402

TOL_DP, TOL_MOMENTUM = 3.0, 1.0
TOL_EXCHANGE = 0.1          # %: the exchange differs only by a term that averages out (docstring)
TOL_LID = 0.5               # % of the beads at the lid, time mean over the window
EXPANSION = (1.05, 2.0)
DP_STD = (0.02, 0.5)
FREQUENCY = (0.5, 4.0)      # x Baskakov's natural frequency of the bed
PACKED = 0.6
TOL_CG = 3.0               # %: coarse-grained runs' mean dP per weight against cg 1 (issue 22)


def window_statistics(case, bed, t0, t1):
    """Mean, std (10 ms averages) and dominant frequency of dP over [t0, t1], and the number of
    fluid steps; with the bed's momentum change taken out of the mean."""
    t, dp = fc.bed_pressure_drop(case, bed)
    w = (t >= t0 - 1e-12) & (t <= t1 + 1e-12)
    dpw, dt = dp[w], np.median(np.diff(t[w]))
    k = max(1, int(round(0.01 / dt)))
    dp_lp = np.convolve(dpw, np.ones(k) / k, mode="valid")
    spec = np.abs(np.fft.rfft((dpw - dpw.mean()) * np.hanning(len(dpw)))) ** 2
    freq = np.fft.rfftfreq(len(dpw), dt)
    band = freq > 0.2
    dp_m, _ = fc.bed_momentum_change(case, bed, t[w][0], t[w][-1])
    return dpw.mean() - dp_m, dp_lp.std(), freq[band][np.argmax(spec[band])], int(w.sum())


def main():
    if sys.argv[1] == "--window":      # postProcess.py --window <case> <t0> <t1>: statistics only
        case, t0, t1 = sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
        bed = fc.case_bed(case, "beads")
        w_a = bed["v_p"] * (bed["rho_p"] - bed["rho_f"]) * bed["g"] / bed["area"]
        mean, std, f, n = window_statistics(case, bed, t0, t1)
        print(f"WINDOW {case} {t0:g}-{t1:g} s: {n} fluid steps; mean dP (less the bed's momentum change) "
              f"{mean:.1f} Pa ({100 * (mean / w_a - 1):+.2f} % from W/A {w_a:.1f} Pa), std {std:.1f} Pa "
              f"({100 * std / w_a:.1f} %), dominant frequency {f:.2f} Hz")
        return 0
    if sys.argv[1] == "--coarse-graining":   # postProcess.py --coarse-graining <cg1 run> <run> ...
        return compare_coarse_graining(sys.argv[2:])
    case = sys.argv[1]
    t_stats = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
    bed = fc.case_bed(case, "beads")
    lo, hi, g, area = bed["lo"], bed["hi"], bed["g"], bed["area"]
    w_a = bed["v_p"] * (bed["rho_p"] - bed["rho_f"]) * g / area
    h0 = bed["v_p"] / (PACKED * area)
    snaps = list(fc.snapshots(case))
    t_snap = np.array([s[0] for s in snaps])

    # --- pressure drop
    t, dp = fc.bed_pressure_drop(case, bed)
    win = t >= t_stats - 1e-12
    if win.sum() < 100:
        raise SystemExit(f"postProcess.py: {win.sum()} fluid steps from t_stats = {t_stats:g} s to the run's end at "
                         f"t = {t[-1]:g} s; the statistics need at least 100 (a longer run or a shorter fluid step)")
    dpw = dp[win]
    dt = np.median(np.diff(t[win]))
    # the standard deviation of dP averaged over 10 ms (bubbles pass in tenths of a second; the
    # centre void fraction adds a step-to-step jitter as particles cross cell faces)
    k = max(1, int(round(0.01 / dt)))
    dp_lp = np.convolve(dpw, np.ones(k) / k, mode="valid")
    mean, std, std_raw = dpw.mean(), dp_lp.std(), dpw.std()
    spec = np.abs(np.fft.rfft((dpw - mean) * np.hanning(len(dpw)))) ** 2
    freq = np.fft.rfftfreq(len(dpw), dt)
    band = freq > 0.2
    f_peak = freq[band][np.argmax(spec[band])]
    f_n = np.sqrt(g / h0) / (2 * np.pi)     # Baskakov et al.: the bed's natural frequency
    # the bed's momentum change over the window (dP A = W + M d<v_z>/dt - walls, the particles'
    # momentum balance), which a window of a few bubble periods does not average out
    dp_momentum, vz = fc.bed_momentum_change(case, bed, t[win][0], t[win][-1])
    pb = fc.particle_balance(case, bed, t_stats)

    # --- bed height
    in_win = t_snap >= t_stats - 1e-12
    h_mean = np.array([2.0 * (s[1][:, 2].mean() - lo[2]) for s in snaps])
    h95 = np.array([np.percentile(s[1][:, 2], 95) - lo[2] for s in snaps])
    # beads at the lid: centres within 1.5 d of it (touching it, or one diameter below)
    d = (6.0 * bed["v_p"] / (np.pi * bed["n"])) ** (1.0 / 3.0)
    at_lid = np.array([np.count_nonzero(s[1][:, 2] > hi[2] - 1.5 * d) for s in snaps])

    # --- momentum balance of the gas
    t_mb, rel = fc.momentum_residual(case)
    worst = int(np.argmax(rel))

    print(f"INFO fluidisedBed: {bed['n']} particles, W/A = {w_a:.2f} Pa, packed height h_0 = {1e3 * h0:.1f} mm; "
          f"statistics over {t_stats:g} - {t[-1]:g} s ({win.sum()} fluid steps, {in_win.sum()} snapshots)")
    print(f"INFO pressure drop: mean {mean:.2f} Pa ({100 * (mean / w_a - 1):+.2f} % from W/A), of which "
          f"{dp_momentum:+.2f} Pa is the bed's momentum change (mean particle velocity {vz[0]:+.4f} -> {vz[1]:+.4f} m/s); "
          f"std {std:.2f} Pa over 10 ms ({100 * std / w_a:.1f} % of W/A; {std_raw:.2f} Pa step by step); dominant "
          f"frequency {f_peak:.2f} Hz (Baskakov's (1/2 pi) sqrt(g/h_mf) at h_mf = h_0: {f_n:.2f} Hz)")
    print(f"INFO particles' momentum balance over the window [N]: fluid {pb['fluid']:.5f} + walls {pb['walls']:.5f} "
          f"({100 * pb['walls'] / pb['weight']:.2f} % of the weight) - weight {pb['weight']:.5f} - M dv/dt {pb['accel']:+.5f} "
          f"= {pb['residual']:+.5f} ({100 * pb['residual'] / pb['weight']:+.3f} % of the weight); the fluid received "
          f"{pb['given']:.5f} ({100 * (pb['given'] / pb['fluid'] - 1):+.3f} % of what the particles felt)")
    print(f"INFO bed height: mean 2<z> {1e3 * h_mean[in_win].mean():.1f} mm (h/h_0 {h_mean[in_win].mean() / h0:.3f}), "
          f"h95 {1e3 * h95[in_win].mean():.1f} mm; gas momentum balance: worst relative residual "
          f"{100 * rel[worst]:.3f} % at t = {t_mb[worst]:g} s, median {100 * np.median(rel):.4f} %")
    print(f"INFO beads at the lid (centre within 1.5 d of it): mean {at_lid[in_win].mean():.1f} over the window, "
          f"most {at_lid.max()} at t = {t_snap[np.argmax(at_lid)]:g} s")
    checks = fc.Checks()
    checks.relative("dP_mean", mean - dp_momentum, w_a, TOL_DP)
    checks.at_most("momentum_percent", 100 * rel[worst], TOL_MOMENTUM)
    checks.at_most("exchange_percent", 100 * abs(pb["given"] / pb["fluid"] - 1), TOL_EXCHANGE)
    checks.within("expansion", h_mean[in_win].mean() / h0, *EXPANSION)
    checks.within("dP_std", std / w_a, *DP_STD)
    checks.within("dP_frequency_over_natural", f_peak / f_n, *FREQUENCY)
    checks.at_most("lid_percent", 100.0 * at_lid[in_win].mean() / bed["n"], TOL_LID,
                   "beads resting at the lid: the gas presses them against it and dP no longer weighs the bed")

    summary = dict(n=int(bed["n"]), w_a=w_a, dp_mean=mean - dp_momentum, dp_std=std, f_peak=f_peak,
                   expansion=float(h_mean[in_win].mean() / h0), h_mean=float(h_mean[in_win].mean()))
    with open(os.path.join(case, "postProcessing", "bedSummary.json"), "w") as f:
        json.dump({k: float(v) for k, v in summary.items()}, f, indent=1)
    draw(case, snaps, t, dp, t_stats, w_a, mean, t_mb, rel, lo, hi)
    return 1 if checks.failed else 0


def compare_coarse_graining(cases):
    """The runs at coarseGraining 2, 3 against the run at 1 (the first case), from each run's
    postProcessing/bedSummary.json: the mean pressure drop per buoyant weight within TOL_CG;
    the expansion and the fluctuation's size and frequency printed."""
    runs = []
    for case in cases:
        with open(os.path.join(case, "postProcessing", "bedSummary.json")) as f:
            runs.append((os.path.basename(os.path.normpath(case)), json.load(f)))
    checks = fc.Checks()
    name0, r0 = runs[0]
    for name, r in runs:
        print(f"INFO {name}: {int(r['n'])} parcels; dP_mean/(W/A) {r['dp_mean'] / r['w_a']:.4f}, "
              f"std {100 * r['dp_std'] / r['w_a']:.1f} % of W/A, dominant frequency {r['f_peak']:.2f} Hz, "
              f"expansion h/h_0 {r['expansion']:.3f}")
    for name, r in runs[1:]:
        checks.relative(f"{name}_vs_{name0}_dP_mean", r["dp_mean"] / r["w_a"], r0["dp_mean"] / r0["w_a"], TOL_CG)
        print(f"INFO {name} vs {name0}: expansion {100 * (r['expansion'] / r0['expansion'] - 1):+.1f} %, "
              f"fluctuation size {100 * (r['dp_std'] / r['w_a'] / (r0['dp_std'] / r0['w_a']) - 1):+.0f} %, "
              f"frequency {100 * (r['f_peak'] / r0['f_peak'] - 1):+.0f} %")
    return 1 if checks.failed else 0


def speed_scatter(ax, snap, lo, hi, vmax):
    time, x, v = snap
    sc = ax.scatter(x[:, 1] * 1e3, x[:, 2] * 1e3, c=np.linalg.norm(v, axis=1), s=0.4, cmap="viridis",
                    vmin=0, vmax=vmax, rasterized=True)
    ax.set_xlim(lo[1] * 1e3, hi[1] * 1e3)
    ax.set_ylim(lo[2] * 1e3, 0.75 * hi[2] * 1e3)
    ax.set_aspect("equal")
    ax.set_title(f"t = {time:.2f} s", fontsize=9)
    ax.tick_params(labelsize=7)
    return sc


def solid_fraction_map(case):
    """1 - alphaMean of the last time directory, averaged over x: (ny, nz), or None."""
    for tw, name in reversed(fc.time_dirs(case)):
        path = os.path.join(case, name, "alphaMean")
        if os.path.exists(path):
            a = fc.internal_field(path)
            nx, ny, nz = fc.block_cells(case)
            if np.ndim(a) == 0:
                a = np.full(nx * ny * nz, a)
            return tw, 1.0 - a.reshape(nz, ny, nx).mean(axis=2)
    return None


def draw(case, snaps, t, dp, t_stats, w_a, mean, t_mb, rel, lo, hi):
    fig = plt.figure(figsize=(15, 9))
    gs = fig.add_gridspec(2, 9, height_ratios=[1, 1.6], width_ratios=[1] * 6 + [0.15, 1.1, 1.1])
    ax = fig.add_subplot(gs[0, :4])
    dt = np.median(np.diff(t))
    k = max(1, int(round(0.01 / dt)))
    ax.plot(t, dp, lw=0.2, color="0.8", label="dP = p_in - p_out - rho_f g H, every step")
    ax.plot(t[k // 2: k // 2 + len(t) - k + 1], np.convolve(dp, np.ones(k) / k, mode="valid"), lw=0.6,
            color="tab:blue", label="averaged over 10 ms")
    ax.axhline(w_a, color="k", ls="--", lw=1, label=f"W/A = {w_a:.0f} Pa")
    ax.axvline(t_stats, color="grey", ls=":", lw=1)
    ax.axhline(mean, color="tab:red", lw=1, label=f"mean from {t_stats:g} s: {mean:.0f} Pa")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("bed pressure drop [Pa]")
    ax.set_ylim(0, 2.0 * w_a)
    ax.legend(fontsize=8, loc="lower right")
    ax = fig.add_subplot(gs[0, 5:])
    ax.semilogy(t_mb, np.maximum(rel, 1e-9), lw=0.3)
    ax.axhline(0.01, color="tab:red", ls="--", lw=1, label="1 %")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("|residual| / largest term of the balance")
    ax.set_title("fluid momentum balance: pressure drop = particles + weight + acceleration", fontsize=9)
    ax.legend(fontsize=8)
    picks = np.unique(np.linspace(0, len(snaps) - 1, 6).round().astype(int))
    vmax = 1.0
    for k, i in enumerate(picks):
        ax = fig.add_subplot(gs[1, k])
        sc = speed_scatter(ax, snaps[i], lo, hi, vmax)
        if k == 0:
            ax.set_ylabel("z [mm]")
        ax.set_xlabel("y [mm]", fontsize=8)
    cb = fig.colorbar(sc, cax=fig.add_subplot(gs[1, 6]))
    cb.set_label("|v| [m/s]", fontsize=8)
    sf = solid_fraction_map(case)
    ax = fig.add_subplot(gs[1, 7:])
    if sf is not None:
        tw, m = sf
        im = ax.imshow(m, origin="lower", extent=[lo[1] * 1e3, hi[1] * 1e3, lo[2] * 1e3, hi[2] * 1e3],
                       vmin=0, vmax=0.6, cmap="magma_r", aspect="equal")
        ax.set_ylim(lo[2] * 1e3, 0.75 * hi[2] * 1e3)
        fig.colorbar(im, ax=ax, fraction=0.1).set_label("solid fraction", fontsize=8)
        ax.set_title(f"time-mean solid fraction\n({t_stats:g} - {tw:g} s)", fontsize=9)
    ax.set_xlabel("y [mm]", fontsize=8)
    fig.suptitle("fluidisedBed: DPMFoam's Goldschmidt bed in voidPimpleFoam + the project's DEM", fontsize=11)
    fig.subplots_adjust(left=0.05, right=0.97, top=0.92, bottom=0.07, wspace=0.35, hspace=0.3)
    out = os.path.join(case, "fluidisedBed.png")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print(f"wrote {out}")

    fig, ax = plt.subplots(figsize=(3.2, 6.4))

    def frame(snap):
        ax.clear()
        speed_scatter(ax, snap, lo, hi, vmax)
        ax.set_xlabel("y [mm]", fontsize=8)
        ax.set_ylabel("z [mm]", fontsize=8)
    fc.write_gif(os.path.join(case, "fluidisedBed.gif"), fig, snaps, frame)

if __name__ == "__main__":
    sys.exit(main())
