#!/bin/bash
# Bad input must stop demRun with exit status 1 and a message that names the file, the line
# and the key; never a crash (signal) and never a silent run. Usage: check_errors.sh <demRun>
demRun=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0

# name | sed expression applied to base.demProperties | text the error must contain (grep -E)
cases=(
  "missing_semicolon|s/^timeStep       1e-5;/timeStep       1e-5/|demProperties:3: error: .*timeStep"
  "unknown_key|s/^skin /skn /|demProperties:7: error: unknown key 'skn'.*did you mean 'skin'"
  "negative_diameter|s/value 2e-3;/value -2e-3;/|demProperties:20: error: key 'value'.*-2e-3"
  "timestep_10x|s/^timeStep       1e-5;/timeStep       1e-4;/|demProperties:3: error: key 'timeStep'.*largest safe step"
  "unknown_model|s/normal hertz;/normal herz;/|demProperties:10: error: key 'normal'.*hertz"
  "missing_material|s/material glass;$/material steel;/|demProperties:19: error: key 'material'.*steel"
  "bad_vector|s/gravity        (0 0 -9.81);/gravity        (0 -9.81);/|demProperties:6: error: key 'gravity'"
  "unbalanced_brace|s/^domain { min/domain { { min/|demProperties:8: error"
  "cdtJkr_without_adhesion|s/tangential history; }/tangential history; rolling cdtJkr; }/|demProperties:11: error: .*cdtJkr rolling model needs 'workOfAdhesion'"
  "cdtJkr_zero_adhesion|s/tangential history; }/tangential history; rolling cdtJkr; }/;s/friction 0.5; }/friction 0.5; workOfAdhesion 0; adhesionHysteresis 1; }/|demProperties:11: error: key 'workOfAdhesion'.*positive"
  "edinburgh_kappa21|s/normal hertz;/normal edinburgh;/;s/friction 0.5; }/friction 0.5; unloadingRatio 1; }/|demProperties:11: error: key 'unloadingRatio'.*exceed 1"
  "edinburgh_damping_word|s/normal hertz;/normal edinburgh; edinburghDamping seed;/;s/friction 0.5; }/friction 0.5; unloadingRatio 2; }/|demProperties:10: error: key 'edinburghDamping'.*seedEq8"
  "rigid_with_modulus|s/glass { youngsModulus 5e6;/glass { rigid true; youngsModulus 5e6;/|demProperties:9: error: key 'youngsModulus'.*rigid"
  "rigid_particles|s/glass { youngsModulus 5e6; poissonsRatio 0.45; density 2500; }/glass { youngsModulus 5e6; poissonsRatio 0.45; density 2500; } steel { rigid true; }/;s/material glass;$/material steel;/|demProperties:19: error: key 'material'.*rigid: only walls"
  "cylinder_velocity|s/walls { box { type box;.*/walls { drum { type cylinder; axis z; centre (0 0); radius 0.01; material glass; velocity (1 0 0); } }/|demProperties:12: error: key 'velocity'.*angularVelocity"
  "prescribed_and_velocity|s/number   200;/number 200; velocity (0 0 1); prescribedVelocity (0 0 1);/|demProperties:18: error: key 'prescribedVelocity'.*not both"
  "periodic_huge_velocity|s/^domain { min (-0.01 -0.01 0); max (0.01 0.01 0.04); }/domain { min (-0.01 -0.01 0); max (0.01 0.01 0.04); periodic (true false false); }/;s/^walls.*/walls { floor { type plane; point (0 0 0); normal (0 0 1); material glass; } }/;s/number   200;/number 200; velocity (1e20 0 0);/;s/^timeStep       1e-5;/timeStep 1e-5; timeStepOverride true;/|error: particle id [0-9]+ moved more than half its radius"
  "through_the_wall|s/number   200;/number 200; velocity (0 0 -1e4);/;s/^timeStep       1e-5;/timeStep 1e-5; timeStepOverride true;/|error: particle id [0-9]+ moved more than half its radius.*Lower timeStep"
  # multisphere templates (a line 13 added after the walls) and a body insertion in place of the spheres
  "multisphere_radii_count|s/^walls \(.*\)/walls \1\nmultisphere { pair { material glass; centres ((0 0 0) (1e-3 0 0)); radii (1e-3); } }/;s/material glass;$/body pair;/;s/diameter { distribution constant; value 2e-3; }//|demProperties:13: error: key 'radii'.*1 radii for 2 centres"
  "multisphere_unknown_body|s/^walls \(.*\)/walls \1\nmultisphere { pair { material glass; centres ((0 0 0) (1e-3 0 0)); radii (1e-3 1e-3); } }/;s/material glass;$/body pear;/;s/diameter { distribution constant; value 2e-3; }//|demProperties:20: error: key 'body'.*'pear' is not among the multisphere templates"
  "multisphere_mass_model|s/^walls \(.*\)/walls \1\nmultisphere { pair { material glass; centres ((0 0 0) (1e-3 0 0)); radii (1e-3 1e-3); massModel sum; } }/;s/material glass;$/body pair;/;s/diameter { distribution constant; value 2e-3; }//|demProperties:13: error: key 'massModel'.*sphereSum"
  "domain_not_finite|s/max (0.01 0.01 0.04); }$/max (0.01 0.01 1e308); }/;s/^domain { min (-0.01 -0.01 0);/domain { min (-0.01 -0.01 -1e308);/|demProperties:8: error: key 'min'.*out of range"
  "step_count_overflow|s/^endTime        0.02;/endTime        1e9;/;s/^timeStep       1e-5;/timeStep 1e-12;/|demProperties:4: error: key 'endTime'.*more than 1e13 steps"
  "gravity_huge|s/^gravity        (0 0 -9.81);/gravity (0 0 -1e300);/|demProperties:6: error: key 'gravity'.*out of range"
  "domain_far|s/max (0.01 0.01 0.04); }$/max (0.01 0.01 1e308); }/|demProperties:8: error: key 'max'.*out of range"
  "soft_material|s/youngsModulus 5e6/youngsModulus 1e4/;s/^endTime        0.02;/endTime        0.3;/|error: a contact overlap reached .*The time step is not the cause.*raise youngsModulus"
  "cylinder_region_outside|s/region   { type box; min (-0.01 -0.01 0); max (0.01 0.01 0.04); }/region { type cylinder; axis z; centre (0 0); radius 0.05; axialMin 0; axialMax 0.04; }/|demProperties:17: error: key 'radius': the cylinder must lie inside the domain"
  "nul_byte|s/^skin           0.3e-3;/skin 0.3e-3; \x00/|demProperties:7: error: .*NUL byte"
  "insertion_too_many|s/number   200;/number 200000;/|demProperties:16: error: insertion 'fill': placed only"
  "sjkr_without_energy|s/tangential history; }/tangential history; cohesion sjkr; }/|demProperties:11: error: .*cohesionEnergyDensity"
  "roughness_angle|s/tangential history; }/tangential history; surface roughness; roughness { distribution uniform; max 2; } }/|demProperties:10: error: key 'max'"
  "blow_up|s/^timeStep       1e-5;/timeStep       5e-4; timeStepOverride true; endTime 1;/;/^endTime /d|blew up|left the domain|moved more than half its radius"
)
for c in "${cases[@]}"; do
    IFS='|' read -r name expr expect <<< "$c"
    mkdir -p "$work/$name/constant"
    sed -e "$expr" "$here/base.demProperties" > "$work/$name/constant/demProperties"
    timeout 60 "$demRun" "$work/$name" > "$work/$name.out" 2> "$work/$name.err"
    status=$?   # 124: a hang (timeout)
    if [ $status -eq 1 ] && grep -qE "$expect" "$work/$name.err"; then
        echo "PASS $name: $(grep -m1 -E 'error' "$work/$name.err")"
        passed=$((passed + 1))
    else
        echo "FAIL $name: exit status $status, expected 1 and stderr matching: $expect"
        sed 's/^/    /' "$work/$name.err" | head -5
        failed=$((failed + 1))
    fi
done

# Inputs that are odd but valid must run to the end (exit 0) within the timeout, never hang.
accepted=(
  "normal_min_equals_max|s/diameter { distribution constant; value 2e-3; }/diameter { distribution normal; mean 2e-3; stdDev 1e-4; min 2e-3; max 2e-3; }/"
  "normal_narrow_tail|s/diameter { distribution constant; value 2e-3; }/diameter { distribution normal; mean 2e-3; stdDev 1e-3; min 2e-3; max 2.000001e-3; }/"
)
for c in "${accepted[@]}"; do
    IFS='|' read -r name expr <<< "$c"
    mkdir -p "$work/$name/constant"
    sed -e "$expr" -e 's/^endTime        0.02;/endTime        0.001;/' "$here/base.demProperties" > "$work/$name/constant/demProperties"
    timeout 60 "$demRun" "$work/$name" > "$work/$name.out" 2> "$work/$name.err"
    status=$?
    if [ $status -eq 0 ] && grep -q "^done:" "$work/$name.out"; then
        echo "PASS $name: runs ($(grep -m1 '^insertion' "$work/$name.out"))"
        passed=$((passed + 1))
    else
        echo "FAIL $name: exit status $status (124: hang), expected a finished run"
        sed 's/^/    /' "$work/$name.err" | head -5
        failed=$((failed + 1))
    fi
done
# 100,000 distinct unknown keys: reported at once (a linear search per key made this N^2: minutes)
name=many_unknown_keys
mkdir -p "$work/$name/constant"
{ cat "$here/base.demProperties"; seq 0 99999 | sed 's/.*/k& 1;/'; } > "$work/$name/constant/demProperties"
start=$(date +%s.%N)
timeout 20 "$demRun" "$work/$name" > "$work/$name.out" 2> "$work/$name.err"
status=$?
secs=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
if [ $status -eq 1 ] && grep -q "demProperties:23: error: unknown key 'k0'" "$work/$name.err"; then
    echo "PASS $name: demProperties:23 named in ${secs} s"; passed=$((passed + 1))
else
    echo "FAIL $name: exit status $status (124: over 20 s)"; failed=$((failed + 1))
fi

# writeInterval far longer than the run (1e9 s / 1e-12 s overflowed the step count into "every
# step"): the initial and final states only
name=write_interval_huge
mkdir -p "$work/$name/constant"
sed -e 's/^writeInterval  0;/writeInterval  1e9;/' -e 's/^endTime        0.02;/endTime        1e-10;/' \
    -e 's/^timeStep       1e-5;/timeStep       1e-12;/' "$here/base.demProperties" > "$work/$name/constant/demProperties"
timeout 60 "$demRun" "$work/$name" > "$work/$name.out" 2> "$work/$name.err"
status=$?
nsnap=$(/usr/bin/python3 -c "import h5py, sys; print(len(h5py.File(sys.argv[1], 'r')['snapshots']))" "$work/$name/particles.h5" 2>/dev/null)
if [ $status -eq 0 ] && [ "$nsnap" = 2 ]; then
    echo "PASS $name: 100 steps, 2 snapshots (start and end)"; passed=$((passed + 1))
else
    echo "FAIL $name: exit status $status, $nsnap snapshots (expected 2)"; failed=$((failed + 1))
fi
echo "bad input: $passed passed, $failed failed"
[ $failed -eq 0 ]
