#!/bin/bash
# Restart of multisphere bodies, bit for bit: a pour of 300 tetrahedral clumps
# (base_multisphere.demProperties) run straight to 0.08 s, and to 0.03 s, then on with -restart
# to 0.08 s, while the clumps still fall and collide. Compared at 0.08 s for exact equality:
# every sphere's position and velocity and every body's centre, orientation, velocity and angular
# momentum. Control: the same continuation with the velocity of one body in contact (the largest
# torque) changed in its last bit at 0.03 s must end more than 1e-9 m/s away, so that the
# comparison can see round-off.
# Usage: check_restart_bodies.sh <demRun>
demRun=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() { "$demRun" "$@" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }; }
for c in straight split; do mkdir -p "$work/$c/constant"; cp "$here/base_multisphere.demProperties" "$work/$c/constant/demProperties"; done
run "$work/straight"
sed -i 's/^endTime .*/endTime        0.03;/' "$work/split/constant/demProperties"
run "$work/split"
sed -i 's/^endTime .*/endTime        0.08;/' "$work/split/constant/demProperties"
cp -r "$work/split" "$work/perturbed"
run "$work/split" -restart
grep -q "multisphere: 300 bodies" "$work/log" || { echo "FAIL: the restarted run has not its 300 bodies"; cat "$work/log"; exit 1; }
/usr/bin/python3 - "$work/perturbed" <<'PY' || exit 1
import sys, h5py, numpy as np
with h5py.File(sys.argv[1] + "/particles.h5", "r+") as h:
    g = max(h["snapshots"].values(), key=lambda g: g.attrs["time"])
    v = g["bodies/velocity"][...]
    k = int(np.argmax(np.linalg.norm(g["bodies/torque"][...], axis=1)))   # one in contact
    v[k, 2] = np.nextafter(v[k, 2], np.inf)
    g["bodies/velocity"][...] = v
PY
run "$work/perturbed" -restart
/usr/bin/python3 - "$work" <<'PY'
import sys, h5py, numpy as np
work = sys.argv[1]
failed = False
def check(name, measured, tol, at_least=False):
    global failed
    ok = measured >= tol if at_least else measured <= tol
    failed |= not ok
    print(f"CHECK {name} measured={measured:.3e} {'minimum' if at_least else 'tolerance'}={tol:g} {'PASS' if ok else 'FAIL'}")
def last(case):
    with h5py.File(f"{work}/{case}/particles.h5", "r") as h:
        g = max(h["snapshots"].values(), key=lambda g: g.attrs["time"])
        i = np.argsort(g["id"][:]); b = g["bodies"]; k = np.argsort(b["id"][:, 0])
        return (g.attrs["time"], {"sphere position": g["position"][:][i], "sphere velocity": g["velocity"][:][i],
                "body position": b["position"][:][k], "body orientation": b["orientation"][:][k],
                "body velocity": b["velocity"][:][k], "body angular momentum": b["angular_momentum_body"][:][k]})
ta, a = last("straight"); tb, b = last("split"); tc, c = last("perturbed")
check("final_time_s", abs(ta - tb), 0)
check("final_time_is_0.08_s", abs(ta - 0.08), 1e-9)
for key in a:
    check(key.replace(" ", "_") + "_entries_that_differ", int(np.sum(a[key] != b[key])), 0)
dv = np.abs(a["sphere velocity"] - c["sphere velocity"]).max()
print(f"control: one ulp of one body's velocity at 0.03 s -> max |dv| {dv:.3e} m/s at 0.08 s")
check("control_velocity_difference_m_per_s", dv, 1e-9, at_least=True)
sys.exit(1 if failed else 0)
PY
