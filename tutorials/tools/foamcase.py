"""Reading a coupled case's output for the tutorials' checks and pictures (numpy, h5py).

- dictionaries: strip_comments, read_dict, scalar, vector, sub_dict (a regex reader of the
  simple OpenFOAM-syntax entries the tutorials use; not a general parser);
- time series: surface_field_value (postProcessing/<name>/<start time>/surfaceFieldValue.dat of
  every start time, so that a run continued from a write time reads as one series),
  table (postProcessing/momentumBalance.dat, particles.dat);
- fields: internal_field (the internal values of an ASCII volField), time_dirs;
- particles: snapshots (particles.h5: time, position, velocity per snapshot, by id order);
- checks: Checks, the CHECK lines every tutorial prints (PASS/FAIL, exit status);
- the bed measures shared by the bed tutorials (case_bed, bed_pressure_drop, ...).
Every tutorial's postProcess.py imports this module (sys.path: tutorials/tools).
"""
import os
import re

import h5py
import numpy as np

NUM = r"([-+0-9.eE]+)"


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def read_dict(path):
    with open(path) as f:
        return strip_comments(f.read())


def scalar(text, key):
    m = re.search(r"(?:^|[\s{;])" + key + r"\s+" + NUM + r"\s*;", text)
    if not m:
        raise SystemExit(f"foamcase: no '{key}' found")
    return float(m.group(1))


def vector(text, key):
    m = re.search(key + r"\s*\(\s*" + NUM + r"\s+" + NUM + r"\s+" + NUM + r"\s*\)", text)
    if not m:
        raise SystemExit(f"foamcase: no vector '{key}' found")
    return np.array([float(m.group(k)) for k in (1, 2, 3)])


def sub_dict(text, name):
    """The body of the first 'name { ... }' (one level of nested braces allowed)."""
    m = re.search(r"(?:^|[\s;{])" + re.escape(name) + r"\s*\{((?:[^{}]|\{[^{}]*\})*)\}", text)
    if not m:
        raise SystemExit(f"foamcase: no sub-dictionary '{name}' found")
    return m.group(1)


def time_dirs(case):
    """[(time, name)] of the directories of `case` named by a number (time directories; the start
    times under postProcessing/<name>), sorted; [] if `case` does not exist."""
    out = []
    for name in os.listdir(case) if os.path.isdir(case) else ():
        try:
            out.append((float(name), name))
        except ValueError:
            pass
    return sorted(out)


def surface_field_value(case, name, ncols=None):
    """time and the columns of postProcessing/<name>/<start>/surfaceFieldValue.dat over all start
    times (a later start replaces the rows from its start on); vectors split into components."""
    base = os.path.join(case, "postProcessing", name)
    rows = []
    for start, sname in time_dirs(base):
        path = os.path.join(base, sname, "surfaceFieldValue.dat")
        if not os.path.exists(path):
            continue
        rows = [r for r in rows if r[0] < start - 1e-12]
        with open(path) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                rows.append([float(x) for x in line.replace("(", " ").replace(")", " ").split()])
    if not rows:
        raise SystemExit(f"foamcase: no {base}/<time>/surfaceFieldValue.dat")
    a = np.array(rows)
    return a if ncols is None else a[:, :ncols]


def table(path):
    """A whitespace table with '#' comments, as an array (rows, columns)."""
    if not os.path.exists(path):
        raise SystemExit(f"foamcase: no {path}")
    return np.loadtxt(path, comments="#", ndmin=2)


def internal_field(path):
    """The internal field of an ASCII OpenFOAM volField: (n,) or (n, 3); a uniform field as a
    scalar or vector value."""
    with open(path) as f:
        text = f.read()
    i = text.index("internalField")
    head = text[i:text.index("\n", i)]
    if "nonuniform" not in head:
        vals = re.findall(NUM, head.split("uniform", 1)[1])
        return np.array([float(v) for v in vals]) if len(vals) > 1 else float(vals[0])
    body = text[text.index("(", i) + 1:]
    if "List<vector>" in head:
        vals = re.findall(r"\(([^()]*)\)", body[:body.index("\n)")])
        return np.array([[float(x) for x in v.split()] for v in vals])
    return np.array(body[:body.index(")")].split(), dtype=float)


def block_cells(case):
    """(nx, ny, nz) of the single hex block of system/blockMeshDict (cells numbered x fastest)."""
    bm = read_dict(os.path.join(case, "system/blockMeshDict"))
    m = re.search(r"hex\s*\([^)]*\)\s*\(\s*(\d+)\s+(\d+)\s+(\d+)\s*\)", bm)
    return tuple(int(m.group(k)) for k in (1, 2, 3))


def snapshots(case, every=1):
    """Yield (time, position (n,3), velocity (n,3)) of the complete snapshots of particles.h5 in
    time order, particles sorted by id; every: only every k-th snapshot."""
    with h5py.File(os.path.join(case, "particles.h5"), "r") as h:
        groups = [g for g in h["snapshots"].values() if g.attrs.get("complete", 0)]
        groups.sort(key=lambda g: g.attrs["time"])
        for k, g in enumerate(groups):
            if k % every:
                continue
            order = np.argsort(g["id"][:])
            yield float(g.attrs["time"]), g["position"][:][order], g["velocity"][:][order]


def snapshot_times(case):
    with h5py.File(os.path.join(case, "particles.h5"), "r") as h:
        return sorted(float(g.attrs["time"]) for g in h["snapshots"].values() if g.attrs.get("complete", 0))


def write_gif(path, fig, frames, draw, fps=10, dpi=80):
    """An animation: draw(frame) into fig for each of frames, each grabbed into the GIF at path;
    prints and returns the frame count. fig is closed after."""
    import matplotlib.pyplot as plt
    from matplotlib.animation import PillowWriter
    writer = PillowWriter(fps=fps)
    with writer.saving(fig, path, dpi=dpi):
        for frame in frames:
            draw(frame)
            fig.tight_layout()
            writer.grab_frame()
    plt.close(fig)
    print(f"wrote {path} ({len(frames)} frames)")
    return len(frames)


# --- CHECK lines, the same in every tutorial -----------------------------------------------
class Checks:
    """CHECK lines (name, measured, reference or limits, PASS/FAIL), one per check; `failed` is
    set on a FAIL, and a non-finite measured value always fails. Postprocessors end with
    `sys.exit(1 if checks.failed else 0)`. `note` is appended to the line (where, when)."""

    def __init__(self):
        self.failed = False

    def _line(self, ok, text, note):
        ok = bool(ok)
        self.failed |= not ok
        print(f"CHECK {text} {'PASS' if ok else 'FAIL'}" + (f" ({note})" if note else ""))
        return ok

    def relative(self, name, measured, reference, tolerance_percent, note=""):
        """|measured / reference - 1| <= tolerance_percent %."""
        err = 100.0 * abs(measured / reference - 1.0)
        return self._line(np.isfinite(measured) and err <= tolerance_percent,
                          f"{name} measured={measured:.6g} reference={reference:.6g} error={err:.3f} "
                          f"tolerance={tolerance_percent:g}", note)

    def deviation(self, name, fraction, tolerance_percent, note=""):
        """A relative deviation (a fraction, reference 0) at most tolerance_percent %."""
        return self._line(np.isfinite(fraction) and 100.0 * fraction <= tolerance_percent,
                          f"{name} measured={fraction:.6g} reference=0 error={100.0 * fraction:.3f} "
                          f"tolerance={tolerance_percent:g}", note)

    def missing(self, name, why):
        """A check that could not be evaluated: always a FAIL, with the reason."""
        return self._line(False, f"{name} measured=nan", why)

    def at_most(self, name, measured, limit, note=""):
        return self._line(np.isfinite(measured) and measured <= limit,
                          f"{name} measured={measured:.6g} limit={limit:g}", note)

    def within(self, name, measured, lo, hi, unit="", note=""):
        return self._line(np.isfinite(measured) and lo <= measured <= hi,
                          f"{name} measured={measured:.6g}{unit} range=[{lo:g}, {hi:g}]{unit}", note)


# --- the fluidised-bed measures shared by the bed tutorials ----------------------------------
def case_bed(case, material):
    """The bed's parameters from constant/: rho_f, rho_p (of `material`), |g|, the domain's
    cross-section A and height H, the particle volume V_p and count N (first snapshot)."""
    tp = read_dict(os.path.join(case, "constant/transportProperties"))
    dem = read_dict(os.path.join(case, "constant/demProperties"))
    dom = sub_dict(dem, "domain")
    lo, hi = vector(dom, "min"), vector(dom, "max")
    with h5py.File(os.path.join(case, "particles.h5"), "r") as h:
        first = min(h["snapshots"].values(), key=lambda g: g.attrs["time"])
        r = first["radius"][:]
    return {
        "rho_f": scalar(tp, "rho"), "nu": scalar(tp, "nu"),
        "rho_p": scalar(sub_dict(sub_dict(dem, "materials"), material), "density"),
        "g": float(np.linalg.norm(vector(dem, "gravity"))),
        "lo": lo, "hi": hi, "area": (hi[0] - lo[0]) * (hi[1] - lo[1]), "height": hi[2] - lo[2],
        "v_p": float(np.sum(4.0 / 3.0 * np.pi * r ** 3)), "n": len(r),
    }


def bed_pressure_drop(case, bed):
    """t, dP = rho_f (p_inlet - p_outlet) - rho_f |g| H [Pa] every fluid step (p keeps the
    hydrostatic part of the gas column); the function objects pInlet and pOutlet."""
    pin = surface_field_value(case, "pInlet", 2)
    pout = surface_field_value(case, "pOutlet", 2)
    m = min(len(pin), len(pout))
    return pin[:m, 0], bed["rho_f"] * (pin[:m, 1] - pout[:m, 1]) - bed["rho_f"] * bed["g"] * bed["height"]


def bed_momentum_change(case, bed, t0, t1):
    """M (<v_z>(t1) - <v_z>(t0)) / (A (t1 - t0)) [Pa]: the bed's momentum change per area and
    time (postProcessing/particles.dat's mean particle velocity), and the two velocities."""
    pm = table(os.path.join(case, "postProcessing/particles.dat"))
    vz = np.interp([t0, t1], pm[:, 0], pm[:, 7])
    mass = bed["v_p"] * bed["rho_p"]
    return mass * (vz[1] - vz[0]) / (bed["area"] * (t1 - t0)), vz


def momentum_residual(case):
    """(time, |residual| / the balance's largest term) of postProcessing/momentumBalance.dat."""
    mb = table(os.path.join(case, "postProcessing/momentumBalance.dat"))
    return mb[:, 0], np.abs(mb[:, 8])


def particle_balance(case, bed, t0):
    """The particles' momentum balance along z over t >= t0, from postProcessing/particles.dat
    (the fluid's and the walls' force on the particles, means over each fluid step) [N]:
    fluid, walls, weight M |g|, M d<v_z>/dt over the window, and the residual
    fluid + walls - weight - M d<v_z>/dt; and `given`, the mean force the fluid received from
    them (with the sign of `fluid`: equal to it when the exchange conserves momentum)."""
    pm = table(os.path.join(case, "postProcessing/particles.dat"))
    if pm.shape[1] < 14:
        raise SystemExit(f"foamcase: {case}/postProcessing/particles.dat has no force columns (written "
                         "by an older solver); run the case again")
    w = pm[:, 0] >= t0
    mass = bed["v_p"] * bed["rho_p"]
    t, vz = pm[w, 0], pm[w, 7]
    fluid, walls = pm[w, 13].mean(), pm[w, 10].mean()
    # what the fluid received (momentumBalance.dat's 'particles' is the particles' force on the
    # fluid, at the end of each fluid step; particles.dat's first row is the start)
    mb = table(os.path.join(case, "postProcessing/momentumBalance.dat"))
    given = -mb[mb[:, 0] >= t0, 3].mean()
    accel = mass * (vz[-1] - vz[0]) / (t[-1] - t[0])
    weight = mass * bed["g"]
    return {"fluid": fluid, "walls": walls, "weight": weight, "accel": accel,
            "residual": fluid + walls - weight - accel, "given": given}


# --- drag laws' packed-bed pressure gradients (the tutorials' references) -------------------
def koch_hill(U, e, c):
    """The packed bed's pressure gradient [Pa/m] by Koch & Hill (2001) as in coupling/src/drag.c,
    its dense branch (solid fraction >= 0.4, which every packed bed here is); c: rho_f, nu, d.
    F = F0 + F1 Re^2 below Re = F3/F1, else F2 + F3 Re, with
    F0 = F2 = 10 phi / e^3, F1 = 0.11 + 5.1e-4 exp(11.6 phi), F3 = 0.0673 + 0.212 phi + 0.0232 / e^5
    and Re = rho_f U d / (2 mu); the bed's pressure gradient is 18 mu phi F U / d^2."""
    mu, d = c["rho_f"] * c["nu"], c["d"]
    e = np.asarray(e, dtype=float)
    phi = 1.0 - e
    if np.any(phi < 0.4):
        raise SystemExit("postProcess.py: KochHill's packed-bed reference (its dense branch) needs a solid fraction of at least 0.4")
    f0 = 10.0 * phi / e ** 3
    f1 = 0.11 + 5.1e-4 * np.exp(11.6 * phi)
    f3 = 0.0673 + 0.212 * phi + 0.0232 / e ** 5
    re = c["rho_f"] * np.abs(U) * d / (2.0 * mu)
    F = np.where(re <= f3 / f1, f0 + f1 * re ** 2, f0 + f3 * re)
    return 18.0 * mu * phi * F * U / d ** 2
