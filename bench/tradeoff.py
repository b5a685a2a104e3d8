#!/usr/bin/env python3
"""The speed/accuracy trade, measured (issue 22): every knob, one at a time from each case's
reference setting, on the project's own validation cases; for every run the wall and CPU time
and the error of each of the case's CHECK quantities against its reference.

Cases (each made by its tutorial's Allrun, so the reference here is the tutorial's own short case):
  settling      tutorials/settling, 0.1 s (one sphere; terminal velocity and the curve)
  ergun         tutorials/ergun -short-case (Gidaspow, centre; the ramp through U_mf)
  fluidisedBed  tutorials/fluidisedBed -short-case (the short Goldschmidt bed, 1.5 s)
  muellerBed    tutorials/muellerBed -short-case (U 0.6 m/s, Gidaspow, centre; 1.5 s, statistics from 0.5 s)
  verticalConveying  tutorials/verticalConveying -short-case (10 m/s, 40 kg/(m^2 s), 0.3 s): the conveying case
Knobs (a run changes one; the rest stay at the case's reference):
  dt            the DEM step as a fraction of the Rayleigh time of the smallest particle; the
                fluid step is kept (couplingInterval = round(deltaT / dt), dt = deltaT / interval);
                above the time-step check's 0.2 the run sets timeStepOverride (reported: 'override')
  couplingInterval  DEM steps per fluid step, the DEM step kept (the fluid step = interval x dt)
  youngsModulus every material's E, the DEM step scaled with the Hertz contact time (E^-2/5)
  voidFraction, interpolation, drag, faceMomentum, nCorrectors: the coupling's and the fluid's models
  coarseGraining  ergun and fluidisedBed: their -cg-case at 1-4 (their own reference is cg 1 of that
                family: a periodic column, the divided void fraction)
  tangential    history or none: a model the scene may do without
Every run ends as PASS (all checks pass), FAIL (with each check's number) or STOP (the program
stopped: its message is kept); a run that crashes, hangs (timeout) or leaves a non-finite number is
reported as such, which is a defect to fix.
Output of the full sweep, the project's record: docs/tradeoff.md (the table: per case and knob, each
value's time and worst check error; the extremes; the cheapest setting that passes every check, with
its speed-up over the reference), docs/tradeoff/<case>.png (the Pareto plots) and
docs/tradeoff/tradeoff_full.csv (one row per run and check). The other modes write the same into
bench/results/ (tradeoff_<mode>.md, .csv, <case>.png) and leave the record alone.
Usage: tradeoff.py [-quick | -smoke | -extremes | -regression] [-j N] [--cases a,b] [--knobs a,b]
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

os.environ.setdefault("WM_PROJECT_DIR", "/opt/of/OpenFOAM-v1912")   # OpenFOAM's etc/, as the Allruns
TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TUT = os.path.join(TOP, "tutorials")
SOLVER = os.path.join(TOP, "build/foam/bin/voidPimpleFoam")
WORK = os.path.join(TOP, "bench/results/runs")
RESULTS = os.path.join(TOP, "bench/results")
RAYLEIGH_LIMIT = 0.2          # dem/src/timestep.h RAYLEIGH_FRACTION
CHECK = re.compile(r"^CHECK (\S+) measured=(\S+) (?:reference=(\S+) error=(\S+) tolerance=(\S+)|"
                   r"limit=(\S+)|range=\[(\S+), (\S+)\])\S* (PASS|FAIL)")


# --- editing a case ----------------------------------------------------------------------------
def edit(path, pattern, repl, count=0, required=True):
    with open(path) as f:
        text = f.read()
    new, n = re.subn(pattern, repl, text, count=count, flags=re.M)
    if required and n == 0:
        raise RuntimeError(f"{path}: '{pattern}' not found")
    with open(path, "w") as f:
        f.write(new)
    return n


def read(path):
    with open(path) as f:
        return f.read()


def number(text, key):
    m = re.search(r"^\s*" + key + r"\s+([-+0-9.eE]+)\s*;", text, flags=re.M)
    if not m:
        raise RuntimeError(f"no '{key}'")
    return float(m.group(1))


def rayleigh_time(case):
    """The Rayleigh time [s] of the smallest particle (insertion diameters x coarseGraining) of the
    softest material: pi R sqrt(rho / G) / (0.1631 nu + 0.8766), as dem/src/timestep.c."""
    dem = re.sub(r"//[^\n]*", "", read(os.path.join(case, "constant/demProperties")))
    cg = re.search(r"^\s*coarseGraining\s+([0-9.eE+-]+)\s*;", dem, flags=re.M)
    cg = float(cg.group(1)) if cg else 1.0
    diam = [float(v) for v in re.findall(r"diameter\s*\{[^}]*?(?:value|min)\s+([0-9.eE+-]+)", dem)]
    tr = math.inf
    for m in re.finditer(r"youngsModulus\s+([0-9.eE+-]+);\s*poissonsRatio\s+([0-9.eE+-]+);\s*density\s+([0-9.eE+-]+)", dem):
        E, nu, rho = map(float, m.groups())
        G = E / (2 * (1 + nu))
        tr = min(tr, math.pi * 0.5 * cg * min(diam) * math.sqrt(rho / G) / (0.1631 * nu + 0.8766))
    return tr


def fluid_step(case):
    return number(read(os.path.join(case, "system/controlDict")), "deltaT")


def set_steps(case, dt, interval, override=False):
    """The DEM step, the coupling interval and the fluid step deltaT = interval x dt."""
    dem = os.path.join(case, "constant/demProperties")
    edit(dem, r"^timeStep\s+[^;]+;", f"timeStep       {dt!r};", 1)
    if override and "timeStepOverride" not in read(dem):
        edit(dem, r"^(timeStep\s+[^;]+;)", r"\1\ntimeStepOverride true;", 1)
    edit(os.path.join(case, "constant/couplingProperties"), r"^couplingInterval\s+[^;]+;",
         f"couplingInterval {interval};", 1)
    edit(os.path.join(case, "system/controlDict"), r"^deltaT\s+[^;]+;", f"deltaT          {interval * dt!r};", 1)


def knob_dt(case, f, strict=False):
    """The DEM step at f T_R, the fluid step kept; past the check's limit with timeStepOverride,
    or with strict without it (then the run must stop with the time-step check's message)."""
    tr = rayleigh_time(case)
    step = fluid_step(case)
    interval = max(1, int(round(step / (f * tr))))
    dt = step / interval
    override = not strict and dt / tr > RAYLEIGH_LIMIT * (1 + 1e-9)
    set_steps(case, dt, interval, override=override)
    return f"{dt / tr:.3g} T_R" + (" (override)" if override else " (no override)" if strict else "")


def knob_interval(case, n):
    dt = number(read(os.path.join(case, "constant/demProperties")), "timeStep")
    set_steps(case, dt, int(n))
    return f"{int(n)}"


def knob_youngs(case, E):
    dem = os.path.join(case, "constant/demProperties")
    E_ref = float(re.search(r"youngsModulus\s+([0-9.eE+-]+)", read(dem)).group(1))
    edit(dem, r"youngsModulus\s+[0-9.eE+-]+", f"youngsModulus {E:g}")
    dt_ref = number(read(dem), "timeStep")
    step = fluid_step(case)
    dt = dt_ref * (E_ref / E) ** 0.4
    interval = max(1, int(round(step / dt)))
    set_steps(case, step / interval, interval)
    return f"{E:g} Pa"


def knob_coupling_key(key, sub=False):
    def apply(case, value):
        path = os.path.join(case, "constant/couplingProperties")
        pat = (r"^(\s+model\s+)\w+;" if sub else r"^(" + key + r"\s+)\w+;")
        edit(path, pat, r"\g<1>" + value + ";", 1)
        return value
    return apply


def knob_fv(key):
    """A PIMPLE key of system/fvSolution; added to PIMPLE where the case leaves it at its default."""
    def apply(case, value):
        path = os.path.join(case, "system/fvSolution")
        if not edit(path, r"^(\s*" + key + r"\s+)\w+;", r"\g<1>" + str(value) + ";", 1, required=False):
            edit(path, r"^(PIMPLE\s*\{)", r"\1\n    " + key + " " + str(value) + ";", 1)
        return str(value)
    return apply


def knob_tangential(case, value):
    edit(os.path.join(case, "constant/demProperties"), r"tangential\s+\w+;", f"tangential {value};", 1)
    return value


def knob_dt_strict(case, f):
    return knob_dt(case, f, strict=True)


KNOBS = {
    "dt": knob_dt, "dtStrict": knob_dt_strict, "couplingInterval": knob_interval, "youngsModulus": knob_youngs,
    "voidFraction": knob_coupling_key("voidFraction", sub=True),
    "interpolation": knob_coupling_key("interpolation"), "drag": knob_coupling_key("drag"),
    "faceMomentum": knob_fv("faceMomentum"), "nCorrectors": knob_fv("nCorrectors"),
    "tangential": knob_tangential,
}


# --- the cases -------------------------------------------------------------------------------
def make_settling(case, cg=None):
    os.makedirs(case)
    for sub in ("0", "constant", "system"):
        shutil.copytree(os.path.join(TUT, "settling", sub), os.path.join(case, sub))
    edit(os.path.join(case, "system/controlDict"), r"^endTime\s+[^;]+;", "endTime         0.1;", 1)


def make_by_allrun(name, mode):
    def make(case, cg=None):
        args = [os.path.join(TUT, name, "Allrun"), mode if cg is None else "-cg-case", case]
        if cg is not None:
            args.append(str(cg))
        subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return make


def run_plain(case, post):
    """blockMesh, the solver, then the check (command list, run in the case)."""
    def run(case_dir):
        return [["blockMesh"], [SOLVER], post]
    return run


CASES = {
    "settling": dict(make=make_settling, post=[sys.executable, os.path.join(TUT, "settling/postProcess.py"),
                                                "1e-4", "3000", "10", "1e-5", "9.81"], cg=False),
    "ergun": dict(make=make_by_allrun("ergun", "-short-case"),
                  post=[sys.executable, os.path.join(TUT, "ergun/postProcess.py"), "."], cg=True),
    "fluidisedBed": dict(make=make_by_allrun("fluidisedBed", "-short-case"), staged=True, cg=True),
    "muellerBed": dict(make=make_by_allrun("muellerBed", "-short-case"), cg=False,
                       post=[sys.executable, os.path.join(TUT, "muellerBed/postProcess.py"), "0.5", "."]),
    "verticalConveying": dict(make=make_by_allrun("verticalConveying", "-short-case"), cg=False,
                              pre=[["postProcess", "-func", "writeCellCentres", "-time", "0"],
                                   ["postProcess", "-func", "writeCellVolumes", "-time", "0"]],
                              post=[sys.executable, os.path.join(TUT, "verticalConveying/postProcess.py"), ".", "0.15"]),
}

# the values of each knob per case (the reference's own value is not repeated: it is the
# reference run); full sweep and -quick
SWEEP = {
    "settling": {
        "dt": [0.02, 0.05, 0.1, 0.3, 0.5], "couplingInterval": [1, 10, 200], "drag": ["DiFelice", "KochHill", "Beetstra"],
        "interpolation": ["cellPoint", "cellLinear"], "faceMomentum": ["false"], "nCorrectors": [1, 3],
    },
    "ergun": {
        "dt": [0.02, 0.05, 0.1, 0.3, 0.5], "couplingInterval": [10, 25, 100, 200], "youngsModulus": [1e5, 1e6],
        "voidFraction": ["divided", "gaussian"], "interpolation": ["cellPoint", "cellLinear"],
        "drag": ["DiFelice", "KochHill", "Beetstra"], "faceMomentum": ["false"], "nCorrectors": [1, 3],
        "coarseGraining": [1, 2, 3, 4], "tangential": ["none"],
    },
    "fluidisedBed": {
        "dt": [0.02, 0.05, 0.3, 0.5], "couplingInterval": [4, 32, 100], "youngsModulus": [1e5, 1e6],
        "voidFraction": ["divided", "gaussian"], "interpolation": ["cellPoint"],
        "drag": ["DiFelice", "KochHill", "Beetstra"], "faceMomentum": ["false"], "nCorrectors": [1, 3],
        "coarseGraining": [1, 2, 3, 4], "tangential": ["none"],
    },
}
SWEEP["muellerBed"] = {
    "dt": [0.3, 0.5], "couplingInterval": [8, 100], "youngsModulus": [1e6], "voidFraction": ["divided"],
    "drag": ["DiFelice"], "nCorrectors": [1],
}
SWEEP["verticalConveying"] = {   # its step is at the check's limit already (0.16 T_R)
    "dt": [0.1, 0.3], "couplingInterval": [5, 50], "voidFraction": ["divided"], "interpolation": ["cellPoint"],
    "nCorrectors": [3],
}
QUICK = {
    "settling": {"dt": [0.5], "couplingInterval": [1, 200], "drag": ["Beetstra"]},
    "ergun": {"dt": [0.3], "couplingInterval": [100], "voidFraction": ["divided"], "coarseGraining": [2]},
    "fluidisedBed": {"couplingInterval": [32], "coarseGraining": [2]},
}
# past the sweep, to find where each knob's result leaves its tolerance and where the run stops
# (run with the full sweep, or alone with -extremes); coarseGraining ends at the tutorials' 4
EXTREMES = {
    "settling": {"dt": [1, 3, 10], "couplingInterval": [1000, 5000, 20000], "dtStrict": [0.25]},
    "ergun": {"dt": [0.7, 1.0, 1.5], "couplingInterval": [500, 1000], "youngsModulus": [1e4, 1e3],
              "dtStrict": [0.25]},
    "fluidisedBed": {"dt": [0.7, 1.0, 1.5], "couplingInterval": [200, 500, 1000], "youngsModulus": [1e4, 1e3]},
    "muellerBed": {"dt": [1.0], "couplingInterval": [400]},
    "verticalConveying": {"dt": [1.0], "couplingInterval": [200]},
}
# knobs with an order, for the extremes table; their values in the reference case
ORDERED = ("dt", "dtStrict", "couplingInterval", "youngsModulus", "nCorrectors", "coarseGraining")


def reference_values(case):
    dem = read(os.path.join(case, "constant/demProperties"))
    dt = number(dem, "timeStep") / rayleigh_time(case)
    return {"dt": dt, "dtStrict": dt,
            "couplingInterval": number(read(os.path.join(case, "constant/couplingProperties")), "couplingInterval"),
            "youngsModulus": float(re.search(r"youngsModulus\s+([0-9.eE+-]+)", dem).group(1)),
            "nCorrectors": number(read(os.path.join(case, "system/fvSolution")), "nCorrectors"),
            "coarseGraining": 1.0}


# The extremes as regression points (ctest coupled_extremes, `-regression`): each past a limit the
# sweep found, with the outcome it must keep: a clean stop with the message that names the cause
# and what to change, or a check that leaves its tolerance (FAIL with its number), never a crash,
# a hang or a non-finite value. (case, knob, value, status, pattern the message must match)
REGRESSION = [
    ("settling", "dtStrict", 0.25, "STOP", r"demProperties:\d+: error: key 'timeStep'.*too large.*timeStepOverride"),
    ("settling", "couplingInterval", 20000, "FAIL", None),
    ("ergun", "dtStrict", 0.25, "STOP", r"demProperties:\d+: error: key 'timeStep'.*too large.*timeStepOverride"),
    ("ergun", "dt", 1.5, "STOP", r"blew up.*contact overlap.*too long for the contacts.*lower timeStep"),
    ("ergun", "youngsModulus", 1e4, "STOP", r"overlap.*The time step is not the cause.*too soft.*raise youngsModulus"),
    ("ergun", "coarseGraining", 4, "STOP", r"demProperties:\d+: error: insertion 'pour': placed only \d+ particles"),
    ("fluidisedBed", "youngsModulus", 1e6, "STOP", r"overlap.*The time step is not the cause.*too soft.*raise youngsModulus"),
    ("fluidisedBed", "dt", 1.0, "STOP", r"blew up.*contact overlap.*too long for the contacts.*lower timeStep"),
]


def regression(timeout):
    """Run the REGRESSION points; a CHECK line per point; 0 if every one ends as it must."""
    failed = 0
    for name, knob, value, want, pattern in REGRESSION:
        row = run_one(name, knob, value, timeout)
        ok = row["status"] == want and (pattern is None or re.search(pattern, row["message"]) is not None)
        if want == "FAIL":
            ok = ok and all(math.isfinite(e) for _, e, _, _ in row["checks"] if isinstance(e, float))
        print(f"CHECK extreme {name} {knob}={value}: {row['status']} (want {want}) in {row['wall']:.1f} s: "
              f"{row['message'] or f'worst {worst(row):.2f} of tolerance'} {'PASS' if ok else 'FAIL'}", flush=True)
        failed += not ok
    print(f"tradeoff -regression: {len(REGRESSION) - failed} of {len(REGRESSION)} extremes end as they must")
    return 1 if failed else 0


SMOKE = {"settling": {"dt": [0.5], "couplingInterval": [200]}}


def commands(name, case):
    spec = CASES[name]
    if spec.get("staged"):
        return [[os.path.join(TUT, "fluidisedBed/Allrun"), "-run-case", case, "0.6", "report"]]
    return [["blockMesh"], *spec.get("pre", []), [SOLVER], spec["post"]]


def stop_message(out, code):
    """What the program said when it stopped: the text after OpenFOAM's FATAL ERROR line, else the
    last line that says error, else the last line."""
    lines = [l.strip() for l in out.splitlines() if l.strip()]
    for k, l in enumerate(lines):
        if "FATAL" in l:
            return " ".join(lines[k + 1:k + 3])[:420]
    errs = [l for l in lines if re.search(r"error|refuse|stop", l, flags=re.I)]
    return (errs[-1] if errs else lines[-1] if lines else f"exit {code}")[:420]


def run_one(name, knob, value, timeout):
    """Make, change, run and check one case; returns the row dict (status, times, checks)."""
    label = "reference" if knob is None else f"{knob}={value}"
    case = os.path.join(WORK, name, re.sub(r"[^A-Za-z0-9_.=-]", "_", label))
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(os.path.dirname(case), exist_ok=True)
    row = dict(case=name, knob=knob or "reference", value="" if knob is None else str(value), setting="",
               status="", message="", wall=math.nan, cpu=math.nan, checks=[])
    try:
        if knob == "coarseGraining":
            CASES[name]["make"](case, cg=int(value))
            row["setting"] = f"cg {value}"
        elif knob == "combined":   # value: "k1=v1+k2=v2+...", applied in that order
            CASES[name]["make"](case)
            row["setting"] = " + ".join(KNOBS[k](case, parse_value(v)) for k, v in
                                        (kv.split("=", 1) for kv in value.split("+")))
        else:
            CASES[name]["make"](case)
            if knob is not None:
                row["setting"] = KNOBS[knob](case, value)
            else:
                row["refvals"] = reference_values(case)
    except (RuntimeError, subprocess.CalledProcessError) as e:
        row.update(status="ERROR", message=f"making the case: {e}")
        return row
    logpath = case + ".log"      # beside the case: a tutorial's own run clears log.* in it
    if os.path.exists(logpath):
        os.remove(logpath)
    t0, cpu = time.time(), 0.0
    status, out = "PASS", ""
    env = dict(os.environ, FOAM_SIGFPE="true")
    for cmd in commands(name, case):
        # each command's own CPU time (wait4: the runs go on in parallel threads)
        with open(logpath, "a") as log:
            start = len(read(logpath)) if os.path.exists(logpath) else 0
            p = subprocess.Popen(cmd, cwd=case, stdout=log, stderr=subprocess.STDOUT, env=env)
            deadline = time.time() + timeout
            while True:
                pid, code, usage = os.wait4(p.pid, os.WNOHANG)
                if pid:
                    break
                if time.time() > deadline:
                    p.kill()
                    pid, code, usage = os.wait4(p.pid, 0)
                    code = None
                    break
                time.sleep(0.2)
        cpu += usage.ru_utime + usage.ru_stime
        text = read(logpath)[start:]
        out += text
        if code is None:
            status = "HANG"
            row["message"] = f"{os.path.basename(cmd[0])} did not end within {timeout:g} s"
            break
        signal = os.WIFSIGNALED(code)
        rc = os.WEXITSTATUS(code) if os.WIFEXITED(code) else -os.WTERMSIG(code)
        if (signal or rc != 0) and cmd[0] != sys.executable:
            status = "CRASH" if signal or rc > 128 else "STOP"
            row["message"] = stop_message(text, rc).replace(case + "/", "")
            break
    row["wall"] = time.time() - t0
    row["cpu"] = cpu
    for line in out.splitlines():
        m = CHECK.match(line)
        if not m:
            continue
        (check, measured, ref, err, tol, limit, lo, hi, verdict) = m.groups()
        measured = float(measured)
        if err is not None:
            e, t = float(err), float(tol)
        elif limit is not None:
            e, t = measured, float(limit)
        else:
            e, t = measured, f"[{lo}, {hi}]"
        row["checks"].append((check, e, t, verdict))
        if not math.isfinite(measured):
            status = "NONFINITE"
    if status == "PASS":
        said = [l.strip() for l in out.splitlines() if l.startswith("postProcess.py:")]
        if not row["checks"] and said:   # the check itself refused the run, and said why
            status, row["message"] = "STOP", said[-1][:420]
        elif not row["checks"]:
            status, row["message"] = "ERROR", "no CHECK lines"
        elif any(c[3] == "FAIL" for c in row["checks"]):
            status = "FAIL"
    row["status"] = status
    return row


def parse_value(v):
    """A CSV value back as the knob takes it: an integer stays one (OpenFOAM's nCorrectors
    refuses 3.0), a number becomes a float, a name stays a string."""
    try:
        if re.fullmatch(r"[-+]?[0-9]+", v):
            return int(v)
        return float(v) if re.fullmatch(r"[-+0-9.eE]+", v) else v
    except ValueError:
        return v


# the order in which a combination applies its knobs: the stiffness first (it rescales the
# step), then the step, then the interval (which keeps the step and sets the fluid's)
COMBINE_ORDER = ("youngsModulus", "dt", "couplingInterval", "voidFraction", "interpolation", "drag", "faceMomentum",
                 "nCorrectors", "tangential")


def combine(name, rows, timeout, log=print):
    """The cheapest combination that passes: greedy from the single knobs. Each knob's fastest
    passing value (5 % or more faster than the reference) is a candidate; starting from the
    fastest, each next candidate is added if the combination with it passes and is faster.
    Not the coarse-graining family (another column) nor the step past the check without override.
    Returns the rows of the combinations run."""
    rs = [r for r in rows if r["case"] == name]
    ref = next((r for r in rs if r["knob"] == "reference"), None)
    if ref is None or ref["status"] != "PASS":
        return []
    best = {}
    for r in rs:
        if r["knob"] in COMBINE_ORDER and r["status"] == "PASS" and r["wall"] < 0.95 * ref["wall"]:
            if r["knob"] not in best or r["wall"] < best[r["knob"]]["wall"]:
                best[r["knob"]] = r
    cands = sorted(best.values(), key=lambda r: r["wall"])
    if len(cands) < 2:
        return []
    chosen, chosen_wall, out = [cands[0]], cands[0]["wall"], []
    for c in cands[1:]:
        trial = sorted(chosen + [c], key=lambda r: COMBINE_ORDER.index(r["knob"]))
        value = "+".join(f"{r['knob']}={r['value']}" for r in trial)
        row = run_one(name, "combined", value, timeout)
        out.append(row)
        log(f"  {name:13s} combined {value}: {row['status']} {row['wall']:.1f} s wall (best so far {chosen_wall:.1f} s)")
        if row["status"] == "PASS" and row["wall"] < chosen_wall:
            chosen, chosen_wall = trial, row["wall"]
    return out


def worst(row):
    """The largest check error relative to its tolerance (1 = at the tolerance), for sorting."""
    r = 0.0
    for _, e, t, verdict in row["checks"]:
        if isinstance(t, float) and t > 0:
            r = max(r, abs(e) / t)
        elif verdict == "FAIL":
            r = max(r, 1.5)
    return r


# --- output ----------------------------------------------------------------------------------
def write_csv(rows, path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "knob", "value", "setting", "status", "wall_s", "cpu_s", "check", "error", "tolerance",
                    "verdict", "message"])
        for r in rows:
            for c in r["checks"] or [("", "", "", "")]:
                w.writerow([r["case"], r["knob"], r["value"], r["setting"], r["status"], f"{r['wall']:.1f}",
                            f"{r['cpu']:.1f}", *c, r["message"]])


def read_csv(path):
    """The rows of a sweep's CSV (write_csv's layout) back; the reference's knob values from its
    case directory, if it is still there."""
    rows, by = [], {}
    with open(path, newline="") as f:
        for rec in csv.DictReader(f):
            key = (rec["case"], rec["knob"], rec["value"])
            if key not in by:
                by[key] = dict(case=rec["case"], knob=rec["knob"], value=rec["value"], setting=rec["setting"],
                               status=rec["status"], message=rec["message"], wall=float(rec["wall_s"]),
                               cpu=float(rec["cpu_s"]), checks=[])
                rows.append(by[key])
            if rec["check"]:
                try:
                    tol = float(rec["tolerance"])
                except ValueError:
                    tol = rec["tolerance"]
                by[key]["checks"].append((rec["check"], float(rec["error"]), tol, rec["verdict"]))
    for r in rows:
        ref_case = os.path.join(WORK, r["case"], "reference")
        if r["knob"] == "reference" and os.path.isdir(ref_case):
            r["refvals"] = reference_values(ref_case)
    return rows


def merge_rows(old, new):
    """old's rows in their order, each replaced by new's row of the same case, knob and value;
    then new's other rows."""
    by = {(r["case"], r["knob"], r["value"]): r for r in new}
    return [by.pop((r["case"], r["knob"], r["value"]), r) for r in old] + list(by.values())


def pareto_plot(name, rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(9, 5))
    knobs = sorted({r["knob"] for r in rows})
    colours = plt.cm.tab20(np.linspace(0, 1, 20))   # more knobs than tab10 has colours
    for k, knob in enumerate(knobs):
        pts = [r for r in rows if r["knob"] == knob and math.isfinite(r["wall"]) and r["checks"]]
        if not pts:
            continue
        ax.scatter([r["wall"] for r in pts], [max(worst(r), 1e-3) for r in pts], color=colours[(2 * k) % 20 + (2 * k) // 20 % 2],
                   marker="*" if knob == "reference" else "o", s=90 if knob == "reference" else 30, label=knob)
        for r in pts:
            ax.annotate(r["value"], (r["wall"], max(worst(r), 1e-3)), fontsize=6, xytext=(3, 2),
                        textcoords="offset points")
    ys = [max(worst(r), 1e-3) for r in rows if r["checks"]] or [1.0]
    lo, hi = min(ys) / 2, max(2.0, 2 * max(ys))
    ax.axhspan(lo, 1.0, color="tab:green", alpha=0.08, label="every check within its tolerance")
    ax.set_ylim(lo, hi)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel("worst check error / its tolerance")
    ax.set_title(f"{name}: each knob changed from the reference", fontsize=10)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


CG_NOTE = ("The coarseGraining rows are the tutorial's -coarseGraining family (a column periodic across the flow, "
           "the divided void fraction, the same mass in parcels; cg 1 is that family's own reference), so their "
           "times compare with the reference's roughly: the bed and the column differ a little.")


def knob_value(r):
    """A run's knob value as a number (dt: the fraction of T_R it ran at), for ordering."""
    if r["knob"] in ("dt", "dtStrict"):
        return float(r["setting"].split()[0]) if r["setting"] else float(r["value"])
    return float(r["value"])


def extremes(rs):
    """Per ordered knob and direction from the reference: the last value that passes, the first that
    leaves its tolerance (FAIL) and the first at which the run stops, with its message."""
    ref = next((r for r in rs if r["knob"] == "reference" and "refvals" in r), None)
    if ref is None:
        return []
    out = []
    for knob in ORDERED:
        pts = sorted((r for r in rs if r["knob"] == knob), key=knob_value)
        if not pts:
            continue
        x0 = ref["refvals"][knob]
        for sign, word in ((1, "up"), (-1, "down")):
            side = [r for r in pts if sign * (knob_value(r) - x0) > 1e-9 * abs(x0)]
            side.sort(key=lambda r: sign * knob_value(r))
            if not side:
                continue
            passing, fail, stop = f"{x0:.3g} (reference)", None, None
            for r in side:
                if r["status"] == "PASS" and fail is None and stop is None:
                    passing = f"{knob_value(r):.3g}"
                elif r["status"] == "FAIL" and fail is None and stop is None:
                    fail = r
                elif r["status"] not in ("PASS", "FAIL") and stop is None:
                    stop = r
            out.append((knob, f"{x0:.3g}", word, passing,
                        f"{knob_value(fail):.3g} (worst {worst(fail):.2f})" if fail else
                        f"not within {knob_value(side[-1]):.3g}",
                        f"{knob_value(stop):.3g}: {stop['status']} {stop['message']}" if stop else
                        f"not within {knob_value(side[-1]):.3g}"))
    return out


def write_markdown(rows, path, command, figures, wall):
    lines = ["# The speed/accuracy trade, measured", "",
             f"Generated by `{command}` ({time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, "
             + (f"{len(rows)} runs in {wall / 60:.0f} min wall, " if wall else "")
             + f"{os.cpu_count()} cores; wall and CPU time per run, two runs at a time: these machines are "
             "shared and noisy, so ratios within one sweep are what to read). Each row changes one knob "
             "from the case's reference (bench/tradeoff.py says how each knob is applied). "
             "'worst' is the largest check error over its tolerance (1 = at the tolerance); the "
             "checks are the tutorial's own, against closed forms or published numbers. The Pareto plots "
             "draw each run's worst check error against its wall time, every knob a colour, the "
             "passing region shaded.", ""]
    for name in CASES:
        rs = [r for r in rows if r["case"] == name]
        if not rs:
            continue
        ref = next((r for r in rs if r["knob"] == "reference"), None)
        lines += [f"## {name}", "", "| knob | value | setting | status | wall [s] | CPU [s] | worst | failing checks (error / tolerance) or message |",
                  "|---|---|---|---|---|---|---|---|"]
        for r in rs:
            fails = "; ".join(f"{c} {e:.3g}/{t}" for c, e, t, v in r["checks"] if v == "FAIL") or r["message"]
            lines.append(f"| {r['knob']} | {r['value']} | {r['setting']} | {r['status']} | {r['wall']:.1f} | "
                         f"{r['cpu']:.1f} | {worst(r):.2f} | {fails} |")
        if any(r["knob"] == "coarseGraining" for r in rs):
            lines += ["", CG_NOTE]
        ext = extremes(rs)
        if ext:
            lines += ["", "Extremes (dt in T_R of the smallest particle; a knob changed alone from the reference):", "",
                      "| knob | reference | direction | last passing | leaves its tolerance at | stops at, with its message |",
                      "|---|---|---|---|---|---|"]
            lines += ["| " + " | ".join(e) + " |" for e in ext]
        passing = [r for r in rs if r["status"] == "PASS"]
        if ref and passing:
            def said(best, what):
                return (f"{what}: **{best['knob']} {best['value']}** ({best['setting'] or 'the reference'}), "
                        f"{best['wall']:.1f} s wall against the reference's {ref['wall']:.1f} s: "
                        f"**{ref['wall'] / best['wall']:.2f}x** (CPU {ref['cpu'] / max(best['cpu'], 1e-9):.2f}x).")
            best = min(passing, key=lambda r: r["wall"])
            own = [r for r in passing if r["knob"] != "coarseGraining"]
            lines += ["", said(best, "Cheapest setting that passes every check")]
            if best["knob"] == "coarseGraining" and own:
                lines += ["", said(min(own, key=lambda r: r["wall"]), "In the case's own column (no coarse graining)")]
        png = os.path.relpath(os.path.join(figures, f"{name}.png"), os.path.dirname(os.path.abspath(path)))
        lines += ["", f"![{name}]({png})", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-quick", action="store_true")
    ap.add_argument("-smoke", action="store_true")
    ap.add_argument("-extremes", action="store_true", help="only the points past the sweep (EXTREMES)")
    ap.add_argument("-regression", action="store_true", help="the REGRESSION points, each checked (ctest)")
    ap.add_argument("-j", type=int, default=min(2, os.cpu_count() or 1))
    ap.add_argument("--cases")
    ap.add_argument("--knobs")
    ap.add_argument("--values", help="only these values of the knobs (with --update: re-run single points)")
    ap.add_argument("--timeout", type=float, default=1800.0)
    ap.add_argument("--markdown", help="the generated page (default: docs/tradeoff.md for the full sweep, "
                    "bench/results/tradeoff_<mode>.md otherwise)")
    ap.add_argument("--combine", action="store_true",
                    help="after the runs, the greedy combination of each case's passing knobs (the full "
                         "sweep does it always); with --update on the CSV's rows")
    ap.add_argument("--update", action="store_true",
                    help="run only what --cases/--knobs select (no reference unless --knobs names it) and "
                         "replace those rows in the sweep's CSV; the table and plots from all rows")
    a = ap.parse_args()
    if a.regression:
        return regression(a.timeout)
    sweep = SMOKE if a.smoke else QUICK if a.quick else EXTREMES if a.extremes else \
        {c: {**SWEEP[c], **{k: SWEEP[c].get(k, []) + v for k, v in EXTREMES[c].items()}} for c in SWEEP}
    cases = a.cases.split(",") if a.cases else list(sweep)
    tag = "smoke" if a.smoke else "quick" if a.quick else "extremes" if a.extremes else "full"
    # the full sweep's page, plots and CSV are the project's record (docs/tradeoff.md, docs/tradeoff/);
    # the other modes write beside their runs and leave that record alone
    out = os.path.join(TOP, "docs/tradeoff") if tag == "full" else RESULTS
    a.markdown = a.markdown or (os.path.join(TOP, "docs/tradeoff.md") if tag == "full"
                                else os.path.join(RESULTS, f"tradeoff_{tag}.md"))
    csv_path = os.path.join(out, f"tradeoff_{tag}.csv")
    old_rows = read_csv(csv_path) if a.update and os.path.exists(csv_path) else []
    have_ref = {r["case"] for r in old_rows if r["knob"] == "reference"}
    jobs = []
    for name in cases:
        if not a.update or name not in have_ref or (a.knobs and "reference" in a.knobs.split(",")):
            jobs.append((name, None, None))
        for knob, values in sweep[name].items():
            if a.knobs and knob not in a.knobs.split(","):
                continue
            jobs += [(name, knob, v) for v in values if not a.values or str(v) in a.values.split(",")]
    print(f"tradeoff: {len(jobs)} runs, {a.j} at a time")
    from concurrent.futures import ThreadPoolExecutor
    rows = []
    t0 = time.time()
    with ThreadPoolExecutor(max_workers=a.j) as ex:
        for row in ex.map(lambda j: run_one(*j, a.timeout), jobs):
            rows.append(row)
            print(f"  {row['case']:13s} {row['knob']:16s} {row['value']:10s} {row['status']:9s} "
                  f"{row['wall']:7.1f} s wall {row['cpu']:7.1f} s CPU  worst {worst(row):.2f}  {row['setting']}"
                  + (f"  ({row['message']})" if row["message"] else ""), flush=True)
    rows = merge_rows(old_rows, rows)   # with --update: the CSV's rows, the new ones in their place
    if a.combine or (not (a.smoke or a.quick or a.extremes) and not a.update):
        combos = []
        with ThreadPoolExecutor(max_workers=a.j) as ex:
            for found in ex.map(lambda n: combine(n, [r for r in rows if r["knob"] != "combined"], a.timeout),
                                list(dict.fromkeys(r["case"] for r in rows))):
                combos += found
        rows = merge_rows(rows, combos)
    if a.update:
        cases = list(dict.fromkeys(r["case"] for r in rows))
    os.makedirs(out, exist_ok=True)
    write_csv(rows, csv_path)
    for name in cases:
        pareto_plot(name, [r for r in rows if r["case"] == name], os.path.join(out, f"{name}.png"))
    if not a.smoke:
        write_markdown(rows, a.markdown, "bench/tradeoff.sh" + (" -quick" if a.quick else " -extremes" if a.extremes else "")
                       + (" (with points re-run by --update)" if a.update else ""), out, None if a.update else time.time() - t0)
    print(f"tradeoff: {time.time() - t0:.0f} s wall; {os.path.relpath(csv_path, TOP)}"
          + ("" if a.smoke else f", {os.path.relpath(a.markdown, TOP)}"))
    bad = [r for r in rows if r["status"] in ("CRASH", "HANG", "NONFINITE", "ERROR")]
    for r in bad:
        print(f"DEFECT {r['case']} {r['knob']}={r['value']}: {r['status']} {r['message']}")
    ref_fail = [r for r in rows if r["knob"] == "reference" and r["status"] != "PASS"]
    return 1 if bad or ref_fail else 0


if __name__ == "__main__":
    sys.exit(main())
