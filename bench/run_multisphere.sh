#!/bin/bash
# Multisphere benchmark: 20,000 tetrahedral clumps of 4 spheres, LIGGGHTS 3.8.0 (fix multisphere)
# vs. our demRun (multisphere bodies) on the same scene.
#
# usage: bench/run_multisphere.sh [--quick] [--liggghts-only | --ours-only] [--demrun PATH]
#                                 [--clumps N] [--mass-model union|sphereSum]
#
#   LIGGGHTS: bench/liggghts-multisphere.in (particletemplate/multisphere + insert/pack +
#             fix multisphere; run 1 = insertion, run nsettle = settling, run nsettled =
#             settled), timed from its "Loop time of X on 1 procs for N steps with M atoms" lines.
#   ours:     demRun <copy of bench/case_multisphere> -phases 1,nsettle,nsettled, timed from its
#             "PHASE k steps=... particles=... wall_s=... particle_steps_per_s=... cpu_s=..." lines.
#   Both run serially (one core, nice, OMP_NUM_THREADS=1) under /usr/bin/time -v.
#   Full run: 20,000 clumps (80,000 spheres), 1 + 20000 + 2000 steps. --quick: 2,000 clumps,
#   1 + 2000 + 200 steps (smoke test only: the settling figure is then mostly free fall).
#   --clumps N: N clumps (N <= 27000); the insertion region's height follows N (0.0875 m x N /
#   20000), so the solid fraction of the region stays 0.15 in both codes.
#   --mass-model: our body mass model (default union, which is what LIGGGHTS' template computes,
#   by Monte Carlo over the union; sphereSum counts the spheres' overlaps twice, 13 % heavier here).
#   KEEP_WORK=1 keeps the temp dir with the logs.
#   Particle-steps count spheres (4 per clump); clump-steps/s = particle-steps/s / 4.
#   Phase wall times are the codes' own loop timers; process CPU and wall come from /usr/bin/time.
#
# Output: RESULT <name> <value> lines; the last ones are the ratios ours/LIGGGHTS.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
quick=0; do_lig=1; do_ours=1
demrun="$repo/build/dem/demRun"
nclumps=""; mass_model=union
while [ $# -gt 0 ]; do
    case "$1" in
        --quick) quick=1 ;;
        --liggghts-only) do_ours=0 ;;
        --ours-only) do_lig=0 ;;
        --demrun) demrun="$2"; shift ;;
        --clumps) nclumps="$2"; shift ;;
        --mass-model) mass_model="$2"; shift ;;
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1' "$0"; exit 0 ;;
        *) echo "run_multisphere.sh: unknown argument '$1'" >&2; exit 2 ;;
    esac
    shift
done

nsettle=20000; nsettled=2000
if [ $quick = 1 ]; then nsettle=2000; nsettled=200; fi
if [ -z "$nclumps" ]; then if [ $quick = 1 ]; then nclumps=2000; else nclumps=20000; fi; fi
case "$nclumps" in ''|*[!0-9]*) echo "--clumps wants a positive integer" >&2; exit 2 ;; esac
if [ "$nclumps" -lt 1 ] || [ "$nclumps" -gt 27000 ]; then echo "--clumps: 1 .. 27000 (the box's lid is at 0.12 m)" >&2; exit 2; fi
case "$mass_model" in union|sphereSum) ;; *) echo "--mass-model: union or sphereSum" >&2; exit 2 ;; esac
nspheres=4                                   # spheres per clump
zins=$(awk -v n="$nclumps" 'BEGIN { printf "%.6g", 0.0875 * n / 20000 }')
endtime=$(awk -v a="$nsettle" -v b="$nsettled" 'BEGIN { printf "%.8g", (1 + a + b) * 1e-5 }')

. "$here/timing.sh"   # /usr/bin/time, peak_rss, cpu_time, elapsed

work=$(mktemp -d /tmp/benchms.XXXXXX)
[ "${KEEP_WORK:-0}" = 1 ] || trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1


echo "INFO date $(date -Is) host $(hostname) cpus $(grep -c ^processor /proc/cpuinfo) quick=$quick clumps=$nclumps spheres=$((nclumps * nspheres)) steps=1+$nsettle+$nsettled region_zmax=$zins ours_mass_model=$mass_model"

if [ $do_lig = 1 ]; then
    if ! command -v liggghts >/dev/null 2>&1; then
        echo "SKIP liggghts not installed"; do_lig=0
    else
        mkdir "$work/lig"
        cp "$here/liggghts-multisphere.in" "$work/lig/in.bench"
        echo "INFO running LIGGGHTS ($nclumps clumps, $nsettle + $nsettled steps) in $work/lig" >&2
        (cd "$work/lig" && nice /usr/bin/time -v -o time.txt liggghts -in in.bench -var nclumps "$nclumps" \
            -var nsettle "$nsettle" -var nsettled "$nsettled" > screen.txt 2>&1) || {
            echo "LIGGGHTS failed; tail of its output:" >&2; tail -20 "$work/lig/screen.txt" >&2; exit 1; }
        # the clumps really are fix multisphere bodies: all templates inserted, 4 atoms each,
        # and fix multisphere ran (its set-up warning names fix_multisphere.cpp)
        l_ins=$(awk '/inserted [0-9]+ particle templates/ { for (i = 1; i < NF; i++) if ($i == "inserted") n = $(i+1) } END { print n + 0 }' "$work/lig/screen.txt")
        if [ "$l_ins" != "$nclumps" ]; then
            echo "LIGGGHTS inserted $l_ins of $nclumps clumps" >&2; exit 1; fi
        grep -q 'fix_multisphere.cpp' "$work/lig/screen.txt" || {
            echo "LIGGGHTS: no sign of fix multisphere in the output" >&2; exit 1; }
        l_mass=$(awk '/Finished calculating properties of template/ { getline; for (i = 1; i < NF; i++) if ($i == "mass") { v = $(i+2); sub(/,$/, "", v); print v; exit } }' "$work/lig/log.liggghts")
        # Loop time lines in order: run 1, run $nsettle, run $nsettled
        read -r l_t1 l_n1 l_m1 l_t2 l_n2 l_m2 < <(awk '
            /^Loop time of/ { t[++k] = $4; n[k] = $9; m[k] = $12 }
            END { if (k < 3) exit 1; print t[k-1], n[k-1], m[k-1], t[k], n[k], m[k] }' "$work/lig/screen.txt") || {
            echo "could not parse LIGGGHTS Loop time lines" >&2; exit 1; }
        if [ "$l_n1" != "$nsettle" ] || [ "$l_n2" != "$nsettled" ]; then
            echo "unexpected LIGGGHTS step counts $l_n1 $l_n2" >&2; exit 1; fi
        if [ "$l_m2" != $((nclumps * nspheres)) ]; then
            echo "LIGGGHTS has $l_m2 atoms at the end, expected $((nclumps * nspheres))" >&2; exit 1; fi
        l_rss=$(peak_rss "$work/lig/time.txt")
        lig_settle=$(awk -v t="$l_t1" -v n="$l_n1" -v m="$l_m1" 'BEGIN { printf "%.6g", n * m / t }')
        lig_settled=$(awk -v t="$l_t2" -v n="$l_n2" -v m="$l_m2" 'BEGIN { printf "%.6g", n * m / t }')
        echo "RESULT liggghts_clumps $l_ins"
        echo "RESULT liggghts_particles $l_m2"
        echo "RESULT liggghts_body_mass_kg $l_mass"
        echo "RESULT liggghts_settling_wall_s $l_t1"
        echo "RESULT liggghts_settled_wall_s $l_t2"
        echo "RESULT liggghts_settling_particle_steps_per_s $lig_settle"
        echo "RESULT liggghts_settled_particle_steps_per_s $lig_settled"
        awk -v x="$lig_settle" -v k=$nspheres 'BEGIN { printf "RESULT liggghts_settling_clump_steps_per_s %.6g\n", x / k }'
        awk -v x="$lig_settled" -v k=$nspheres 'BEGIN { printf "RESULT liggghts_settled_clump_steps_per_s %.6g\n", x / k }'
        awk -v r="$l_rss" -v m="$l_m2" 'BEGIN { printf "RESULT liggghts_peak_rss_bytes_per_particle %.1f\n", r / m }'
        echo "RESULT liggghts_process_cpu_s $(cpu_time "$work/lig/time.txt")"
        echo "RESULT liggghts_process_wall_s $(elapsed "$work/lig/time.txt")"
    fi
fi

if [ $do_ours = 1 ]; then
    if [ ! -x "$demrun" ]; then
        echo "SKIP ours: $demrun not found (build with cmake -S . -B build && cmake --build build)"
        do_ours=0
    else
        cp -r "$here/case_multisphere" "$work/case-copy"
        dp="$work/case-copy/constant/demProperties"
        awk -v n="$nclumps" -v z="$zins" -v te="$endtime" -v mm="$mass_model" '
            $1 == "endTime"   { sub(/endTime +[^;]+;/, "endTime        " te ";") }
            $1 == "number"    { sub(/number +[0-9]+;/, "number   " n ";") }
            $1 == "massModel" { sub(/massModel +[A-Za-z]+;/, "massModel " mm ";") }
            $1 == "region" && /quick: height/ { sub(/0\.075 0\.075 0\.0875\)/, "0.075 0.075 " z ")") }
            { print }' "$here/case_multisphere/constant/demProperties" > "$dp"
        grep -q "number   $nclumps;" "$dp" && grep -q "0.075 0.075 $zins)" "$dp" && grep -q "massModel $mass_model;" "$dp" || {
            echo "could not set up $dp for $nclumps clumps" >&2; exit 1; }
        echo "INFO running ours ($nclumps clumps, $nsettle + $nsettled steps) in $work/case-copy" >&2
        nice /usr/bin/time -v -o "$work/time_ours.txt" "$demrun" "$work/case-copy" \
            -phases "1,$nsettle,$nsettled" > "$work/ours.txt" 2>&1 || {
            echo "demRun failed; tail of its output:" >&2; tail -20 "$work/ours.txt" >&2; exit 1; }
        o_bodies=$(awk '/^multisphere: [0-9]+ bodies/ { print $2 }' "$work/ours.txt")
        if [ "$o_bodies" != "$nclumps" ]; then
            echo "demRun reports '${o_bodies:-no}' multisphere bodies, expected $nclumps" >&2; exit 1; fi
        o_mass=$(awk '/^multisphere template .* mass / { for (i = 1; i < NF; i++) if ($i == "mass") { print $(i+1); exit } }' "$work/ours.txt")
        # PHASE <k> steps=<n> particles=<N> wall_s=<s> particle_steps_per_s=<x> cpu_s=<c>
        read -r o_t1 o_n1 o_m1 o_x1 o_c1 o_t2 o_n2 o_m2 o_x2 o_c2 < <(awk '
            /^PHASE / { k++; for (i = 3; i <= NF; i++) { split($i, kv, "="); v[k, kv[1]] = kv[2] } }
            END { if (k < 3) exit 1
                  print v[k-1,"wall_s"], v[k-1,"steps"], v[k-1,"particles"], v[k-1,"particle_steps_per_s"], v[k-1,"cpu_s"],
                        v[k,"wall_s"], v[k,"steps"], v[k,"particles"], v[k,"particle_steps_per_s"], v[k,"cpu_s"] }' \
            "$work/ours.txt") || { echo "could not parse PHASE lines of demRun" >&2; exit 1; }
        if [ "$o_n1" != "$nsettle" ] || [ "$o_n2" != "$nsettled" ]; then
            echo "unexpected demRun step counts $o_n1 $o_n2" >&2; exit 1; fi
        o_rss=$(peak_rss "$work/time_ours.txt")
        echo "RESULT ours_clumps $o_bodies"
        echo "RESULT ours_particles $o_m2"
        echo "RESULT ours_body_mass_kg $o_mass"
        echo "RESULT ours_settling_wall_s $o_t1"
        echo "RESULT ours_settled_wall_s $o_t2"
        echo "RESULT ours_settling_cpu_s $o_c1"
        echo "RESULT ours_settled_cpu_s $o_c2"
        echo "RESULT ours_settling_particle_steps_per_s $o_x1"
        echo "RESULT ours_settled_particle_steps_per_s $o_x2"
        awk -v x="$o_x1" -v k=$nspheres 'BEGIN { printf "RESULT ours_settling_clump_steps_per_s %.6g\n", x / k }'
        awk -v x="$o_x2" -v k=$nspheres 'BEGIN { printf "RESULT ours_settled_clump_steps_per_s %.6g\n", x / k }'
        awk -v r="$o_rss" -v m="$o_m2" 'BEGIN { printf "RESULT ours_peak_rss_bytes_per_particle %.1f\n", r / m }'
        echo "RESULT ours_process_cpu_s $(cpu_time "$work/time_ours.txt")"
        echo "RESULT ours_process_wall_s $(elapsed "$work/time_ours.txt")"
    fi
fi

if [ $do_lig = 1 ] && [ $do_ours = 1 ]; then
    awk -v a="$o_x1" -v b="$lig_settle" 'BEGIN { printf "RESULT ratio_ours_over_liggghts_settling %.4g\n", a / b }'
    awk -v a="$o_x2" -v b="$lig_settled" 'BEGIN { printf "RESULT ratio_ours_over_liggghts_settled %.4g\n", a / b }'
fi
