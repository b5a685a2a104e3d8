#!/bin/bash
# The DEM bed on 1, 2 and 4 ranks (issue 23), and restarts across rank counts: 2,000 glass spheres
# of 1.5 mm poured into a 20 x 20 x 40 mm box (Hertz, tangential history) settle for 0.25 s.
#  1. `mpirun -np 2` and `-np 4` (oversubscribed) of the straight run: the same 2,000 ids, and the
#     settled bed's height (twice the mean centre height) and solid fraction (the spheres' volume
#     over the box's cross-section times that height) within 0.5 % of the serial run's;
#  2. a run made on 4 ranks to 0.15 s and restarted on 1 rank to 0.25 s, and one made on 1 rank and
#     restarted on 2: the same ids, height and solid fraction within 0.5 % of the straight serial run;
#  3. every snapshot of a parallel run holds every particle once (one file, written by all ranks);
#  4. bad input on 2 ranks (every rank reads it) stops both, with one message naming file:line and
#     key, and a non-zero exit status;
#  5. an outlet (a drain under the pour, acting every 1 ms, to 0.08 s) on 1, 2 and 4 ranks, and on 2
#     ranks restarted on 1 at 0.04 s: the same particles removed (count and mass exact, the same ids
#     left) and the mass balance exact in every log;
#  6. a stream (lifecycle.demProperties' feed pipe, 0.06 s) on 1, 2 and 4 ranks: the same ids at the
#     same places (1e-12 m) at every write, and the mass balance exact in every log.
# The largest difference in position from the serial run is printed (the runs differ only in the
# order of force sums, which a pour amplifies).
# Usage: check_parallel_bed.sh <demRun> <mpiexec>
demRun=$1
mpiexec=${2:-mpirun}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1   # ../shared/docs: mpirun as root
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
make_case() {   # dir endTime
    mkdir -p "$1/constant"
    sed -e "s/^endTime        0.02;/endTime        $2;/" -e "s/^writeInterval  0;/writeInterval  0.05;/" \
        -e "s/number   200;/number   2000;/" -e "s/value 2e-3;/value 1.5e-3;/" \
        "$here/base.demProperties" > "$1/constant/demProperties"
}
. "$here/run_ranks.sh"
run() { run_ranks "$@"; }   # ranks dir [args]
drain() { echo 'outlets { drain { type plane; point (0 0 0.004); normal (0 0 -1); interval 1e-3; } }' >> "$1/constant/demProperties"; }
for np in 1 2 4; do make_case "$work/drain$np" 0.08; drain "$work/drain$np"; run $np "$work/drain$np"; cp "$work/log" "$work/drain$np.log"; done
make_case "$work/drainR" 0.04; drain "$work/drainR"; run 2 "$work/drainR"
sed -i 's/^endTime        0.04;/endTime        0.08;/' "$work/drainR/constant/demProperties"; run 1 "$work/drainR" -restart
cp "$work/log" "$work/drainR.log"
for c in drain1 drain2 drain4 drainR; do
    grep "mass balance at t = 0.08 s" "$work/$c.log" | sed "s/^/  $c: /"
    grep -q "mass balance at t = 0.08 s:.*(exact)" "$work/$c.log" || { echo "CHECK $c: the mass balance closes exactly FAIL"; exit 1; }
done

# a stream (tests/input/lifecycle.demProperties: beads fed through a disc, colliding in a tube) on
# 1, 2 and 4 ranks: every rank draws and places alike against the particles of all ranks near the
# face, and keeps what its box holds
for np in 1 2 4; do
    mkdir -p "$work/feed$np/constant"
    sed -e "s/^endTime        0.2;/endTime        0.06;/" "$here/lifecycle.demProperties" > "$work/feed$np/constant/demProperties"
    run $np "$work/feed$np"; cp "$work/log" "$work/feed$np.log"
    grep -q "mass balance at t = 0.06 s:.*(exact)" "$work/feed$np.log" || { echo "CHECK feed$np: the mass balance closes exactly FAIL"; exit 1; }
done

make_case "$work/bad" 0.25
sed -i 's/youngsModulus 5e6/youngsModulus -5e6/' "$work/bad/constant/demProperties"
if "$mpiexec" -np 2 --oversubscribe "$demRun" "$work/bad" > "$work/bad.log" 2>&1; then
    echo "CHECK bad input on 2 ranks stops the run                                                         FAIL"; exit 1
fi
nerr=$(grep -c "error:" "$work/bad.log")
if [ "$nerr" = 1 ] && grep -q "demProperties:[0-9]*: error: key 'youngsModulus'" "$work/bad.log"; then
    echo "CHECK bad input on 2 ranks: one message with file:line and key, exit status non-zero             PASS"
else
    echo "CHECK bad input on 2 ranks: one message with file:line and key ($nerr 'error:' lines)            FAIL"
    cat "$work/bad.log"; exit 1
fi
for np in 1 2 4; do make_case "$work/straight$np" 0.25; run $np "$work/straight$np"; done
make_case "$work/from4" 0.15; run 4 "$work/from4"
sed -i 's/^endTime        0.15;/endTime        0.25;/' "$work/from4/constant/demProperties"; run 1 "$work/from4" -restart
make_case "$work/from1" 0.15; run 1 "$work/from1"
sed -i 's/^endTime        0.15;/endTime        0.25;/' "$work/from1/constant/demProperties"; run 2 "$work/from1" -restart

/usr/bin/python3 - "$work" <<'PY'
import sys, h5py, numpy as np
work = sys.argv[1]
N, R, AREA = 2000, 0.75e-3, 0.02 * 0.02
failed = 0
def check(what, ok):
    global failed
    print(f"CHECK {what:<100} {'PASS' if ok else 'FAIL'}")
    failed += not ok
def last(case):
    with h5py.File(f"{work}/{case}/particles.h5", "r") as f:
        snaps = f["snapshots"]
        every_once = all(np.array_equal(np.sort(snaps[k]["id"][:]), np.arange(N)) for k in snaps)
        s = snaps[sorted(snaps)[-1]]
        ids, x = s["id"][:], s["position"][:]
        o = np.argsort(ids)
        return ids[o], x[o], float(s.attrs["time"]), every_once
ids1, x1, t1, _ = last("straight1")
h1 = 2 * x1[:, 2].mean()
phi1 = N * 4 / 3 * np.pi * R**3 / (AREA * h1)
print(f"serial: t = {t1:g} s, bed height {h1 * 1e3:.4f} mm, solid fraction {phi1:.4f}")
for case, what in [("straight2", "2 ranks"), ("straight4", "4 ranks"), ("from4", "4 ranks to 0.15 s, restarted on 1"),
                   ("from1", "1 rank to 0.15 s, restarted on 2")]:
    ids, x, t, every_once = last(case)
    h = 2 * x[:, 2].mean()
    phi = N * 4 / 3 * np.pi * R**3 / (AREA * h)
    dx = np.abs(x - x1).max() if np.array_equal(ids, ids1) else float("inf")
    check(f"{what}: t = {t:g} s, ids 0..{N - 1} each once in every snapshot", t == t1 and np.array_equal(ids, ids1) and every_once)
    check(f"{what}: bed height {h * 1e3:.4f} mm, {100 * (h / h1 - 1):+.3f} % of serial (0.5 % allowed)", abs(h / h1 - 1) <= 0.005)
    check(f"{what}: solid fraction {phi:.4f}, {100 * (phi / phi1 - 1):+.3f} % of serial (0.5 % allowed)", abs(phi / phi1 - 1) <= 0.005)
    print(f"  {what}: largest difference in position from the serial run {dx:.3g} m")
def left(case):
    with h5py.File(f"{work}/{case}/particles.h5", "r") as f:
        s = f["snapshots"][sorted(f["snapshots"])[-1]]
        return float(s.attrs["time"]), np.sort(s["id"][:]), s["lifecycle/balance"][:]
t0, ids0, bal0 = left("drain1")
for case, what in [("drain2", "2 ranks"), ("drain4", "4 ranks"), ("drainR", "2 ranks to 0.04 s, restarted on 1")]:
    t, ids, bal = left(case)
    check(f"outlet, {what}: {N - len(ids)} removed by t = {t:g} s as serially ({N - len(ids0)}), the same ids left, "
          f"the same counts and mass", t == t0 and np.array_equal(ids, ids0) and np.array_equal(bal, bal0))
# the stream: at every write the same ids at the same places on 2 and 4 ranks as on 1 (1e-12 m:
# only the order of force sums may differ)
def snaps(case):
    with h5py.File(f"{work}/{case}/particles.h5", "r") as f:
        out = []
        for k in sorted(f["snapshots"]):
            s = f["snapshots"][k]
            order = np.argsort(s["id"][:])
            out.append((float(s.attrs["time"]), s["id"][:][order], s["position"][:][order]))
        return out
feed1 = snaps("feed1")
for case, what in [("feed2", "2 ranks"), ("feed4", "4 ranks")]:
    other = snaps(case)
    same = len(other) == len(feed1) and all(t == u and np.array_equal(i, j) for (t, i, _), (u, j, _) in zip(feed1, other))
    dx = max(np.abs(x - y).max() if len(x) else 0.0 for (_, _, x), (_, _, y) in zip(feed1, other)) if same else float("inf")
    check(f"stream, {what}: {len(feed1[-1][1])} beads fed by t = {feed1[-1][0]:.3g} s, the same ids at every write as serially, "
          f"positions within 1e-12 m (largest {dx:.3g} m)", same and dx <= 1e-12)
sys.exit(1 if failed else 0)
PY
