#!/bin/bash
# Bad input for the lattice and file insertions and for symmetry planes: demRun must stop with
# exit status 1 and a message naming demProperties:line and the key, or the data file and its
# line; never a crash, never a silent run. Usage: check_insertion_errors.sh <demRun>
demRun=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0

# the lattice entry turned into a file entry (lines 20-23 of base_insertion.demProperties)
FILE='20s/method   lattice;/method   file; file "positions.dat";/;21,23d'
SYM='s/point (-0.01 0 0); normal (1 0 0)/point (-0.0085 0 0); normal (1 0 0)/'
# the lattice entry turned into a file of multisphere bodies' centres (a two-sphere template)
BODYFILE='20s/method   lattice;/method   file; file "positions.dat"; body pair;/;21,25d;s/^walls$/multisphere { pair { material glass; centres ((0 0 0) (2e-3 0 0)); radii (1e-3 1e-3); } }\nwalls/'

# name | sed expression on base_insertion.demProperties | constant/positions.dat (printf %b;
# empty: none) | shell command run in constant/ afterwards | text the error must contain (grep -E)
cases=(
  "lattice_spacing_overlap|s/spacing  0.002;/spacing  0.0015;/|||demProperties:22: error: key 'spacing'.*smaller than the largest diameter 0.002"
  "lattice_spacing_vector_overlap|s/spacing  0.002;/spacing  (0.002 0.0019 0.002);/|||demProperties:22: error: key 'spacing'.*smaller than the largest diameter"
  "lattice_spacing_two_numbers|s/spacing  0.002;/spacing  (0.002 0.003);/|||demProperties:22: error: key 'spacing'"
  "lattice_distribution_overlap|s/distribution constant; value 2e-3;/distribution uniform; min 1e-3; max 2.5e-3;/|||demProperties:22: error: key 'spacing'.*distribution's largest"
  "lattice_number_too_large|s/number   200;/number   5000;/|||demProperties:23: error: key 'number'.*holds only 1000 points"
  "unknown_method|s/method   lattice;/method   latice;/|||demProperties:20: error: key 'method'.*did you mean 'lattice'"
  "lattice_overlaps_wall|s/floor { type plane; point (0 0 0)/floor { type plane; point (0 0 0.0015)/|||demProperties:21: error: key 'region'.*overlaps wall 'floor'"
  "lattice_beyond_symmetry|$SYM|||demProperties:21: error: key 'region'.*beyond symmetryPlane 'front'"
  "lattice_random_key|s/number   200;/number   200; maxAttempts 10;/|||demProperties:23: error: unknown key 'maxAttempts'"
  "symmetry_with_material|s/normal (1 0 0); }/normal (1 0 0); material glass; }/|||demProperties:14: error: key 'material'.*no material"
  "symmetry_outside_domain|s/point (-0.01 0 0); normal (1 0 0)/point (-0.02 0 0); normal (1 0 0)/|||demProperties:14: error: key 'point'.*within the domain"
  "symmetry_zero_normal|s/normal (1 0 0); }/normal (0 0 0); }/|||demProperties:14: error: key 'normal'.*zero"
  "symmetry_periodic|s/max (0.01 0.01 0.04); }/max (0.01 0.01 0.04); periodic (true false false); }/|||demProperties:14: error: key 'normal'.*periodic direction x"
  "symmetry_missing_point|s/point (-0.01 0 0); normal (1 0 0)/normal (1 0 0)/|||demProperties:14: error: key 'point'.*required"
  "file_key_missing|20s/method   lattice;/method   file;/;21,23d|||demProperties:[0-9]+: error: key 'file'.*required"
  "file_missing|$FILE|||positions.dat: error: cannot open"
  "file_gzipped_only|$FILE|0 0 0.005\n|gzip positions.dat|positions.dat: error: .*positions.dat.gz' exists: gunzip it first"
  "file_gzipped|20s/method   lattice;/method   file; file \"positions.dat.gz\";/;21,23d|0 0 0.005\n|gzip positions.dat|positions.dat.gz: error: .*gunzip it first"
  "file_columns|$FILE|0 0 0.005 0.002\n0 0.004 0.005\n0 0 0.01 0.002 1 2\n||positions.dat:3: error: expected 3, 4, 7 or 8 columns"
  "file_not_a_number|$FILE|0 0 0.005\n0 abc 0.005\n||positions.dat:2: error: column 2 \(y\): 'abc' is not a number"
  "file_bad_diameter|$FILE|0 0 0.005 -0.002\n||positions.dat:1: error: column 4: the diameter -0.002 m is out of range"
  "file_overlap|$FILE|# x y z\n0 0 0.005\n0 0.005 0.005   // fine\n\n0 0.001 0.005\n||positions.dat:5: error: .*overlaps the particle of line 2"
  "body_file_columns|$BODYFILE|0 0 0.005 0.002\n||positions.dat:1: error: insertion 'bed' places multisphere bodies: 3, 6, 10 or 13 columns.*got 4"
  "body_file_overlap|$BODYFILE|0 0 0.005\n0 0.0005 0.005\n||positions.dat:2: error: body 'pair' at .*its sphere [12] overlaps"
  "file_outside|$FILE|0 0 0.005\n0 0 0.05\n||positions.dat:2: error: .*outside the domain"
  "file_overlaps_wall|$FILE|0 0 0.0005\n||positions.dat:1: error: .*overlaps wall 'floor'"
  "file_beyond_symmetry|$FILE;$SYM|-0.009 0 0.005\n||positions.dat:1: error: .*beyond symmetryPlane 'front'"
  "file_unknown_material|$FILE|0 0 0.005 0.002 0 0 0 steel\n||positions.dat:1: error: column 8: material 'steel' is not among the materials \(glass\)"
  "file_no_diameter|$FILE;/diameter {/d|0 0 0.005\n||positions.dat:1: error: no diameter column"
  "file_no_material|$FILE;/material glass;/d|0 0 0.005\n||positions.dat:1: error: no material column"
  "file_empty|$FILE|# nothing\n\n||positions.dat: error: no positions"
  "vectorField_count|$FILE|FoamFile { version 2.0; format ascii; class vectorField; }\n3\n(\n(0 0 0.005)\n(0 0.005 0.005)\n)\n||positions.dat:2: error: the count says 3 positions, the list has 2"
  "vectorField_unclosed|$FILE|(\n(0 0 0.005)\n(0 0.005 0.005)\n||positions.dat:1: error: the list of positions opened here is not closed"
  "vectorField_short_vector|$FILE|(\n(0 0 0.005)\n(0 0.005)\n)\n||positions.dat:3: error: a position is \(x y z\): expected a number, got '\)'"
  "vectorField_binary|$FILE|FoamFile { version 2.0; format binary; class vectorField; }\n2\n(\n)\n||positions.dat:1: error: a binary vectorField"
  "vectorField_trailing|$FILE|(\n(0 0 0.005)\n)\nextra\n||positions.dat:4: error: unexpected 'extra' after the list"
)
for c in "${cases[@]}"; do
    IFS='|' read -r name expr data post expect <<< "$c"
    mkdir -p "$work/$name/constant"
    sed -e "$expr" "$here/base_insertion.demProperties" > "$work/$name/constant/demProperties"
    [ -n "$data" ] && printf '%b' "$data" > "$work/$name/constant/positions.dat"
    [ -n "$post" ] && (cd "$work/$name/constant" && eval "$post")
    "$demRun" "$work/$name" > "$work/$name.out" 2> "$work/$name.err"
    status=$?
    if [ $status -eq 1 ] && grep -qE "$expect" "$work/$name.err"; then
        echo "PASS $name: $(grep -m1 -E 'error' "$work/$name.err" | sed "s|$work/||")"
        passed=$((passed + 1))
    else
        echo "FAIL $name: exit status $status, expected 1 and stderr matching: $expect"
        sed 's/^/    /' "$work/$name.err" | head -5
        failed=$((failed + 1))
    fi
done
# and the base case itself runs
mkdir -p "$work/good/constant"
cp "$here/base_insertion.demProperties" "$work/good/constant/demProperties"
if "$demRun" "$work/good" > "$work/good.out" 2>&1 && grep -q "insertion 'bed': 200 particles (lattice)" "$work/good.out"; then
    echo "PASS base case runs: $(grep -m1 insertion "$work/good.out")"
    passed=$((passed + 1))
else
    echo "FAIL base case does not run"; sed 's/^/    /' "$work/good.out" | tail -5
    failed=$((failed + 1))
fi
echo "bad insertion input: $passed passed, $failed failed"
[ $failed -eq 0 ]
