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
  "sjkr_without_energy|s/tangential history; }/tangential history; cohesion sjkr; }/|demProperties:11: error: .*cohesionEnergyDensity"
  "roughness_angle|s/tangential history; }/tangential history; surface roughness; roughness { distribution uniform; max 2; } }/|demProperties:10: error: key 'max'"
  "blow_up|s/^timeStep       1e-5;/timeStep       5e-4; timeStepOverride true; endTime 1;/;/^endTime /d|blew up|left the domain"
)
for c in "${cases[@]}"; do
    IFS='|' read -r name expr expect <<< "$c"
    mkdir -p "$work/$name/constant"
    sed -e "$expr" "$here/base.demProperties" > "$work/$name/constant/demProperties"
    "$demRun" "$work/$name" > "$work/$name.out" 2> "$work/$name.err"
    status=$?
    if [ $status -eq 1 ] && grep -qE "$expect" "$work/$name.err"; then
        echo "PASS $name: $(grep -m1 -E 'error' "$work/$name.err")"
        passed=$((passed + 1))
    else
        echo "FAIL $name: exit status $status, expected 1 and stderr matching: $expect"
        sed 's/^/    /' "$work/$name.err" | head -5
        failed=$((failed + 1))
    fi
done
echo "bad input: $passed passed, $failed failed"
[ $failed -eq 0 ]
