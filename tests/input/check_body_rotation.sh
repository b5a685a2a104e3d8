#!/bin/bash
# A multisphere body's start orientation and angular velocity from demProperties (issue 26): one
# free tetrahedral clump (four spheres of 0.8 mm, massModel sphereSum) without gravity, far from
# the walls, started turned by 30 degrees about (1 1 0) and spinning at omega = (10, 20, 30) rad/s,
# by each insertion method: random (number 1, orientation { axis; angle; }), lattice (number 1,
# orientation as the same quaternion (w x y z)) and file (one line of 13 columns: x y z, v,
# the quaternion, omega). Checked against a reference computed here, independently of the code,
# from seed 004: the mass and inertia of the sphere sum (eq. 1-7: m_k, the centre of mass, the
# tensor sum of 2/5 m_k r_k^2 1 + m_k (|d_k|^2 1 - d_k d_k^T)), turned into space by the given
# rotation (Rodrigues):
#   1. the first snapshot (t = 0) holds the body's E_rot = 1/2 omega . I omega (eq. 8), to 1e-9;
#   2. its spheres sit where the rotation puts the template's centres about the centre of mass
#      (1e-12 m), and the body's angular velocity is omega (1e-9);
#   3. the free rotor keeps E_rot: the last snapshot's, after 2000 steps, to 1e-9 (no contact: the
#      clump turns in place), and demRun's last line reports it (to its 6 digits);
#   4. the three methods give the same state at t = 0.
# A bad orientation stops at its key: a quaternion of three numbers, and one of zero length.
# Usage: check_body_rotation.sh <demRun>
demRun=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
head_of() {   # the case without its insertion
cat <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object demProperties; }
timeStep       1e-6;
endTime        0.002;
writeInterval  0.001;
gravity        (0 0 0);
skin           0.3e-3;
domain { min (-0.02 -0.02 -0.02); max (0.02 0.02 0.02); }
materials { glass { youngsModulus 5e6; poissonsRatio 0.45; density 2500; } }
contactModels { normal hertz; tangential history; }
interactions { default { restitution 0.5; friction 0.5; } }
walls { box { type box; min (-0.02 -0.02 -0.02); max (0.02 0.02 0.02); material glass; } }
multisphere
{
    tetra
    {
        material  glass;
        centres   ((0 0 0) (1.2e-3 0 0) (0.6e-3 1.04e-3 0) (0.6e-3 0.35e-3 0.98e-3));
        radii     (0.8e-3 0.8e-3 0.8e-3 0.8e-3);
        massModel sphereSum;
    }
}
EOD
}
# 30 degrees about (1 1 0)/sqrt 2: w = cos 15, (x, y) = sin 15 / sqrt 2
Q="0.96592582628906831 0.18301270189221933 0.18301270189221933 0"
mk() { mkdir -p "$work/$1/constant"; { head_of; cat; } > "$work/$1/constant/demProperties"; }
mk random <<EOD
insertion { one { region { type box; min (-0.005 -0.005 -0.005); max (0.005 0.005 0.005); } number 1; body tetra;
                  orientation { axis (1 1 0); angle 30; } angularVelocity (10 20 30); } }
EOD
mk lattice <<EOD
insertion { one { method lattice; region { type box; min (-0.005 -0.005 -0.005); max (0.005 0.005 0.005); }
                  spacing 0.01; number 1; body tetra; orientation ($Q); angularVelocity (10 20 30); } }
EOD
mk file <<EOD
insertion { one { method file; file body.dat; body tetra; } }
EOD
echo "0.001 -0.002 0.003  0 0 0  $Q  10 20 30" > "$work/file/constant/body.dat"
fail=0
for m in random lattice file; do
    "$demRun" "$work/$m" > "$work/$m/log" 2>&1 || { echo "CHECK body rotation $m: runs FAIL"; tail -3 "$work/$m/log"; fail=1; }
done
/usr/bin/python3 - "$work" "$Q" <<'PY' || fail=1
import sys, re, h5py, numpy as np
work, q = sys.argv[1], np.array([float(v) for v in sys.argv[2].split()])
c = np.array([(0, 0, 0), (1.2e-3, 0, 0), (0.6e-3, 1.04e-3, 0), (0.6e-3, 0.35e-3, 0.98e-3)])
r, rho = 0.8e-3, 2500.0
m = rho * 4.0 / 3.0 * np.pi * r ** 3                       # eq. 1: each sphere's mass
com = c.mean(axis=0)                                       # eq. 2-3 (equal masses)
d = c - com
I = sum(0.4 * m * r * r * np.eye(3) + m * (dk @ dk * np.eye(3) - np.outer(dk, dk)) for dk in d)   # eq. 6-7
w, x, y, z = q / np.linalg.norm(q)
R = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
              [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
              [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
omega = np.array([10.0, 20.0, 30.0])
E = 0.5 * omega @ (R @ I @ R.T) @ omega                    # eq. 8 in space
ok, states = True, {}
def check(what, good):
    global ok
    print(f"CHECK body rotation {what} {'PASS' if good else 'FAIL'}")
    ok &= bool(good)
for meth in ("random", "lattice", "file"):
    try:
        f = h5py.File(f"{work}/{meth}/particles.h5", "r")
    except OSError:
        check(f"{meth}: snapshots written", False)
        continue
    snaps = sorted(f["snapshots"].values(), key=lambda g: g.attrs["time"])
    g0 = snaps[0]
    e0 = float(g0["bodies/rotational_energy"][0])
    check(f"{meth}: E_rot at t = 0 {e0:.9g} J against seed 004 eq. 8 {E:.9g} J (1e-9)", abs(e0 - E) <= 1e-9 * E)
    X = g0["bodies/position"][0]
    placed = np.sort((X + d @ R.T).round(15), axis=0)
    got = np.sort(g0["position"][...].round(15), axis=0)
    w0 = g0["bodies/omega"][0]
    check(f"{meth}: the spheres where the rotation puts them (worst {np.abs(placed - got).max():.2g} m, 1e-12) "
          f"and omega {w0}", np.abs(placed - got).max() <= 1e-12 and np.abs(w0 - omega).max() <= 1e-9 * 30)
    e1 = float(snaps[-1]["bodies/rotational_energy"][0])
    check(f"{meth}: E_rot at t = {snaps[-1].attrs['time']:g} s {e1:.9g} J (1e-9 of eq. 8)", abs(e1 - E) <= 1e-9 * E)
    mm = re.search(r"rotational kinetic energy (\S+) J", open(f"{work}/{meth}/log").read())
    e_log = float(mm.group(1)) if mm else float("nan")
    check(f"{meth}: demRun's last line reports it, {e_log:g} J (1e-6: its 6 digits)", abs(e_log - E) <= 1e-6 * E)
    states[meth] = (float(g0["bodies/rotational_energy"][0]), g0["bodies/orientation"][0], w0)
    f.close()
if len(states) == 3:
    a, b, cc = states["random"], states["lattice"], states["file"]
    check("the three methods start alike (E_rot, orientation, omega)",
          all(abs(s[0] - a[0]) <= 1e-12 * a[0] and np.abs(s[1] - a[1]).max() <= 1e-12 and np.abs(s[2] - a[2]).max() <= 1e-9
              for s in (b, cc)))
sys.exit(0 if ok else 1)
PY
for bad in "orientation (1 0 0);|key 'orientation'" "orientation (0 0 0 0);|key 'orientation'"; do
    IFS='|' read -r edit want <<< "$bad"
    mkdir -p "$work/bad/constant"
    sed "s/orientation (\$Q);/$edit/; s/orientation ([0-9. ]*);/$edit/" "$work/lattice/constant/demProperties" > "$work/bad/constant/demProperties"
    if ! "$demRun" "$work/bad" > "$work/bad/log" 2>&1 && grep -Eq "demProperties:[0-9]+: error: $want" "$work/bad/log"; then
        echo "CHECK body rotation bad input '$edit' stops at its key PASS"
    else
        echo "CHECK body rotation bad input '$edit' stops at its key FAIL"; tail -2 "$work/bad/log"; fail=1
    fi
done
exit $fail
