#!/bin/bash
# The gas's turbulence (issue 21): single-phase turbulent flow in a periodic round pipe (D = 50 mm,
# 50 mm long, cyclic along x; an O-grid of 8 x 8 core and 4 x 8 x 8 outer cells across, 4 along),
# air (nu 1.5e-5 m^2/s, rho 1.205 kg/m^3), no particles, the mean velocity held by the driving
# gradient (constant/drivingGradient). kEpsilon with wall functions (constant/turbulenceProperties,
# 0/k, 0/epsilon, 0/nut), the first cells at y+ 30-70. The friction factor from the time mean of
# the gas's wall shear over the last 0.2 s, f = 8 tau_w / (rho U^2), against Colebrook's for a
# smooth pipe, 1/sqrt(f) = -2 log10(2.51 / (Re sqrt(f))) (the log law the wall functions are built
# on), within 5 %, at Re = 5e4 and 1e5 (Blasius, f = 0.316 Re^-0.25, printed beside it); the
# superficial velocity held (0.1 %). Measured while writing this: kEpsilon -3.7 % of Colebrook at
# 5e4 on this mesh and on 12 x 12 + 4 x 12 x 12 cells alike; kOmegaSST -6.4 % (not tested).
# Usage: check_turbulent_pipe.sh <voidPimpleFoam> <tutorials/settling>
solver=$1 src=$2
export WM_PROJECT_DIR=${OF_DEV_DIR:-/opt/of/OpenFOAM-v1912}
[ -f "$WM_PROJECT_DIR/etc/controlDict" ] || export WM_PROJECT_DIR=/usr/share/openfoam
work=$(mktemp -d)
[ -n "${KEEP:-}" ] && echo "work: $work" || trap 'rm -rf "$work"' EXIT

make_pipe() {   # dir U [m/s] endTime
    cp -r "$src" "$1"
    rm -rf "$1"/log.* "$1"/particles.* "$1"/postProcessing "$1"/[1-9]* "$1"/0.[0-9]* "$1"/*.png
    cd "$1" || exit 1
    /usr/bin/python3 - "$2" "$3" <<'PY'
import math, re, sys
U, end = float(sys.argv[1]), sys.argv[2]
R, L = 25.0, 50.0                      # [mm]
c, a = 0.5 * R / math.sqrt(2), R / math.sqrt(2)
square = [(-c, -c), (c, -c), (c, c), (-c, c)]
outer = [(-a, -a), (a, -a), (a, a), (-a, a)]
verts = [(x, y, z) for x in (0.0, L) for (y, z) in square + outer]
v = "\n".join(f"    ({x:g} {y:.9g} {z:.9g})" for x, y, z in verts)
N, M, NX = 8, 8, 4
blocks = f"""    hex (0 1 2 3 8 9 10 11) ({N} {N} {NX}) simpleGrading (1 1 1)
    hex (4 5 1 0 12 13 9 8) ({N} {M} {NX}) simpleGrading (1 1 1)
    hex (1 5 6 2 9 13 14 10) ({M} {N} {NX}) simpleGrading (1 1 1)
    hex (3 2 6 7 11 10 14 15) ({N} {M} {NX}) simpleGrading (1 1 1)
    hex (4 0 3 7 12 8 11 15) ({M} {N} {NX}) simpleGrading (1 1 1)"""
edges = "\n".join(f"    arc {p} {q} ({x:g} {y:g} {z:g})" for off, x in ((0, 0.0), (8, L))
                  for p, q, y, z in ((4 + off, 5 + off, 0, -R), (5 + off, 6 + off, R, 0),
                                     (6 + off, 7 + off, 0, R), (7 + off, 4 + off, -R, 0)))
open("system/blockMeshDict", "w").write(f"""FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
convertToMeters 0.001;
vertices
(
{v}
);
blocks
(
{blocks}
);
edges
(
{edges}
);
boundary
(
    walls {{ type wall; faces ( (4 5 13 12) (5 6 14 13) (6 7 15 14) (7 4 12 15) ); }}
    inlet  {{ type cyclic; neighbourPatch outlet; faces ( (0 1 2 3) (4 5 1 0) (1 5 6 2) (3 2 6 7) (4 0 3 7) ); }}
    outlet {{ type cyclic; neighbourPatch inlet; faces ( (8 9 10 11) (12 13 9 8) (9 13 14 10) (11 10 14 15) (12 8 11 15) ); }}
);
""")
D = 2 * R * 1e-3
k = 1.5 * (0.05 * U) ** 2
epsilon = 0.09 ** 0.75 * k ** 1.5 / (0.07 * D)
def field(name, cls, dim, internal, wall):
    open(f"0/{name}", "w").write(f"""FoamFile {{ version 2.0; format ascii; class {cls}; object {name}; }}
dimensions {dim};
internalField uniform {internal};
boundaryField {{ walls {{ {wall} }} inlet {{ type cyclic; }} outlet {{ type cyclic; }} }}
""")
field("U", "volVectorField", "[0 1 -1 0 0 0 0]", f"({U} 0 0)", "type noSlip;")
field("p", "volScalarField", "[0 2 -2 0 0 0 0]", "0", "type fixedFluxPressure;")
field("k", "volScalarField", "[0 2 -2 0 0 0 0]", f"{k:g}", f"type kqRWallFunction; value uniform {k:g};")
field("epsilon", "volScalarField", "[0 2 -3 0 0 0 0]", f"{epsilon:g}", f"type epsilonWallFunction; value uniform {epsilon:g};")
field("nut", "volScalarField", "[0 2 -1 0 0 0 0]", "0", "type nutkWallFunction; value uniform 0;")
open("constant/turbulenceProperties", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object turbulenceProperties; }
simulationType RAS;
RAS { RASModel kEpsilon; turbulence on; printCoeffs on; }
""")
open("constant/drivingGradient", "w").write(f"""FoamFile {{ version 2.0; format ascii; class dictionary; object drivingGradient; }}
Ubar ({U} 0 0);
""")
t = open("constant/transportProperties").read()
t = re.sub(r"nu\s+(\[[^]]*\])?\s*[0-9.eE+-]+;", "nu              [0 2 -1 0 0 0 0] 1.5e-5;", t)
t = re.sub(r"rho\s+(\[[^]]*\])?\s*[0-9.eE+-]+;", "rho             [1 -3 0 0 0 0 0] 1.205;", t)
open("constant/transportProperties", "w").write(t)
open("constant/g", "w").write("FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }\n"
                              "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 0);\n")
open("constant/demProperties", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object demProperties; }
timeStep       1e-5;
endTime        1;
domain { min (0 -0.025 -0.025); max (0.05 0.025 0.025); periodic (true false false); }
materials { glass { youngsModulus 1e7; poissonsRatio 0.3; density 2500; } }
contactModels { normal hertz; tangential history; }
interactions { default { restitution 0.5; friction 0.5; } }
""")
c = open("constant/couplingProperties").read()
c = re.sub(r"couplingInterval\s+\d+;", "couplingInterval 10;", c)
open("constant/couplingProperties", "w").write(c)
s = open("system/controlDict").read()
s = re.sub(r"^endTime .*", f"endTime         {end};", s, flags=re.M)
s = re.sub(r"^deltaT .*", "deltaT          1e-4;", s, flags=re.M)
s = re.sub(r"^writeInterval .*", f"writeInterval   {end};", s, flags=re.M)
open("system/controlDict", "w").write(s)
f = open("system/fvSchemes").read()
f = f.replace("div(alphaPhi,U) Gauss limitedLinearV 1;",
              "div(alphaPhi,U) Gauss limitedLinearV 1;\n    div(alphaPhi,k) bounded Gauss upwind;\n"
              "    div(alphaPhi,epsilon) bounded Gauss upwind;")
f = f.replace("interpolationSchemes { default linear; }", "interpolationSchemes { default linear; }\nwallDist { method meshWave; }")
open("system/fvSchemes", "w").write(f)
s = open("system/fvSolution").read()
s = s.replace('"(U|UFinal)"', '"(U|UFinal|k|kFinal|epsilon|epsilonFinal)"')
s = re.sub(r"nCorrectors\s+\d+;", "nCorrectors      3;", s)
open("system/fvSolution", "w").write(s)
PY
    blockMesh > log.blockMesh 2>&1 || { tail -20 log.blockMesh; exit 1; }
    cd - > /dev/null
}

for U in 15 30; do   # Re = U D / nu = 5e4, 1e5
    make_pipe "$work/U$U" $U 0.6
    ( cd "$work/U$U" && "$solver" > log.voidPimpleFoam 2>&1 ) || { tail -30 "$work/U$U/log.voidPimpleFoam"; exit 1; }
done
/usr/bin/python3 - "$work" <<'PY'
import sys, math, numpy as np
work = sys.argv[1]
D, L, nu, rho = 0.05, 0.05, 1.5e-5, 1.205
ok = True
for U in (15, 30):
    b = np.loadtxt(f"{work}/U{U}/postProcessing/drivingGradient.dat", comments="#")
    late = b[:, 0] > 0.4
    tau = -b[late, 8].mean() / (math.pi * D * L)          # the gas's wall shear [Pa]
    f = 8 * tau / (rho * U**2)
    Re = U * D / nu
    fc = 0.02
    for _ in range(50):
        fc = (-2 * math.log10(2.51 / (Re * math.sqrt(fc)))) ** -2
    fb = 0.316 * Re ** -0.25
    us = b[-1, 2]
    good = abs(f / fc - 1) < 0.05 and abs(us / U - 1) < 1e-3
    print(f"Re {Re:.3g}: f = {f:.5f} (tau_w {tau:.4g} Pa, gradient {b[late, 1].mean():.4g} Pa/m); Colebrook {fc:.5f} "
          f"({100 * (f / fc - 1):+.2f} %), Blasius {fb:.5f} ({100 * (f / fb - 1):+.2f} %); superficial velocity {us:.6g} m/s")
    print(f"CHECK turbulent pipe Re {Re:.0e}: friction factor within 5 % of Colebrook, velocity held 0.1 % "
          f"{'PASS' if good else 'FAIL'}")
    ok &= good
print("turbulent_pipe:", "passed" if ok else "FAILED")
sys.exit(0 if ok else 1)
PY
