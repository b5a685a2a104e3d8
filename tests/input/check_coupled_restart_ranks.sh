#!/bin/bash
# A coupled run continued on another number of ranks (issue 23): the short fluidisedBed case (5,000
# beads falling from their lattice and landing), run to 0.05 s on 1 rank and continued to 0.1 s on
# 2 (decomposePar of the written time, mpirun -parallel, reconstructPar), and the reverse (2 ranks,
# reconstructPar, then 1). The bed is chaotic (check_coupled_restart.sh: one ulp grows to 0.4 m/s
# in 0.05 s), so the continued runs cannot equal the straight one; what must hold exactly does:
#   - each continued run starts from the snapshot at 0.05 s (its log says so, at DEM step 4000);
#   - at 0.1 s the snapshot is complete with the 5,000 beads, ids 0 .. 4999 each once, and the
#     beads' total volume that of the straight serial run to 1e-12 (none lost or duplicated);
#   - the gas momentum balance of every step after the restart within 1 % (the solver's check);
# and the bed's mean height at 0.1 s is printed beside the straight run's (INFO).
# Usage: check_coupled_restart_ranks.sh <voidPimpleFoam> <tutorials/fluidisedBed/Allrun>
set -uo pipefail
solver=$1 allrun=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export WM_PROJECT_DIR=${OF_DEV_DIR:-/opt/of/OpenFOAM-v1912}
[ -f "$WM_PROJECT_DIR/etc/controlDict" ] || export WM_PROJECT_DIR=/usr/share/openfoam
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fail=0
check() { if [ "$2" = 1 ]; then echo "CHECK $1 PASS"; else echo "CHECK $1 FAIL"; fail=1; fi; }
end_at() { sed -i -e "s/^endTime .*/endTime         $2;/" "$1/system/controlDict"; }
serial() { "$solver" -case "$1" > "$1/$2.log" 2>&1 || { tail -20 "$1/$2.log"; exit 1; }; }
parallel() {   # parallel <case> <log>: decompose what is written, run on 2 ranks, reconstruct
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (1 1 2); delta 0.001; }\n' \
        > "$1/system/decomposeParDict"
    ( cd "$1" && rm -rf processor* && decomposePar -force > log.decomposePar 2>&1 \
        && mpirun -np 2 "$solver" -parallel > "$2.log" 2>&1 && reconstructPar -newTimes > log.reconstructPar 2>&1 ) \
        || { tail -20 "$1/$2.log"; exit 1; }
}

"$allrun" -short-case "$work/base" > /dev/null || exit 1
sed -i -e 's/^writeInterval .*/writeInterval   0.05;/' "$work/base/system/controlDict"
blockMesh -case "$work/base" > "$work/blockMesh.log" 2>&1 || { tail "$work/blockMesh.log"; exit 1; }
for v in straight s2p p2s; do cp -r "$work/base" "$work/$v"; done
end_at "$work/straight" 0.1; serial "$work/straight" run
end_at "$work/s2p" 0.05; serial "$work/s2p" first
end_at "$work/s2p" 0.1; parallel "$work/s2p" second
end_at "$work/p2s" 0.05; parallel "$work/p2s" first
end_at "$work/p2s" 0.1; serial "$work/p2s" second

for v in s2p p2s; do
    what="1 -> 2 ranks"; [ $v = p2s ] && what="2 -> 1 rank"
    check "$what: continued from the snapshot at 0.05 s" \
        "$(grep -qE "coupling: continuing from .*particles.h5 at t = 0.05 s \(DEM step 4000\), 5000 particles" "$work/$v/second.log" && echo 1)"
    resid=$(awk '!/^#/ && NF >= 9 && $1 > 0.0501 {r = $9 < 0 ? -$9 : $9; if (r > m) m = r; n++} END {print m + 0, n + 0}' \
        "$work/$v/postProcessing/momentumBalance.dat")
    check "$what: the gas momentum balance within 1 % at every step after the restart (largest, steps: $resid)" \
        "$(awk -v r="${resid% *}" -v n="${resid#* }" 'BEGIN {print (r < 0.01 && n >= 240)}')"
    /usr/bin/python3 - "$work/straight" "$work/$v" "$what" <<'PY' || fail=1
import sys, h5py, numpy as np
def last(case):
    f = h5py.File(f"{case}/particles.h5", "r")["snapshots"]
    k = sorted(f)[-1]
    g = f[k]
    return g.attrs["time"], int(g.attrs["complete"]), g["id"][...], g["radius"][...], g["position"][...]
t0, c0, id0, r0, x0 = last(sys.argv[1])
t1, c1, id1, r1, x1 = last(sys.argv[2])
what = sys.argv[3]
ok = abs(t1 - 0.1) < 1e-9 and c1 == 1 and len(id1) == 5000 and np.array_equal(np.sort(id1), np.arange(5000))
print(f"CHECK {what}: at t = {t1:.6g} s a complete snapshot of {len(id1)} beads, ids 0 .. 4999 each once {'PASS' if ok else 'FAIL'}")
v0, v1 = (4 / 3 * np.pi * r0 ** 3).sum(), (4 / 3 * np.pi * r1 ** 3).sum()
okv = abs(v1 - v0) <= 1e-12 * v0
print(f"CHECK {what}: the beads' total volume as the straight run's (relative difference {abs(v1 - v0) / v0:.2g}, 1e-12) {'PASS' if okv else 'FAIL'}")
print(f"INFO {what}: mean bead height at 0.1 s {1e3 * x1[:, 2].mean():.4f} mm, the straight serial run {1e3 * x0[:, 2].mean():.4f} mm")
sys.exit(0 if ok and okv else 1)
PY
done
grep -h "Bytes sent per rank" "$work"/s2p/second.log | sed 's/^/INFO 2 ranks: /'
[ $fail = 0 ] && echo "coupled_restart_ranks: passed" || { echo "coupled_restart_ranks: FAILED"; exit 1; }
