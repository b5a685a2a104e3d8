#!/bin/bash
# The driving gradient of a periodic pipe (issue 21): a square duct a = 20 mm, 40 mm long and
# cyclic along x, 8 x 10 x 10 cells, gas rho 10 kg/m^3, nu 1e-3 m^2/s, the mean superficial
# velocity held at 0.5 m/s (constant/drivingGradient; Re = 10, laminar). Checks:
#   1. gas alone: the superficial velocity reaches 0.5 m/s (0.1 %) and the gradient the square
#      duct's Poiseuille value, f Re_Dh = 56.91 (Shah & London 1978): -dp/dx = 28.454 mu U / a^2
#      = 355.7 Pa/m: with 20 cells across within 1.5 %, converging at second order (the error of 10
#      cells 3 to 5 times that of 20), the Richardson extrapolation of the two within 0.3 %;
#   2. with 600 spheres (d = 1.5 mm, rho 8000) settled into a layer on the floor and dragged by the gas:
#      the pipe's balance in the time mean over 0.3-0.6 s, rho_f G V = the gas's wall shear + the
#      particles' wall forces, within 1 % (the particles feel the driving gradient too:
#      drivingGradient.H); the gas's balance along the flow within 1 % at every step after the
#      first 20 ms (the start, a plug flow against no-slip walls, leaves 5 % in the first steps);
#   3. a continued run starts from the gradient written at its start time;
#   4. with `average interstitial` (as Lethe's flow control) and the 600 spheres: the fluid-volume
#      mean of U, int(alpha U) dV / int(alpha) dV, held at 0.5 m/s (0.1 %, mean over 0.3-0.6 s), and
#      the superficial mean = 0.5 m/s x (1 - V_spheres / V) (0.1 %: the void fraction holds the
#      spheres' volume); a bad `average` is refused with file and key.
# Usage: check_coupled_drive.sh <voidPimpleFoam> <tutorials/settling>
solver=$1 src=$2
export WM_PROJECT_DIR=${OF_DEV_DIR:-/opt/of/OpenFOAM-v1912}
[ -f "$WM_PROJECT_DIR/etc/controlDict" ] || export WM_PROJECT_DIR=/usr/share/openfoam
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

make_case() {   # dir particles endTime [cells across, default 10] [average, default superficial]
    cp -r "$src" "$1"
    rm -rf "$1"/log.* "$1"/particles.* "$1"/postProcessing "$1"/[1-9]* "$1"/0.[0-9]*
    cd "$1" || exit 1
    /usr/bin/python3 - "$2" "$3" "${4:-10}" "${5:-superficial}" <<'PY'
import re, sys
n, end, across, average = int(sys.argv[1]), sys.argv[2], int(sys.argv[3]), sys.argv[4]
open("system/blockMeshDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
convertToMeters 0.001;
vertices ( (0 -10 -10) (40 -10 -10) (40 10 -10) (0 10 -10) (0 -10 10) (40 -10 10) (40 10 10) (0 10 10) );
blocks ( hex (0 1 2 3 4 5 6 7) (8 ACROSS ACROSS) simpleGrading (1 1 1) );
boundary
(
    walls { type wall; faces ( (0 3 2 1) (4 5 6 7) (0 1 5 4) (2 3 7 6) ); }
    inlet  { type cyclic; neighbourPatch outlet; faces ( (0 4 7 3) ); }
    outlet { type cyclic; neighbourPatch inlet;  faces ( (1 2 6 5) ); }
);
""".replace("ACROSS", str(across)))
for f, wall in (("0/U", "walls { type noSlip; }"), ("0/p", "walls { type fixedFluxPressure; }")):
    t = open(f).read().replace(wall, wall + " inlet { type cyclic; } outlet { type cyclic; }")
    if f == "0/U": t = t.replace("internalField   uniform (0 0 0);", "internalField   uniform (0.5 0 0);")
    open(f, "w").write(t)
t = open("constant/transportProperties").read()
t = re.sub(r"nu\s+(\[[^]]*\])?\s*[0-9.eE+-]+;", "nu              [0 2 -1 0 0 0 0] 1e-3;", t)
open("constant/transportProperties", "w").write(t)
open("constant/drivingGradient", "w").write(f"""FoamFile {{ version 2.0; format ascii; class dictionary; object drivingGradient; }}
Ubar        (0.5 0 0);   // [m/s] the mean velocity of the gas, along x
average     {average};
relaxation  1;
""")
open("constant/demProperties", "w").write(f"""FoamFile {{ version 2.0; format ascii; class dictionary; object demProperties; }}
timeStep       2e-5;
endTime        1;
gravity        (0 0 -9.81);
maxExpectedVelocity 2;
domain {{ min (0 -0.01 -0.01); max (0.04 0.01 0.01); periodic (true false false); }}
materials {{ sphere {{ youngsModulus 1e6; poissonsRatio 0.3; density 8000; }} }}
contactModels {{ normal hertz; tangential history; }}
interactions {{ default {{ restitution 0.5; friction 0.5; }} }}
walls
{{
    floor {{ type plane; point (0 0 -0.01); normal (0 0 1); material sphere; }}
    lid   {{ type plane; point (0 0 0.01); normal (0 0 -1); material sphere; }}
    front {{ type plane; point (0 -0.01 0); normal (0 1 0); material sphere; }}
    back  {{ type plane; point (0 0.01 0); normal (0 -1 0); material sphere; }}
}}
""" + (f"""insertion
{{
    beads
    {{
        region   {{ type box; min (0 -0.009 -0.009); max (0.04 0.009 0); }}
        number   {n};
        material sphere;
        diameter {{ distribution constant; value 1.5e-3; }}
    }}
}}
""" if n else ""))
c = open("constant/couplingProperties").read()
c = re.sub(r"couplingInterval\s+\d+;", "couplingInterval 50;", c)
c = re.sub(r"model\s+centre;", "model     divided;", c)
open("constant/couplingProperties", "w").write(c)
s = open("system/controlDict").read()
s = re.sub(r"^endTime .*", f"endTime         {end};", s, flags=re.M)
s = re.sub(r"^deltaT .*", "deltaT          1e-3;", s, flags=re.M)
s = re.sub(r"^writeInterval .*", "writeInterval   0.1;", s, flags=re.M)
s = re.sub(r"^writePrecision .*", "writePrecision  17;", s, flags=re.M)
open("system/controlDict", "w").write(s)
s = open("system/fvSolution").read()   # five correctors, as for the beds (README: two leave up to 14 %)
open("system/fvSolution", "w").write(re.sub(r"nCorrectors\s+\d+;", "nCorrectors      5;", s))
PY
    blockMesh > log.blockMesh 2>&1 || { tail -20 log.blockMesh; exit 1; }
    cd - > /dev/null
}
run() { ( cd "$1" && "$solver" > log.voidPimpleFoam 2>&1 ) || { tail -30 "$1/log.voidPimpleFoam"; exit 1; }; }

make_case "$work/gas" 0 0.6
run "$work/gas"
make_case "$work/gas20" 0 0.6 20
run "$work/gas20"
make_case "$work/beads" 600 0.6
run "$work/beads"
# 3: continued from 0.3 s
make_case "$work/split" 600 0.3
run "$work/split"
sed -i 's/^endTime .*/endTime         0.6;/' "$work/split/system/controlDict"
run "$work/split"
# 4: the interstitial mean held, and a bad `average`
make_case "$work/interstitial" 600 0.6 10 interstitial
run "$work/interstitial"
make_case "$work/badAverage" 0 0.01 10 sideways
if (cd "$work/badAverage" && "$solver" > log.voidPimpleFoam 2>&1); then
    echo "CHECK a bad 'average' is refused                                                         FAIL (the run went on)"
    exit 1
fi
if grep -q "constant/drivingGradient" "$work/badAverage/log.voidPimpleFoam" && grep -q "key 'average': sideways" "$work/badAverage/log.voidPimpleFoam"; then
    echo "CHECK a bad 'average' is refused with file and key                                        PASS"
else
    echo "CHECK a bad 'average' is refused with file and key                                        FAIL:"
    tail -12 "$work/badAverage/log.voidPimpleFoam"
    exit 1
fi

/usr/bin/python3 - "$work" <<'PY'
import sys, numpy as np
work = sys.argv[1]
ok = True
def check(what, good):
    global ok
    print(f"CHECK {what:82s} {'PASS' if good else 'FAIL'}")
    ok &= bool(good)
def table(case):
    return np.loadtxt(f"{work}/{case}/postProcessing/drivingGradient.dat", comments="#")
g, g20 = table("gas"), table("gas20")
mu, U, a = 10 * 1e-3, 0.5, 0.02
closed = 28.454 * mu * U / a**2
extrapolated = g20[-1, 1] + (g20[-1, 1] - g[-1, 1]) / 3   # Richardson, second order
print(f"gas alone at 0.6 s: superficial velocity {g[-1, 2]:.6g} m/s; gradient {g[-1, 1]:.5g} Pa/m (10 cells across, "
      f"{100 * (g[-1, 1] / closed - 1):+.2f} %), {g20[-1, 1]:.5g} Pa/m (20 cells, {100 * (g20[-1, 1] / closed - 1):+.2f} %), "
      f"extrapolated {extrapolated:.5g} Pa/m ({100 * (extrapolated / closed - 1):+.3f} %); Poiseuille in a square duct "
      f"{closed:.5g} Pa/m")
check("gas alone: the superficial velocity held at 0.5 m/s (0.1 %)", abs(g[-1, 2] / 0.5 - 1) < 1e-3 and abs(g20[-1, 2] / 0.5 - 1) < 1e-3)
check("gas alone: 20 cells across within 1.5 % of Poiseuille (f Re = 56.91), second order: 10 cells' error / 20's in [3, 5]",
      abs(g20[-1, 1] / closed - 1) < 0.015 and 3 < (g[-1, 1] - closed) / (g20[-1, 1] - closed) < 5)
check("gas alone: the Richardson extrapolation of the two within 0.3 % of Poiseuille", abs(extrapolated / closed - 1) < 0.003)
b = table("beads")
w = b[:, 0] >= 0.3
drive, walls, pwalls = b[w, 3].mean(), b[w, 8].mean(), b[w, 12].mean()
imbalance = (drive + walls + pwalls) / drive
print(f"with 600 beads, means over 0.3-0.6 s: drive rho_f G V {drive:.5g} N = gas wall shear {-walls:.5g} N + "
      f"particles' wall forces {-pwalls:.5g} N; imbalance {100 * imbalance:+.3f} %; gradient {b[w, 1].mean():.5g} Pa/m")
check("with beads: drive = gas wall shear + particles' wall forces in the time mean, 1 %", abs(imbalance) < 0.01)
check("with beads: the particles carry part of it (their wall forces > 1 % of the drive)", -pwalls > 0.01 * drive)
scale = np.maximum(np.maximum(np.abs(b[:, 4]), np.abs(b[:, 7])), np.abs(b[:, 8]))   # drive, particles, walls
gasres = np.abs(b[:, 11]) / np.maximum(scale, 1e-30)
late = b[:, 0] > 0.02
print(f"the gas's balance along the flow: largest residual {gasres.max():.2g} of its largest term in the first "
      f"20 ms (a plug flow started against no-slip walls), {gasres[late].max():.2g} after")
check("with beads: the gas's balance along the flow at every step after the first 20 ms, 1 %", gasres[late].max() < 0.01)
s = table("split")
at = lambda t, x: t[np.argmin(np.abs(t[:, 0] - x))]
first = s[s[:, 0] > 0.3 + 1e-9][0]
straight = b[b[:, 0] > 0.3 + 1e-9][0]
print(f"continued at 0.3 s: first step's gradient {first[1]:.17g} Pa/m, the straight run's {straight[1]:.17g} Pa/m")
check("a continued run goes on from the written gradient (first step as the straight run's, 1e-12)",
      abs(first[1] - straight[1]) <= 1e-12 * abs(straight[1]))
i = table("interstitial")
w = i[:, 0] >= 0.3
held, sup = i[w, 14].mean(), i[w, 2].mean()
alpha_mean = 1 - 600 * np.pi / 6 * 1.5e-3**3 / (0.04 * 0.02 * 0.02)
print(f"average interstitial, means over 0.3-0.6 s: interstitial {held:.6g} m/s, superficial {sup:.6g} m/s, "
      f"0.5 (1 - V_spheres / V) = {0.5 * alpha_mean:.6g} m/s")
check("interstitial: the fluid-volume mean of U held at 0.5 m/s (0.1 %)", abs(held / 0.5 - 1) < 1e-3)
check("interstitial: the superficial mean = 0.5 m/s (1 - V_spheres / V) (0.1 %)", abs(sup / (0.5 * alpha_mean) - 1) < 1e-3)
print("coupled_drive:", "passed" if ok else "FAILED")
sys.exit(0 if ok else 1)
PY
