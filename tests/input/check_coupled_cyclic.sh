#!/bin/bash
# Cyclic sides in a coupled run (issue 21; in parallel, issue 23): the settling box of tutorials/settling made periodic
# in x (cyclic patches left/right for the gas, domain periodic in x for the particles), 40
# spheres (d = 1 mm, divided void fraction, cellPoint interpolation) launched at 0.3 m/s along x,
# so that they cross the cyclic sides while they settle. Checks:
#   - the solver takes the 80 face pairs and runs 0.05 s; particles wrapped across the sides;
#   - at every write time, sum over cells of (1 - alpha) V = the particles' volume (1e-9: the
#     divided model's share beyond a cyclic face is on the other side, none dropped);
#   - the gas momentum balance of every step within 1 % (the solver's own check);
#   - particles periodic in x with a mesh that is not (and the other way round), or sides that do
#     not match, stop with demProperties:line and the key.
# Usage: check_coupled_cyclic.sh <voidPimpleFoam> <tutorials/settling>
solver=$1 src=$2
export WM_PROJECT_DIR=${OF_DEV_DIR:-/opt/of/OpenFOAM-v1912}
[ -f "$WM_PROJECT_DIR/etc/controlDict" ] || export WM_PROJECT_DIR=/usr/share/openfoam
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
check() { if [ "$2" = 1 ]; then echo "CHECK $1 PASS"; else echo "CHECK $1 FAIL"; fail=1; fi; }

make_case() {   # dir: the periodic channel
    cp -r "$src" "$1"
    rm -rf "$1"/log.* "$1"/particles.* "$1"/postProcessing "$1"/[1-9]* "$1"/0.[0-9]*
    cd "$1" || exit 1
    /usr/bin/python3 - <<'PY'
import re
b = open("system/blockMeshDict").read()
b = re.sub(r"boundary\s*\(.*\);", """boundary
(
    walls { type wall; faces ( (0 3 2 1) (4 5 6 7) (0 1 5 4) (2 3 7 6) ); }
    left  { type cyclic; neighbourPatch right; faces ( (0 4 7 3) ); }
    right { type cyclic; neighbourPatch left;  faces ( (1 2 6 5) ); }
);""", b, flags=re.S)
open("system/blockMeshDict", "w").write(b)
for f, wall in (("0/U", "walls { type noSlip; }"), ("0/p", "walls { type fixedFluxPressure; }")):
    t = open(f).read().replace(wall, wall + " left { type cyclic; } right { type cyclic; }")
    open(f, "w").write(t)
d = open("constant/demProperties").read()
d = d.replace("domain { min (-0.01 -0.01 0); max (0.01 0.01 0.1); }",
              "domain { min (-0.01 -0.01 0); max (0.01 0.01 0.1); periodic (true false false); }")
d = d.replace("walls { floor { type plane; point (0 0 0); normal (0 0 1); material sphere; } }",
              "walls { floor { type plane; point (0 0 0); normal (0 0 1); material sphere; }\n"
              "        front { type plane; point (0 -0.01 0); normal (0 1 0); material sphere; }\n"
              "        back { type plane; point (0 0.01 0); normal (0 -1 0); material sphere; } }")
d = re.sub(r"insertion\s*\{.*\}\s*$", """insertion
{
    release
    {
        region   { type box; min (-0.01 -0.009 0.05); max (0.01 0.009 0.09); }
        number   40;
        material sphere;
        velocity (0.3 0 0);
        diameter { distribution constant; value 1e-3; }
    }
}
""", d, flags=re.S)
open("constant/demProperties", "w").write(d)
c = open("constant/couplingProperties").read()
c = re.sub(r"model\s+centre;", "model     divided;", c).replace("interpolation cell;", "interpolation cellPoint;")
open("constant/couplingProperties", "w").write(c)
s = open("system/controlDict").read()
s = re.sub(r"^endTime .*", "endTime         0.05;", s, flags=re.M)
s = re.sub(r"^writeInterval .*", "writeInterval   0.01;", s, flags=re.M)
s = re.sub(r"^writePrecision .*", "writePrecision  17;", s, flags=re.M)   # alpha near 1: 8 digits hide 1e-8
open("system/controlDict", "w").write(s)
PY
    blockMesh > log.blockMesh 2>&1 || { tail -20 log.blockMesh; exit 1; }
    cd - > /dev/null
}

check_mapped() {   # check_mapped <case>: the volume at every write time, particles wrapped
/usr/bin/python3 - "$1" <<'PY' || fail=1
import sys, os, re, glob, h5py, numpy as np
case = sys.argv[1]
def field(path):
    t = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\)\s*;", t, re.S)
    if m: return np.array(m.group(2).split(), float)
    m = re.search(r"internalField\s+uniform\s+([-+0-9.eE]+)", t)
    return np.full(320, float(m.group(1)))
V = (0.02 / 4) * (0.02 / 4) * (0.1 / 20)
vp = np.pi / 6 * 1e-3 ** 3
worst, crossed = 0.0, 0
times = sorted((d for d in os.listdir(case) if re.fullmatch(r"0\.\d+", d)), key=float)
for t in times:
    a = field(f"{case}/{t}/alpha")
    mapped = ((1 - a) * V).sum()
    worst = max(worst, abs(mapped - 40 * vp) / (40 * vp))
f = h5py.File(f"{case}/particles.h5", "r")["snapshots"]
snaps = sorted(f)
x0 = f[snaps[0]]["position"][...][np.argsort(f[snaps[0]]["id"][...])]
x1 = f[snaps[-1]]["position"][...][np.argsort(f[snaps[-1]]["id"][...])]
crossed = int(((x1[:, 0] < x0[:, 0] - 1e-6)).sum())   # moving +x at 0.3 m/s: a smaller x means wrapped
print(f"{len(times)} write times: largest |sum (1-alpha)V - N V_p| / N V_p = {worst:.3g}; "
      f"{crossed} of 40 particles crossed the cyclic side")
ok = worst < 1e-9 and crossed > 5 and len(times) >= 5
print(f"CHECK the particles' volume mapped in full at every write (1e-9) and particles crossed {'PASS' if ok else 'FAIL'}")
sys.exit(0 if ok else 1)
PY
}

make_case "$work/channel"
( cd "$work/channel" && "$solver" > log.voidPimpleFoam 2>&1 ) || { tail -30 "$work/channel/log.voidPimpleFoam"; exit 1; }
log=$work/channel/log.voidPimpleFoam
check "the solver took the cyclic pairs (left and right: 80 face pairs)" \
    "$(grep -c 'cyclic patches left and right: 80 face pairs' "$log" | awk '{print ($1 == 1)}')"
check_mapped "$work/channel"
# column 9: |residual| / the largest term of the balance, each step (tutorials/tools/foamcase.py)
resid=$(awk '!/^#/ && NF >= 9 {r = $9 < 0 ? -$9 : $9; if (r > m) m = r} END {print m + 0}' "$work/channel/postProcessing/momentumBalance.dat")
check "the gas momentum balance within 1 % at every step (largest relative residual $resid)" \
    "$(awk -v r="$resid" 'BEGIN {print (r < 0.01)}')"

# In parallel (issue 23): the same channel on 2 ranks cut across its height (each rank holds both
# cyclic sides; the cell interpolation, as -parallel takes), the same checks on the reconstructed
# case; cut across the cyclic direction it is refused with a message naming the cut.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
decompose() {   # decompose <case> <n>
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n %s; delta 0.001; }\n' "$2" > "$1/system/decomposeParDict"
    ( cd "$1" && decomposePar -force > log.decomposePar 2>&1 ) || { tail -20 "$1/log.decomposePar"; exit 1; }
}
make_case "$work/parallel"
sed -i 's/^interpolation .*/interpolation cell;/' "$work/parallel/constant/couplingProperties"
decompose "$work/parallel" "(1 1 2)"
( cd "$work/parallel" && mpirun -np 2 "$solver" -parallel > log.voidPimpleFoam 2>&1 && reconstructPar > log.reconstructPar 2>&1 ) \
    || { tail -30 "$work/parallel/log.voidPimpleFoam"; exit 1; }
check "2 ranks: the solver took the cyclic pairs on each rank" \
    "$(grep -c 'cyclic patches left and right: 40 face pairs' "$work/parallel/log.voidPimpleFoam" | awk '{print ($1 == 1)}')"
check_mapped "$work/parallel" || fail=1
resid=$(awk '!/^#/ && NF >= 9 {r = $9 < 0 ? -$9 : $9; if (r > m) m = r} END {print m + 0}' "$work/parallel/postProcessing/momentumBalance.dat")
check "2 ranks: the gas momentum balance within 1 % at every step (largest relative residual $resid)" \
    "$(awk -v r="$resid" 'BEGIN {print (r < 0.01)}')"
make_case "$work/across"
sed -i 's/^interpolation .*/interpolation cell;/' "$work/across/constant/couplingProperties"
decompose "$work/across" "(2 1 1)"
( cd "$work/across" && timeout 120 mpirun -np 2 "$solver" -parallel > log 2>&1 ); rc=$?
check "2 ranks cut across the cyclic direction: stops (exit $rc) naming the cut and what to change" \
    "$( [ $rc != 0 ] && [ $rc != 124 ] && grep -q "the decomposition cuts across a cyclic direction" "$work/across/log" && echo 1)"

# mismatches: particles periodic without cyclic patches, and cyclic patches without periodic particles
make_case "$work/mismatch"
sed -i 's/periodic (true false false);/periodic (false false false);/' "$work/mismatch/constant/demProperties"
( cd "$work/mismatch" && "$solver" > log 2>&1 ); rc=$?
check "cyclic mesh, particles not periodic: exit 1, demProperties:line and key 'periodic'" \
    "$( [ $rc = 1 ] && grep -qE "demProperties:[0-9]+: error: key 'periodic': the particles are not periodic in x" "$work/mismatch/log" && echo 1)"
sed -i 's/periodic (false false false);/periodic (true false false);/; s/max (0.01 0.01 0.1); periodic/max (0.011 0.01 0.1); periodic/' "$work/mismatch/constant/demProperties"
( cd "$work/mismatch" && "$solver" > log 2>&1 ); rc=$?
check "periodic sides that differ from the cyclic ones: exit 1, demProperties:line and key 'min'" \
    "$( [ $rc = 1 ] && grep -qE "demProperties:[0-9]+: error: key 'min': the particles' periodic side in x" "$work/mismatch/log" && echo 1)"
[ $fail = 0 ] && echo "coupled_cyclic: passed" || { echo "coupled_cyclic: FAILED"; exit 1; }
