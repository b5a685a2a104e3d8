#!/bin/bash
# Every contact model in a 2,000-sphere bed (issue 4): the bed settles in a box without NaN or
# blow-up at the largest time step the core's check allows (taken from the check's own message,
# times 0.99 for its 3-digit rounding), and at ten times that step demRun stops with a clear
# message: the time-step check names the key (exit 1), and with timeStepOverride the blow-up
# detector stops the run (exit 1: "blew up", or "moved more than half its radius" in one step),
# never a crash or a NaN.
# "Settled": mean kinetic energy per particle below that of 2 cm/s after 0.25 s.
# Usage: check_model_beds.sh <demRun>
demRun=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0

# name | contactModels entries | default-interaction entries
models=(
  "hertz_history|normal hertz; tangential history;|"
  "edinburgh|normal edinburgh; tangential history;|unloadingRatio 5; surfaceEnergy 0.05; loadingExponent 1.5; adhesionExponent 1.5;"
  "sjkr|normal hertz; tangential history; cohesion sjkr;|cohesionEnergyDensity 2e4;"
  "cdt|normal hertz; tangential history; rolling cdt;|rollingFriction 0.1;"
  "cdtJkr|normal hertz; tangential history; rolling cdtJkr; torsionTorque true;|workOfAdhesion 0.05; adhesionHysteresis 5;"
  "epsd|normal hertz; tangential history; rolling epsd;|rollingFriction 0.1; rollingViscousDamping 0.3;"
  "roughness|normal hertz; tangential history; surface roughness; roughness { distribution normal; stdDev 0.1; seed 7; }|"
  "jkr|normal jkr; tangential history;|workOfAdhesion 0.02;"
  "dmt|normal dmt; tangential history;|workOfAdhesion 0.02;"
  "hooke|normal hooke; tangential history; characteristicVelocity 0.5;|"
)

write_case() {   # dir models interaction timeStep extra
    mkdir -p "$1/constant"
    cat > "$1/constant/demProperties" <<CASE
timeStep       $4;
endTime        0.25;
writeInterval  0;
progressInterval 1000;
gravity        (0 0 -9.81);
$5
domain { min (-0.015 -0.015 0); max (0.015 0.015 0.07); }
materials { glass { youngsModulus 5e6; poissonsRatio 0.45; density 2500; } }
contactModels { $2 }
interactions { default { restitution 0.5; friction 0.5; $3 } }
walls { box { type box; min (-0.015 -0.015 0); max (0.015 0.015 0.07); material glass; } }
insertion
{
    fill
    {
        region   { type box; min (-0.014 -0.014 0.001); max (0.014 0.014 0.069); }
        number   2000;
        material glass;
        diameter { distribution constant; value 2e-3; }
        maxAttempts 5000;
    }
}
CASE
}

result() {   # ok name message
    if [ "$1" = 1 ]; then echo "PASS $2: $3"; passed=$((passed + 1)); else echo "FAIL $2: $3"; failed=$((failed + 1)); fi
}

for m in "${models[@]}"; do
    IFS='|' read -r name cm inter <<< "$m"
    # the largest safe step, from the check's message
    write_case "$work/$name.probe" "$cm" "$inter" 1
    "$demRun" "$work/$name.probe" > "$work/$name.probe.out" 2>&1
    safe=$(grep -oE 'largest safe step is [0-9.e+-]+' "$work/$name.probe.out" | awk '{print $5}')
    if [ -z "$safe" ]; then result 0 "$name" "no largest safe step in the check's message"; sed 's/^/    /' "$work/$name.probe.out" | tail -3; continue; fi
    dt=$(awk -v s="$safe" 'BEGIN { printf "%.6g", 0.99 * s }')
    dt10=$(awk -v s="$safe" 'BEGIN { printf "%.6g", 10 * s }')

    write_case "$work/$name" "$cm" "$inter" "$dt"
    "$demRun" "$work/$name" > "$work/$name.out" 2>&1
    status=$?
    ke=$(grep -oE 'kinetic energy [0-9.e+-]+' "$work/$name.out" | awk '{print $3}')
    n=$(grep -oE 'insertion .fill.: [0-9]+' "$work/$name.out" | awk '{print $3}')
    ok=$(awk -v k="$ke" -v n="$n" 'BEGIN { m = 2500 * 4 / 3 * 3.14159265 * 1e-9; print (k != "" && n == 2000 && k / n < 0.5 * m * 0.02^2) ? 1 : 0 }')
    [ $status -eq 0 ] || ok=0
    result "$ok" "$name" "dt $dt s (safe $safe): exit $status, $n particles, kinetic energy ${ke:-?} J after 0.25 s"
    [ "$ok" = 1 ] || tail -3 "$work/$name.out" | sed 's/^/    /'

    write_case "$work/$name.10x" "$cm" "$inter" "$dt10"
    "$demRun" "$work/$name.10x" > "$work/$name.10x.out" 2>&1
    status=$?
    ok=0; [ $status -eq 1 ] && grep -q "error: key 'timeStep'.*largest safe step" "$work/$name.10x.out" && ok=1
    result "$ok" "$name.10x" "exit $status: $(grep -m1 -oE "error: key 'timeStep'.{0,40}" "$work/$name.10x.out")"

    write_case "$work/$name.10xo" "$cm" "$inter" "$dt10" "timeStepOverride true;"
    "$demRun" "$work/$name.10xo" > "$work/$name.10xo.out" 2>&1
    status=$?
    ok=0; [ $status -eq 1 ] && grep -qE "blew up|left the domain|moved more than half its radius" "$work/$name.10xo.out" && ok=1
    result "$ok" "$name.10x override" "exit $status: $(grep -m1 -oE "(blew up|left the domain|moved more than half its radius).{0,60}" "$work/$name.10xo.out")"
done
echo "model beds: $passed passed, $failed failed"
[ $failed -eq 0 ]
