#!/bin/bash
# Prescribed particles (insertion's prescribedVelocity: a piston) log and write only finite numbers
# (issue 26): a piston of 3 mm on the floor driven sideways at 0.2 m/s through a bed of 150 beads
# of 2 mm for 12 mm, with every rolling model (none, cdt, epsd). A prescribed particle has no inverse mass or inertia
# (0): the kinetic energy must leave it out (it was 0.5 / 0 x |omega|^2 = inf x 0 = -nan), and
# epsd's reduced rolling inertia must take the bead's where one partner's is infinite (it was
# inf / inf: a NaN torque, reported as a particle moving more than half its radius at -nan m/s).
# Each run must end without an error; its log must hold no nan or inf; every number in its
# snapshots must be finite; the piston must be where its set velocity puts it (to 1e-12 m), still
# without spin; and the log must say that the kinetic energy leaves the piston out.
# Usage: check_prescribed.sh <demRun>
demRun=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
for rolling in none cdt epsd; do
    d=$work/$rolling
    mkdir -p "$d/constant"
    cat > "$d/constant/demProperties" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object demProperties; }
timeStep       1e-5;
endTime        0.06;
writeInterval  0.02;
gravity        (0 0 -9.81);
skin           0.3e-3;
domain { min (-0.01 -0.01 0); max (0.01 0.01 0.04); }
materials { glass { youngsModulus 5e6; poissonsRatio 0.45; density 2500; } }
contactModels { normal hertz; tangential history; rolling $rolling; }
interactions { default { restitution 0.5; friction 0.5; rollingFriction 0.1; } }
walls { box { type box; min (-0.01 -0.01 0); max (0.01 0.01 0.04); material glass; } }
insertion
{
    piston { region { type box; min (-0.0075 -0.0015 0); max (-0.0045 0.0015 0.003); } number 1; material glass;
             diameter { distribution constant; value 3e-3; } prescribedVelocity (0.2 0 0); }
    bed    { region { type box; min (-0.01 -0.01 0); max (0.01 0.01 0.02); } number 150; material glass;
             diameter { distribution constant; value 2e-3; } }
}
EOD
    [ "$rolling" = none ] && sed -i 's/ rollingFriction 0.1;//' "$d/constant/demProperties"
    if ! "$demRun" "$d" > "$d/log" 2>&1; then
        echo "CHECK prescribed rolling $rolling: the run ends without an error FAIL"; tail -3 "$d/log"; fail=1; continue
    fi
    if grep -Eiq '(^|[^a-z])(-?nan|-?inf)([^a-z]|$)' "$d/log"; then
        echo "CHECK prescribed rolling $rolling: the log holds only finite numbers FAIL"
        grep -Ei '(^|[^a-z])(-?nan|-?inf)([^a-z]|$)' "$d/log" | head -3; fail=1
    else
        echo "CHECK prescribed rolling $rolling: the log holds only finite numbers PASS"
    fi
    grep -q "kinetic energy: the 1 prescribed particles" "$d/log" &&
        echo "CHECK prescribed rolling $rolling: the log says the kinetic energy leaves the piston out PASS" ||
        { echo "CHECK prescribed rolling $rolling: the log says the kinetic energy leaves the piston out FAIL"; fail=1; }
    /usr/bin/python3 - "$d/particles.h5" "$rolling" <<'PY' || fail=1
import sys, h5py, numpy as np
ok = True
with h5py.File(sys.argv[1], "r") as f:
    snaps = [f["snapshots"][k] for k in sorted(f["snapshots"])]
    finite = all(np.all(np.isfinite(s[k][...])) for s in snaps for k in s
                 if isinstance(s[k], h5py.Dataset) and s[k].dtype.kind == "f")
    last = snaps[-1]
    i = int(np.flatnonzero(last["prescribed"][...])[0])
    first = snaps[0]
    j = int(np.flatnonzero(first["id"][...] == last["id"][i])[0])
    dz = last["position"][i, 0] - first["position"][j, 0]
    want = 0.2 * (last.attrs["time"] - first.attrs["time"])
    placed = abs(dz - want) <= 1e-12 and np.all(last["omega"][i] == 0.0)
for what, good in (("every number in the snapshots is finite", finite),
                   (f"the piston moved {dz:.9g} m as set ({want:.9g} m), without spin", placed)):
    print(f"CHECK prescribed rolling {sys.argv[2]}: {what} {'PASS' if good else 'FAIL'}")
    ok &= bool(good)
sys.exit(0 if ok else 1)
PY
done
exit $fail
