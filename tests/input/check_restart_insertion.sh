#!/bin/bash
# Restart of cases with a lattice or file insertion and symmetry planes. The planes are case
# geometry, read again from demProperties (nothing of them is saved); the insertion is skipped on
# restart (case_read's skip_insertion), so the particles come from the snapshot only.
#  1. lattice bed moving at -0.2 m/s between two symmetry planes, under gravity: run to 0.03 s, and
#     the same run stopped at 0.015 s and restarted to 0.03 s: positions equal (1e-9 m);
#  2. file insertion: run to 0.01 s, delete the positions file, restart to 0.02 s: the restart
#     runs (the file is not read), inserts nothing, keeps the particle ids.
# Usage: check_restart_insertion.sh <demRun>
demRun=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# a second symmetry plane at +x and walls at +-y close the base case's domain
walls='s|^    front .*$|&\n    back  { type symmetryPlane; point (0.01 0 0); normal (-1 0 0); }\n    left  { type plane; point (0 -0.01 0); normal (0 1 0); material glass; }\n    right { type plane; point (0 0.01 0); normal (0 -1 0); material glass; }|'
make_case() {   # dir endTime writeInterval [extra sed]
    mkdir -p "$1/constant"
    sed -e "s/^endTime        0.002;/endTime        $2;/" -e "s/^writeInterval  0;/writeInterval  $3;/" \
        -e "s/^        material glass;/        material glass; velocity (-0.2 0 0);/" -e "$walls" -e "${4:-}" \
        "$here/base_insertion.demProperties" > "$1/constant/demProperties"
}
run() { "$demRun" "$@" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }; cat "$work/log" >> "$work/all.log"; }

make_case "$work/straight" 0.03 0.005
run "$work/straight"
make_case "$work/split" 0.015 0.005
run "$work/split"
sed -i 's/^endTime        0.015;/endTime        0.03;/' "$work/split/constant/demProperties"
run "$work/split" -restart
cp "$work/log" "$work/lattice_restart.log"

FILE='20s/method   lattice;/method   file; file "positions.dat";/;21,23d'
make_case "$work/file" 0.01 0.005 "$FILE"
awk 'BEGIN { for (i = 0; i < 100; i++) printf "%.6f %.6f %.6f\n", -0.008 + 0.004 * (i % 5),
                -0.008 + 0.004 * (int(i / 5) % 5), 0.002 + 0.004 * int(i / 25) }' > "$work/file/constant/positions.dat"
run "$work/file"
rm "$work/file/constant/positions.dat"
sed -i 's/^endTime        0.01;/endTime        0.02;/' "$work/file/constant/demProperties"
run "$work/file" -restart
cp "$work/log" "$work/file_restart.log"

/usr/bin/python3 - "$work" <<'PY'
import sys, h5py, numpy as np
work = sys.argv[1]
def final(path):
    g = h5py.File(path, "r")["snapshots"]
    keys = sorted(g)
    last = g[keys[-1]]
    order = np.argsort(last["id"][...])
    return float(last.attrs["time"]), last["position"][...][order], last["id"][...][order], g, keys
t_a, xa, _, _, _ = final(f"{work}/straight/particles.h5")
t_b, xb, _, _, _ = final(f"{work}/split/particles.h5")
diff = np.abs(xa - xb).max()
xmin = xb[:, 0].min()
t_f, _, ids_f, g, keys = final(f"{work}/file/particles.h5")
ids0 = np.sort(g[keys[0]]["id"][...])
lat_log = open(f"{work}/lattice_restart.log").read()
file_log = open(f"{work}/file_restart.log").read()
print(f"lattice bed: restarted vs straight run, largest position difference {diff:.3g} m; "
      f"lowest x {xmin:.6g} m (symmetry plane at -0.01 m)")
checks = [
    ("lattice: restart from t = 0.015 s, no insertion", "restart from" in lat_log and "t = 0.015 s" in lat_log
     and "insertion '" not in lat_log),
    ("lattice: restarted run ends at the same time", abs(t_a - t_b) < 1e-12),
    ("lattice: positions as without restart (1e-9 m)", diff < 1e-9),
    ("lattice: centres reached the symmetry plane, none beyond", -0.01 - 1e-15 <= xmin < -0.01 + 5e-4),
    ("file: restart runs without the positions file, no insertion", "restart from" in file_log
     and "insertion '" not in file_log),
    ("file: ends at t = 0.02 s with the same 100 particle ids", abs(t_f - 0.02) < 1e-12 and len(ids_f) == 100
     and np.array_equal(ids_f, ids0)),
]
failed = 0
for name, ok in checks:
    print(f"CHECK {name} {'PASS' if ok else 'FAIL'}")
    failed += not ok
print(f"restart_insertion: {len(checks) - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
PY
