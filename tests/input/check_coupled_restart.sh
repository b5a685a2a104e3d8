#!/bin/bash
# A coupled run continued from a write time (startFrom latestTime: the fields of that time and
# the particle snapshot with its contact history) is the uninterrupted run, bit for bit. The case
# is the short variant of tutorials/fluidisedBed (5,000 beads falling from their lattice, landing
# and packing), run to 0.1 s straight, and to 0.05 s, then on to 0.1 s. Compared after the
# restart, for exact equality: every step's momentum-balance terms (pressure drop, particle force,
# weight, ...; 250 fluid steps, 17 digits; the time column to 1e-12 s, see below), every particle's position, velocity, angular velocity and force in the
# snapshots at 0.1 s, and the fluid's U, p, phi and alpha written at 0.1 s (17 digits).
# That the comparison can see round-off: a third run continues from the same snapshot with one
# particle's velocity changed in its last bit (1e-16 relative); the bed amplifies that to more
# than 1e-9 m/s by 0.1 s (before the continuation was made exact, the restart's own round-off
# grew from 1e-15 to 3 % of the forces between 0.05 and 0.1 s).
# Usage: check_coupled_restart.sh <voidPimpleFoam> <tutorials/fluidisedBed/Allrun>
set -uo pipefail
solver=$1 allrun=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export WM_PROJECT_DIR=${OF_DEV_DIR:-/opt/of/OpenFOAM-v1912}
[ -f "$WM_PROJECT_DIR/etc/controlDict" ] || export WM_PROJECT_DIR=/usr/share/openfoam
"$allrun" -short-case "$work/base" || exit 1
sed -i -e 's/^endTime .*/endTime         0.1;/' -e 's/^writeInterval .*/writeInterval   0.05;/' "$work/base/system/controlDict"
blockMesh -case "$work/base" > "$work/blockMesh.log" 2>&1 || { tail "$work/blockMesh.log"; exit 1; }
cp -r "$work/base" "$work/straight"
cp -r "$work/base" "$work/continued"
"$solver" -case "$work/straight" > "$work/straight.log" 2>&1 || { tail -20 "$work/straight.log"; exit 1; }
sed -i -e 's/^endTime .*/endTime         0.05;/' "$work/continued/system/controlDict"
"$solver" -case "$work/continued" > "$work/first.log" 2>&1 || { tail -20 "$work/first.log"; exit 1; }
sed -i -e 's/^endTime .*/endTime         0.1;/' "$work/continued/system/controlDict"
cp -r "$work/continued" "$work/perturbed"
"$solver" -case "$work/continued" > "$work/second.log" 2>&1 || { tail -20 "$work/second.log"; exit 1; }
grep -m1 "coupling: continuing from" "$work/second.log" || { echo "FAIL: the second run did not continue from the snapshot"; exit 1; }
/usr/bin/python3 - "$work/perturbed" <<'PY' || exit 1
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1] + "/particles.h5", "r+") as h:
    g = max(h["snapshots"].values(), key=lambda g: g.attrs["time"])
    v = g["velocity"][...]
    i = int(np.argmax(np.abs(v[:, 2])))
    v[i, 2] = np.nextafter(v[i, 2], np.inf)
    g["velocity"][...] = v
    print(f"perturbed: particle {g['id'][i]} at t = {g.attrs['time']:.17g} s, velocity z + 1 ulp")
PY
"$solver" -case "$work/perturbed" > "$work/perturbed.log" 2>&1 || { tail -20 "$work/perturbed.log"; exit 1; }
/usr/bin/python3 - "$work/straight" "$work/continued" "$work/perturbed" <<'PY'
import sys
import h5py
import numpy as np
a, b, c = sys.argv[1], sys.argv[2], sys.argv[3]
failed = False
def check(name, measured, tol):
    global failed
    ok = measured <= tol
    failed |= not ok
    print(f"CHECK {name} measured={measured:.3e} tolerance={tol:g} {'PASS' if ok else 'FAIL'}")
def check_at_least(name, measured, minimum):
    global failed
    ok = measured >= minimum
    failed |= not ok
    print(f"CHECK {name} measured={measured:.3e} minimum={minimum:g} {'PASS' if ok else 'FAIL'}")
def rows_after(case, t0=0.05):
    out = []
    for line in open(case + "/postProcessing/momentumBalance.dat"):
        if line.startswith("#") or not line.strip():
            continue
        if float(line.split()[0]) > t0 + 1e-9:
            out.append(line.split())
    return out
A, B = rows_after(a), rows_after(b)
check("momentum_balance_rows_after_restart_missing", abs(len(A) - len(B)) + (len(A) < 200) * 1000, 0)
# the time column is OpenFOAM's clock: the straight run's accumulates deltaT (0.050199999999999807),
# the continued one starts from the time name 0.05; the fluid's equations do not use it
check("momentum_balance_times_s", max(abs(float(x[0]) - float(y[0])) for x, y in zip(A, B)), 1e-12)
check("momentum_balance_lines_whose_terms_differ", sum(x[1:] != y[1:] for x, y in zip(A, B)), 0)
def last(case):
    with h5py.File(case + "/particles.h5", "r") as h:
        g = max(h["snapshots"].values(), key=lambda g: g.attrs["time"])
        i = np.argsort(g["id"][:])
        return (g.attrs["time"], len(h["snapshots"]),
                {k: g[k][:][i] for k in ("position", "velocity", "omega", "force")})
ta, na, fa = last(a)
tb, nb, fb = last(b)
tc, nc, fc = last(c)
check("snapshots", abs(na - nb), 0)
check("final_time_s", abs(ta - tb), 0)
check("final_time_is_0.1_s", abs(ta - 0.1), 1e-9)
for k in fa:
    check(f"{k}_differs_bitwise_in_particles", int(np.sum(fa[k] != fb[k])), 0)
def field(case, name, t="0.1"):
    return open(f"{case}/{t}/{name}").read()
for name in ("U", "p", "phi", "alpha"):
    check(f"field_{name}_at_0.1_s_text_differs", int(field(a, name) != field(b, name)), 0)
# the control: one ulp at 0.05 s shows at 0.1 s (the comparison above can see round-off)
dv = np.abs(fa["velocity"] - fc["velocity"]).max()
print(f"control: one ulp of one particle's velocity at 0.05 s -> max |dv| {dv:.3e} m/s at 0.1 s")
check_at_least("control_velocity_difference_m_per_s", dv, 1e-9)
sys.exit(1 if failed else 0)
PY
