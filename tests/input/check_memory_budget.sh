#!/bin/bash
# Counts too large for the machine's memory stop at the key that implies them (issue 26), with the
# memory they would take and the largest (or smallest) value of the key accepted here, and never
# with the allocator's "out of memory" and no location (dem/src/memory_budget.h). Each case edits
# a base dictionary, runs demRun and must exit 1 with "<file>:<line>: error: key '<key>'" and
# "accepted here is"; the budget is the machine's memory, or DEM_MEMORY_BYTES where a case sets it
# (a budget of 91,200 bytes is 100 particles of 912 bytes):
#   number 1e8 (85 GiB: above any machine these tests run on), solidFraction 0.5 of 1 um beads,
#   a lattice spacing of 1 um, 300 clumps of 4 spheres in a budget of 1,000 particles, and a stream
#   (tests/input/lifecycle.demProperties) that fills a budget of 100 particles during the run.
# Control: each base case runs (to t = 0) without the edit in the same budget where one is set.
# Usage: check_memory_budget.sh <demRun>
demRun=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
# name|base|budget|sed edit|key
cases=(
  "number|base|0|s/number   200;/number 100000000;/|number"
  "solidFraction|base|0|s/number   200;/solidFraction 0.5;/;s/value 2e-3;/value 1e-6;/|solidFraction"
  "lattice|base_insertion|0|s/spacing  0.002;/spacing 1e-6;/;s/value 2e-3;/value 1e-6;/;s/number   200;//|spacing"
  "bodies|base_multisphere|912000|s/^endTime .*/endTime 0;/|number"
  "stream|lifecycle|91200|s/^endTime .*/endTime 0.1;/|massRate"
)
for c in "${cases[@]}"; do
    IFS='|' read -r name base budget edit key <<< "$c"
    d=$work/$name
    mkdir -p "$d/constant"
    sed -e "$edit" "$here/$base.demProperties" > "$d/constant/demProperties"
    env_budget=()
    [ "$budget" != 0 ] && env_budget=(DEM_MEMORY_BYTES=$budget)
    env "${env_budget[@]}" "$demRun" "$d" > "$d/log" 2>&1
    rc=$?
    if [ $rc = 1 ] && grep -Eq "demProperties:[0-9]+: error: key '$key': .*accepted here is|demProperties:[0-9]+: error: key '$key': .*the most this machine's memory holds" "$d/log" &&
       ! grep -q "out of memory" "$d/log"; then
        echo "CHECK memory $name: stops at key '$key' with the largest accepted value PASS"
    else
        echo "CHECK memory $name: stops at key '$key' with the largest accepted value FAIL (exit $rc)"; tail -2 "$d/log"; fail=1
    fi
    grep "error:" "$d/log" | head -1 | cut -c1-400
done
# control: the bodies' base case fits a budget of 2,000 particles (300 x 4 spheres)
d=$work/control
mkdir -p "$d/constant"
sed -e 's/^endTime .*/endTime 0;/' "$here/base_multisphere.demProperties" > "$d/constant/demProperties"
if DEM_MEMORY_BYTES=1824000 "$demRun" "$d" > "$d/log" 2>&1; then
    echo "CHECK memory control: 300 clumps of 4 spheres run in a budget of 2,000 particles PASS"
else
    echo "CHECK memory control: 300 clumps of 4 spheres run in a budget of 2,000 particles FAIL"; tail -2 "$d/log"; fail=1
fi
exit $fail
