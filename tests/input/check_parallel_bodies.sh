#!/bin/bash
# Multisphere bodies on 1, 2 and 4 ranks (issue 23), and restarts across rank counts: the pour of
# 300 tetrahedral clumps of check_restart_bodies.sh (base_multisphere.demProperties), run until it
# has settled (0.3 s; its kinetic energy is below 1e-9 J/kg from 0.25 s on).
#  1. `mpirun -np 2` and `-np 4` (oversubscribed) of the straight run, a run made on 4 ranks to
#     0.15 s and restarted on 1 rank, and one made on 1 rank and restarted on 2: the settled bed's
#     height (twice the bodies' mean centre height) and solid fraction (the bodies' volume over the
#     box's cross-section times that height) within 0.5 % of the serial run's (the runs differ in
#     the order of force sums, which a pour amplifies; the largest difference is printed);
#  2. every snapshot of every run (one file, written by all ranks) holds the 300 bodies and their
#     1,200 spheres once each, each sphere's body among them, and each sphere where its body puts it:
#     centre + R(q) offset, to 1e-12 m (the rows of bodies and spheres written by different ranks
#     belong together);
#  3. each log counts the 300 bodies.
# Usage: check_parallel_bodies.sh <demRun> <mpiexec>
demRun=$1
mpiexec=${2:-mpirun}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
make_case() {   # dir endTime
    mkdir -p "$1/constant"
    sed -e "s/^endTime .*/endTime        $2;/" -e "s/^writeInterval .*/writeInterval  0.05;/" \
        "$here/base_multisphere.demProperties" > "$1/constant/demProperties"
}
. "$here/run_ranks.sh"
run() {   # ranks dir [args]
    run_ranks "$@"
    grep -q "multisphere: 300 bodies" "$work/log" || { echo "FAIL: $1 rank(s), $(basename "$2"): not 300 bodies"; cat "$work/log"; exit 1; }
}
for np in 1 2 4; do make_case "$work/straight$np" 0.3; run $np "$work/straight$np"; done
make_case "$work/from4to1" 0.15; run 4 "$work/from4to1"
sed -i "s/^endTime .*/endTime        0.3;/" "$work/from4to1/constant/demProperties"; run 1 "$work/from4to1" -restart
make_case "$work/from1to2" 0.15; run 1 "$work/from1to2"
sed -i "s/^endTime .*/endTime        0.3;/" "$work/from1to2/constant/demProperties"; run 2 "$work/from1to2" -restart
/usr/bin/python3 - "$work" <<'PY'
import sys, h5py, numpy as np
work = sys.argv[1]
failed = False
def check(name, ok, text):
    global failed
    failed |= not ok
    print(f"CHECK {name} {text} {'PASS' if ok else 'FAIL'}")
def rotate(q, v):   # q = (w, x, y, z) rotates v, row by row
    w, u = q[:, :1], q[:, 1:]
    t = 2.0 * np.cross(u, v)
    return v + w * t + np.cross(u, t)
area = 0.02 * 0.02
def snapshots(case):
    worst_pair, complete = 0.0, True
    with h5py.File(f"{work}/{case}/particles.h5", "r") as h:
        snaps = sorted(h["snapshots"].values(), key=lambda g: g.attrs["time"])
        for g in snaps:
            b = g["bodies"]
            bid = b["id"][:, 0]; sid = g["id"][:]; body = g["body"][:] - 1
            complete &= len(bid) == 300 and len(np.unique(bid)) == 300 and len(sid) == 1200 and len(np.unique(sid)) == 1200
            row = {k: i for i, k in enumerate(bid)}
            if not all(k in row for k in body):
                complete = False; continue
            k = np.array([row[k] for k in body])
            want = b["position"][:][k] + rotate(b["orientation"][:][k], g["body_offset"][:])
            worst_pair = max(worst_pair, float(np.abs(g["position"][:] - want).max()))
        last = snaps[-1]
        z = last["bodies/position"][:, 2]
        height = 2.0 * z.mean()
        volume = 300 * 7.56541e-09   # the union's volume, as the log gives it
        return last.attrs["time"], height, volume / (area * height), complete, worst_pair, len(snaps), last["bodies/position"][:][np.argsort(last["bodies/id"][:, 0])]
t1, h1, phi1, ok1, pair1, n1, x1 = snapshots("straight1")
print(f"serial: bed height {h1 * 1e3:.4f} mm, solid fraction {phi1:.4f} at t = {t1:.3f} s")
for case in ("straight1", "straight2", "straight4", "from4to1", "from1to2"):
    t, h, phi, ok, pair, n, x = snapshots(case)
    check(f"{case}_snapshots", ok and pair <= 1e-12,
          f"{n} snapshots: 300 bodies and 1,200 spheres once each, each sphere where its body puts it (largest miss {pair:.2e} m, 1e-12 allowed)")
    if case == "straight1": continue
    check(f"{case}_time", abs(t - t1) < 1e-9, f"ends at t = {t:.6f} s")
    check(f"{case}_height", abs(h / h1 - 1) <= 5e-3, f"bed height {h * 1e3:.4f} mm, {100 * (h / h1 - 1):+.3f} % of serial (0.5 % allowed)")
    check(f"{case}_solid_fraction", abs(phi / phi1 - 1) <= 5e-3, f"solid fraction {phi:.4f}, {100 * (phi / phi1 - 1):+.3f} % of serial (0.5 % allowed)")
    print(f"  {case}: largest difference in a body's centre from the serial run {np.abs(x - x1).max():.3e} m")
sys.exit(1 if failed else 0)
PY
