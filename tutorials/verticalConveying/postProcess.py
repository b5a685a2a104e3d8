#!/usr/bin/env python3
"""verticalConveying: check a run of dilute upward conveying, or draw the state diagram of a sweep.

One run (postProcess.py <case> [t_stats], t_stats default 0.3 s) reads:
  particles.h5: the snapshots (every writeInterval) with the life cycle's counters (the mass fed
      by the stream and taken by each outlet, exact to 2^-64 kg) and each bead's fluid velocity;
  postProcessing/pLow|pHigh/<start>/surfaceFieldValue.dat: the area-mean kinematic pressure on
      the planes 0.1025 and 0.2475 m, through the centres of the developed section's (0.1-0.25 m)
      first and last cell layers, every step;
  postProcessing/gasFlow/<start>/surfaceFieldValue.dat: the gas's volume flow out of the top;
  postProcessing/wallShear.dat: the wall patches' shear force on the gas, every step;
  postProcessing/particles.dat: the walls' force on the beads, per DEM wall, every fluid step;
  constant/: the beads, the gas, g, the stream's feed rate.
Over the window t >= t_stats (the steady state) it measures and checks (CHECK lines; exit 1 on a
FAIL):
  solids_balance: the solids mass flow out (the top outlet, and the bottom one for beads that
      fall back through the feed) over the window against the mass fed over it, within 1 %;
      the exact balance fed - out - held = 0 of the life cycle (in quanta) is printed;
  slip: the mean slip of the beads in the section, <u_f - v> along z (u_f the gas velocity the
      coupling gave each bead), against the terminal velocity w_t that the case's drag law gives
      at the section's mean voidage eps: DiFelice with model B, (beta_p(eps, w_t) / eps) w_t =
      (rho_p - rho_f) V_p g, beta_p = (pi/8) mu d eps^(1 - chi) (0.63 sqrt(Re) + 4.8)^2,
      Re = eps rho_f w d / mu (docs/models/drag_difelice.md, forces_modelA_B.md), within 5 %.
      Measured in the sweep (2026-12-03): +0.2 to +2.0 % at 5-10 m/s, +4.1/+4.3 % at 13 m/s, and
      +6.4/+6.9 % at 17 m/s, where the check fails. The beads' relaxation length v w_t / g (2.3 m
      at 10 m/s, 4.7 m at 17 m/s) is far beyond the 0.3 m pipe: in the section they keep about
      their feed velocity U - 3.4 m/s, so the mean slip is the gas velocity they see less that, and
      they see more than U where they avoid the slow wall band (1.5 % more at 17 m/s). The check
      holds where that excess is small; it does not show relaxed beads;
  pressure_gradient: the section's mean -dp/dz = rho_f (p1 - p2) / (0.145 m) against the weight
      and the wall shear of what it holds, per volume of the section V_s:
        [N_s m g + rho_f g (V_s - N_s V_p) + S_gas + S_beads + (J2 - J1) + (Jg2 - Jg1)] / V_s,
      N_s the beads in the section, S_gas the gas's shear on wallSection, S_beads the beads'
      wall force on the DEM wall wallSection, J = m_dot sum(v_z^2) / sum(v_z) the beads' momentum
      flux through each end (the sums over a slab 20 mm thick about the plane, m_dot the solids
      mass flow out: what the beads still accelerate by) and the gas's momentum flux out less in
      (rho_f sum(alpha u_z^2 dA) through each plane, from the written fields: the particles
      reshape the gas's profile along the section), within 2 %.
  The section's volume V_s = A_mesh (z2 - z1), A_mesh = 8 R^2 sin(pi/8), the 16-sided polygon of
  the O-grid's wall (2.5 % less than pi R^2).
It writes <case>/summary.txt (the measured figures, one 'key value' per line) and
<case>/verticalConveying.png.
The sweep (postProcess.py -stateDiagram <run>...) reads each run's summary.txt and draws
stateDiagram.png: -dp/dz in the developed section against the superficial gas velocity, one
curve per solids flux, with the gas alone (Blasius, f = 0.316 Re^-0.25, plus the gas's weight).
Check: each flux's curve has its minimum inside the swept range (the classic state diagram: the
solids' weight falls and the wall friction grows with the gas velocity); the minimum's velocity
and gradient are printed (a parabola through the lowest point and its neighbours).
"""
import math
import os
import re
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "tools"))
import foamcase as fc  # noqa: E402

Z1, Z2, SLAB = 0.1, 0.25, 0.02
P1, P2 = 0.1025, 0.2475    # the pressure planes: through the first and last cell layers' centres
TOL_SOLIDS, TOL_SLIP, TOL_DP = 1.0, 5.0, 2.0


def parameters(case):
    dem = fc.read_dict(os.path.join(case, "constant/demProperties"))
    glass = fc.sub_dict(fc.sub_dict(dem, "materials"), "glass")
    feed = fc.sub_dict(dem, "feed")
    d = fc.scalar(fc.sub_dict(feed, "diameter"), "value")
    tr = fc.read_dict(os.path.join(case, "constant/transportProperties"))
    R = fc.scalar(fc.sub_dict(dem, "wallSection"), "radius")
    g = np.linalg.norm(fc.vector(fc.read_dict(os.path.join(case, "constant/g")), "value"))
    rho_f, nu = fc.scalar(tr, "rho"), fc.scalar(tr, "nu")
    return {"d": d, "rho_p": fc.scalar(glass, "density"), "rho_f": rho_f, "mu": rho_f * nu, "nu": nu,
            "g": g, "R": R, "A": 8 * R * R * math.sin(math.pi / 8), "feed": fc.scalar(feed, "massRate"),
            "v_in": fc.vector(feed, "velocity")[2]}


def quanta(hi, lo):
    """kg from the (high, low) int64 pair of a count of 2^-64 kg."""
    return float(hi) + float(np.uint64(np.int64(lo))) / 2.0 ** 64


def lifecycle(case):
    """[(t, fed kg, {outlet: kg}, held kg, exact fed - out - held in quanta)] per snapshot."""
    out = []
    rho = parameters(case)["rho_p"]
    with h5py.File(os.path.join(case, "particles.h5"), "r") as h:
        groups = [g for g in h["snapshots"].values() if g.attrs.get("complete", 0)]
        groups.sort(key=lambda g: g.attrs["time"])
        for g in groups:
            lc = g["lifecycle"]
            b = lc["balance"][0]
            names = lc.attrs["outlet_names"]
            names = (names.decode() if isinstance(names, bytes) else str(names)).split()
            o = lc["outlets"][:]
            outlets = {n: quanta(o[k, 1], o[k, 2]) for k, n in enumerate(names)}
            fed = quanta(b[1], b[2])
            removed = quanta(b[4], b[5])
            r = g["radius"][:]
            held = float(np.sum(rho * 4.0 / 3.0 * math.pi * r ** 3))
            out.append((float(g.attrs["time"]), fed, outlets, held, fed - removed - held, int(b[0]), int(b[3]), len(r)))
    return out


def snapshots_with_fluid(case):
    with h5py.File(os.path.join(case, "particles.h5"), "r") as h:
        groups = [g for g in h["snapshots"].values() if g.attrs.get("complete", 0)]
        groups.sort(key=lambda g: g.attrs["time"])
        for g in groups:
            yield float(g.attrs["time"]), g["position"][:], g["velocity"][:], g["fluid_velocity"][:]


def terminal_velocity(par, eps):
    """w with (beta_p(eps, w) / eps) w = (rho_p - rho_f) V_p g (DiFelice, model B), by bisection."""
    d, mu, rho_f = par["d"], par["mu"], par["rho_f"]
    weight = (par["rho_p"] - rho_f) * math.pi / 6 * d ** 3 * par["g"]

    def force(w):
        re_p = eps * rho_f * w * d / mu
        chi = 3.7 - 0.65 * math.exp(-(1.5 - math.log10(re_p)) ** 2 / 2)
        beta = math.pi / 8 * mu * d * eps ** (1 - chi) * (0.63 * math.sqrt(re_p) + 4.8) ** 2
        return beta / eps * w

    lo, hi = 1e-6, 100.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if force(mid) < weight else (lo, mid)
    return 0.5 * (lo + hi)


def gas_momentum_flux(case, par, t_stats):
    """The gas's momentum flux out of the section less what enters it [N], the time mean over
    the write times t >= t_stats: rho_f sum(alpha u_z^2 V / dz) over the two cell layers about
    each plane (their mean: the flux through the plane between them), from the written alpha and
    U and the cell centres and volumes (0/C, 0/V, written by Allrun)."""
    cz = fc.internal_field(os.path.join(case, "0/Cz"))
    vol = fc.internal_field(os.path.join(case, "0/V"))
    dz = 0.005
    def at(plane, alpha, u):
        near = np.abs(cz - plane) < dz
        return par["rho_f"] * np.sum(alpha[near] * u[near, 2] ** 2 * vol[near] / dz) / 2.0
    diffs = []
    for t, name in fc.time_dirs(case):
        if t < t_stats - 1e-9 or not os.path.exists(os.path.join(case, name, "alpha")):
            continue
        alpha = fc.internal_field(os.path.join(case, name, "alpha"))
        u = fc.internal_field(os.path.join(case, name, "U"))
        diffs.append(at(Z2, alpha, u) - at(Z1, alpha, u))
    return float(np.mean(diffs))


def series(case, name):
    a = fc.surface_field_value(case, name, 2)
    return a[:, 0], a[:, 1]


def one_run(case, t_stats):
    par = parameters(case)
    checks = fc.Checks()
    m = par["rho_p"] * math.pi / 6 * par["d"] ** 3
    vp = math.pi / 6 * par["d"] ** 3
    vs = par["A"] * (Z2 - Z1)

    life = lifecycle(case)
    tl = np.array([x[0] for x in life])
    w = tl >= t_stats - 1e-9
    if w.sum() < 3:
        checks.missing("solids_balance", f"fewer than 3 snapshots after t = {t_stats} s")
        return 1
    i0, i1 = np.where(w)[0][[0, -1]]
    span = tl[i1] - tl[i0]
    fed = (life[i1][1] - life[i0][1]) / span
    outs = {n: (life[i1][2][n] - life[i0][2][n]) / span for n in life[i1][2]}
    out = sum(outs.values())
    held0, held1 = life[i0][3], life[i1][3]
    print(f"solids over {tl[i0]:g}-{tl[i1]:g} s: fed {fed * 1e3:.4f} g/s (the case's {par['feed'] * 1e3:.4f} g/s), out "
          + ", ".join(f"{n} {v * 1e3:.4f} g/s" for n, v in outs.items())
          + f"; held {held0 * 1e3:.4f} -> {held1 * 1e3:.4f} g; the life cycle's balance at the end: fed "
          f"{life[-1][5]} = removed {life[-1][6]} + held {life[-1][7]} beads, fed - out - held = {life[-1][4]:.3g} kg")
    checks.relative("solids_balance", out, fed, TOL_SOLIDS, note="the solids mass flow out (top + bottom) against "
                    "the fed, over the window")

    # the section: beads, slip, momentum fluxes
    ns, slip, jlo, jhi, vz_sec, ts = [], [], [], [], [], []
    for t, x, v, uf in snapshots_with_fluid(case):
        if t < t_stats - 1e-9:
            continue
        z = x[:, 2]
        sec = (z >= Z1) & (z < Z2)
        ns.append(sec.sum())
        slip.append(np.sum(uf[sec, 2] - v[sec, 2]))
        vz_sec.append(np.sum(v[sec, 2]))
        lo = np.abs(z - Z1) < SLAB / 2
        hi = np.abs(z - Z2) < SLAB / 2
        jlo.append((np.sum(v[lo, 2] ** 2), np.sum(v[lo, 2])))
        jhi.append((np.sum(v[hi, 2] ** 2), np.sum(v[hi, 2])))
        ts.append(t)
    n_s = float(np.mean(ns))
    eps = 1 - n_s * vp / vs
    slip_mean = float(np.sum(slip) / np.sum(ns))
    u_beads = float(np.sum(vz_sec) / np.sum(ns))
    wt = terminal_velocity(par, eps)
    print(f"developed section {Z1:g}-{Z2:g} m: {n_s:.0f} beads on average, voidage {eps:.5f}, bead velocity "
          f"{u_beads:.3f} m/s, mean slip {slip_mean:.4f} m/s; the drag law's terminal velocity there {wt:.4f} m/s "
          f"(at eps = 1: {terminal_velocity(par, 1.0):.4f} m/s)")
    checks.relative("slip", slip_mean, wt, TOL_SLIP, note="the beads' mean slip in the section against the "
                    "terminal velocity of DiFelice's law (model B) at the section's voidage")

    tp1, p1 = series(case, "pLow")
    tp2, p2 = series(case, "pHigh")
    n = min(len(tp1), len(tp2))
    tp, dpdz = tp1[:n], par["rho_f"] * (p1[:n] - p2[:n]) / (P2 - P1)
    wp = tp >= t_stats - 1e-9
    grad = float(dpdz[wp].mean())
    shear = fc.table(os.path.join(case, "postProcessing/wallShear.dat"))
    with open(os.path.join(case, "postProcessing/wallShear.dat")) as f:
        patches = f.readline().split(":")[-1].split()
    k = patches.index("wallSection")
    ws = shear[:, 0] >= t_stats - 1e-9
    s_gas = -float(shear[ws, 1 + 3 * k + 2].mean())
    pm = fc.table(os.path.join(case, "postProcessing/particles.dat"))
    with open(os.path.join(case, "postProcessing/particles.dat")) as f:
        head = f.read(4096).splitlines()
    walls = [ln for ln in head if ln.startswith("# then each wall")][0].split(":")[-1].split()
    kw = walls.index("wallSection")
    wm = pm[:, 0] >= t_stats - 1e-9
    s_beads = -float(pm[wm, 14 + 3 * kw + 2].mean())
    # the beads' momentum flux through a plane, J = m_dot v_J, with v_J = sum(v_z^2) / sum(v_z) over
    # a slab about the plane (the flux-weighted mean velocity) and m_dot the solids mass flow out
    # (steady: the same through both planes); far less noisy than the slab's sum(m v_z^2) / delta,
    # whose count of beads scatters by a few per cent between snapshots
    v_lo = np.sum([a for a, b in jlo]) / np.sum([b for a, b in jlo])
    v_hi = np.sum([a for a, b in jhi]) / np.sum([b for a, b in jhi])
    flux = float(out * (v_hi - v_lo))
    gas_flux = gas_momentum_flux(case, par, t_stats)
    print(f"the beads' flux-weighted velocity at z1 {v_lo:.4f} m/s, at z2 {v_hi:.4f} m/s")
    w_s = n_s * m * par["g"]
    w_g = par["rho_f"] * par["g"] * (vs - n_s * vp)
    rhs = (w_s + w_g + s_gas + s_beads + flux + gas_flux) / vs
    print(f"pressure gradient in the section: -dp/dz {grad:.2f} Pa/m; the section holds (per volume, Pa/m): beads' "
          f"weight {w_s / vs:.2f}, gas's weight {w_g / vs:.2f}, gas's wall shear {s_gas / vs:.2f}, beads' wall force "
          f"{s_beads / vs:.2f}, beads' momentum flux out - in {flux / vs:.2f}, gas's momentum flux out - in "
          f"{gas_flux / vs:.2f}; sum {rhs:.2f}")
    checks.relative("pressure_gradient", grad, rhs, TOL_DP, note="-dp/dz against the weights, the wall shear and "
                    "the beads' momentum flux of the developed section")

    tq, q = series(case, "gasFlow")
    u_s = float(q[tq >= t_stats - 1e-9].mean() / par["A"])
    gs = fed / (math.pi * par["R"] ** 2)   # the beads' pipe: the DEM's round wall
    print(f"superficial gas velocity {u_s:.4f} m/s, solids flux {gs:.3f} kg/(m^2 s), loading {fed / (par['rho_f'] * u_s * par['A']):.3f} kg/kg")
    with open(os.path.join(case, "summary.txt"), "w") as f:
        for key, val in (("superficial_velocity", u_s), ("solids_flux", gs), ("pressure_gradient", grad),
                         ("pressure_gradient_balance", rhs), ("voidage", eps), ("bead_velocity", u_beads),
                         ("slip", slip_mean), ("terminal_velocity", wt), ("solids_out_over_in", out / fed),
                         ("beads_weight", w_s / vs), ("gas_weight", w_g / vs), ("gas_wall_shear", s_gas / vs),
                         ("beads_wall_force", s_beads / vs), ("beads_momentum_flux", flux / vs),
                         ("gas_momentum_flux", gas_flux / vs)):
            f.write(f"{key} {val:.9g}\n")
    draw_run(case, par, life, tp, dpdz, t_stats, (w_s, w_g, s_gas, s_beads, flux + gas_flux, grad * vs), wt, slip_mean)
    return 1 if checks.failed else 0


def draw_run(case, par, life, tp, dpdz, t_stats, terms, wt, slip):
    fig, axes = plt.subplots(1, 4, figsize=(14, 4.2), gridspec_kw={"width_ratios": [0.6, 1.3, 1.3, 1.3]})
    t, x, v, uf = list(snapshots_with_fluid(case))[-1]
    keep = np.abs(x[:, 1]) < 0.002
    ax = axes[0]
    sc = ax.scatter(1e3 * x[keep, 0], x[keep, 2], c=v[keep, 2], s=1, cmap="viridis", linewidths=0)
    ax.set_xlim(-1e3 * par["R"], 1e3 * par["R"])
    ax.set_ylim(0, 0.3)
    ax.axhspan(Z1, Z2, color="0.92", zorder=-1)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("z [m]")
    ax.set_title(f"t = {t:.2f} s", fontsize=9)
    fig.colorbar(sc, ax=ax, label="v_z [m/s]")
    ax = axes[1]
    tl = np.array([r[0] for r in life])
    ax.plot(tl, 1e3 * np.array([r[1] for r in life]), "k-", label="fed")
    for n in life[-1][2]:
        ax.plot(tl, 1e3 * np.array([r[2][n] for r in life]), label=f"out: {n}")
    ax.plot(tl, 1e3 * np.array([r[3] for r in life]), "--", label="held")
    ax.axvspan(t_stats, tl[-1], color="0.92")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("solids mass [g]")
    ax.legend(fontsize=8)
    ax.set_title("the feed, the outlets and the hold-up", fontsize=9)
    ax = axes[2]
    ax.plot(tp, dpdz, lw=0.3, color="tab:purple", alpha=0.25, label="every step")
    k = max(1, int(round(0.01 / max(tp[1] - tp[0], 1e-12))))
    ax.plot(tp[k - 1:], np.convolve(dpdz, np.ones(k) / k, mode="valid"), color="tab:purple", label="0.01 s mean")
    ax.legend(fontsize=8)
    ax.axvspan(t_stats, tp[-1], color="0.92")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("-dp/dz in the section [Pa/m]")
    ax.set_ylim(0, 2 * max(np.median(dpdz[tp >= t_stats]), 1))
    ax = axes[3]
    names = ["beads'\nweight", "gas's\nweight", "gas's\nwall shear", "beads'\nwall force", "mom.\nfluxes"]
    vs = par["A"] * (Z2 - Z1)
    vals = np.array(terms[:5]) / vs
    ax.bar(names, vals, color="tab:blue")
    ax.bar(["sum"], [vals.sum()], color="tab:green")
    ax.bar(["-dp/dz"], [terms[5] / vs], color="tab:purple")
    ax.tick_params(axis="x", labelsize=7)
    ax.set_ylabel("[Pa/m]")
    ax.set_title(f"the section's balance; slip {slip:.3f} m/s, w_t {wt:.3f} m/s", fontsize=9)
    fig.tight_layout()
    out = os.path.join(case, "verticalConveying.png")
    fig.savefig(out, dpi=100)
    plt.close(fig)
    print(f"wrote {out}")


def read_summary(run):
    with open(os.path.join(run, "summary.txt")) as f:
        return {k: float(v) for k, v in (ln.split() for ln in f if ln.strip())}


def state_diagram(runs, out_dir):
    checks = fc.Checks()
    rows = [read_summary(r) for r in runs]
    fluxes = sorted({round(r["solids_flux"]) for r in rows})
    par = parameters(runs[0])
    fig, ax = plt.subplots(figsize=(7, 5))
    for gs in fluxes:
        pts = sorted((r["superficial_velocity"], r["pressure_gradient"]) for r in rows if round(r["solids_flux"]) == gs)
        u, dp = np.array(pts).T
        i = int(np.argmin(dp))
        inside = 0 < i < len(u) - 1
        if inside:
            a, b, c = np.polyfit(u[i - 1:i + 2], dp[i - 1:i + 2], 2)
            u_min, dp_min = -b / (2 * a), c - b * b / (4 * a)
        else:
            u_min, dp_min = u[i], dp[i]
        print(f"solids flux {gs} kg/(m^2 s): " + ", ".join(f"{x:.2f} m/s {y:.1f} Pa/m" for x, y in zip(u, dp))
              + f"; minimum {dp_min:.1f} Pa/m at {u_min:.2f} m/s")
        checks.within(f"state_diagram_minimum_Gs{gs}", float(i), 1, len(u) - 2,
                      note=f"the index of the lowest -dp/dz among {len(u)} velocities: inside the range, minimum "
                      f"{dp_min:.1f} Pa/m at {u_min:.2f} m/s")
        ax.plot(u, dp, "o-", label=f"G_s = {gs} kg/(m$^2$ s)")
        if inside:
            ax.plot([u_min], [dp_min], "k*", ms=10)
    uu = np.linspace(min(r["superficial_velocity"] for r in rows) * 0.9, max(r["superficial_velocity"] for r in rows) * 1.05, 100)
    D = 2 * par["R"]
    f = 0.316 * (uu * D / par["nu"]) ** -0.25
    ax.plot(uu, f * par["rho_f"] * uu ** 2 / (2 * D) + par["rho_f"] * par["g"], "k--", lw=1, label="gas alone (Blasius)")
    ax.set_xlabel("superficial gas velocity [m/s]")
    ax.set_ylabel("-dp/dz in the developed section [Pa/m]")
    ax.set_title("state diagram: dilute upward conveying, d = 0.5 mm glass, D = 20 mm", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    out = os.path.join(out_dir, "stateDiagram.png")
    fig.savefig(out, dpi=110, bbox_inches="tight")
    plt.close(fig)
    print(f"wrote {out}")
    return 1 if checks.failed else 0


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "-stateDiagram":
        return state_diagram(sys.argv[2:], os.getcwd())
    case = sys.argv[1] if len(sys.argv) > 1 else "."
    t_stats = float(sys.argv[2]) if len(sys.argv) > 2 else 0.3
    return one_run(case, t_stats)


if __name__ == "__main__":
    sys.exit(main())
