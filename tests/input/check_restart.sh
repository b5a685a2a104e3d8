#!/bin/bash
# Restart: a run to t = 0.01 s, continued with -restart to t = 0.02 s, must go on from the last
# complete snapshot (same particles, same ids, the time continues, snapshots append), and a
# snapshot whose writing was interrupted (no `complete` mark) must be skipped.
# Usage: check_restart.sh <demRun>
demRun=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/case/constant"
sed -e 's/^endTime        0.02;/endTime        0.01;/' -e 's/^writeInterval  0;/writeInterval  0.005;/' \
    "$here/base.demProperties" > "$work/case/constant/demProperties"
"$demRun" "$work/case" > "$work/run1.log" 2>&1 || { cat "$work/run1.log"; exit 1; }
sed -i 's/^endTime        0.01;/endTime        0.02;/' "$work/case/constant/demProperties"
"$demRun" "$work/case" -restart > "$work/run2.log" 2>&1 || { cat "$work/run2.log"; exit 1; }
/usr/bin/python3 - "$work/case/particles.h5" "$work/run2.log" <<'PY'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
snaps = sorted(f["snapshots"])
times = [float(f["snapshots"][k].attrs["time"]) for k in snaps]
ids = [np.sort(f["snapshots"][k]["id"][...]) for k in snaps]
log = open(sys.argv[2]).read()
checks = [
    ("restart message names t = 0.01 s", "restart from" in log and "t = 0.01 s" in log),
    ("snapshots 0, 0.005, 0.01 then 0.015, 0.02 s", np.allclose(times, [0, 0.005, 0.01, 0.015, 0.02], atol=1e-12)),
    ("same particle ids in every snapshot", all(np.array_equal(i, ids[0]) for i in ids)),
    ("all snapshots complete", all("complete" in f["snapshots"][k].attrs for k in snaps)),
]
failed = 0
for name, ok in checks:
    print(f"CHECK {name} {'PASS' if ok else 'FAIL'}")
    failed += not ok
print(f"restart: {len(checks) - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
PY
