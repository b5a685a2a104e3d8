#!/bin/bash
# 50k-sphere Hertz benchmark: LIGGGHTS 3.8.0 vs. our demRun on the same scene.
#
# usage: bench/run_bench.sh [--quick] [--liggghts-only | --ours-only] [--demrun PATH] [--snapshot FILE]
#
#   LIGGGHTS: bench/liggghts-50k-hertz.in (run 1 = insertion, run 20000 = settling,
#             run 2000 = settled), timed from its "Loop time of X on 1 procs for N steps
#             with M atoms" lines.
#   ours:     demRun <copy of bench/case50k> -phases 1,20000,2000, timed from its
#             "PHASE k steps=... particles=... wall_s=... particle_steps_per_s=..." lines.
#   Both run serially (one core, nice) under /usr/bin/time -v for the peak RSS.
#   --quick divides the settling/settled step counts by 10 (smoke test; figures not comparable
#   with full runs). KEEP_WORK=1 keeps the temp dir with the logs. --snapshot FILE keeps our
#   final state (the settled bed, particles.h5) as FILE, for restarts (run_regression.sh).
#   Wall times are the codes' own loop timers; CPU times come from /usr/bin/time (whole process).
#
# Output: RESULT <name> <value> lines; the last two are the ratios ours/LIGGGHTS.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
quick=0; do_lig=1; do_ours=1
demrun="$repo/build/dem/demRun"
snapshot=""
while [ $# -gt 0 ]; do
    case "$1" in
        --quick) quick=1 ;;
        --liggghts-only) do_ours=0 ;;
        --ours-only) do_lig=0 ;;
        --demrun) demrun="$2"; shift ;;
        --snapshot) snapshot="$2"; shift ;;
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1' "$0"; exit 0 ;;
        *) echo "run_bench.sh: unknown argument '$1'" >&2; exit 2 ;;
    esac
    shift
done

nsettle=20000; nsettled=2000
if [ $quick = 1 ]; then nsettle=2000; nsettled=200; fi

. "$here/timing.sh"   # /usr/bin/time, peak_rss, cpu_time, elapsed

work=$(mktemp -d /tmp/bench50k.XXXXXX)
[ "${KEEP_WORK:-0}" = 1 ] || trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1


echo "INFO date $(date -Is) host $(hostname) cpus $(grep -c ^processor /proc/cpuinfo) quick=$quick"

if [ $do_lig = 1 ]; then
    if ! command -v liggghts >/dev/null 2>&1; then
        echo "SKIP liggghts not installed"; do_lig=0
    else
        mkdir "$work/lig"
        awk -v a="$nsettle" -v b="$nsettled" '
            $1 == "run" && $2 == "20000" { print "run", a; next }
            $1 == "run" && $2 == "2000"  { print "run", b; next }
            { print }' "$here/liggghts-50k-hertz.in" > "$work/lig/in.bench"
        echo "INFO running LIGGGHTS ($nsettle + $nsettled steps) in $work/lig" >&2
        (cd "$work/lig" && nice /usr/bin/time -v -o time.txt liggghts -in in.bench > screen.txt 2>&1) || {
            echo "LIGGGHTS failed; tail of its output:" >&2; tail -20 "$work/lig/screen.txt" >&2; exit 1; }
        # Loop time lines in order: run 1, run $nsettle, run $nsettled
        read -r l_t1 l_n1 l_m1 l_t2 l_n2 l_m2 < <(awk '
            /^Loop time of/ { t[++k] = $4; n[k] = $9; m[k] = $12 }
            END { if (k < 3) exit 1; print t[k-1], n[k-1], m[k-1], t[k], n[k], m[k] }' "$work/lig/screen.txt") || {
            echo "could not parse LIGGGHTS Loop time lines" >&2; exit 1; }
        if [ "$l_n1" != "$nsettle" ] || [ "$l_n2" != "$nsettled" ]; then
            echo "unexpected LIGGGHTS step counts $l_n1 $l_n2" >&2; exit 1; fi
        l_rss=$(peak_rss "$work/lig/time.txt")
        lig_settle=$(awk -v t="$l_t1" -v n="$l_n1" -v m="$l_m1" 'BEGIN { printf "%.6g", n * m / t }')
        lig_settled=$(awk -v t="$l_t2" -v n="$l_n2" -v m="$l_m2" 'BEGIN { printf "%.6g", n * m / t }')
        lig_bpp=$(awk -v r="$l_rss" -v m="$l_m2" 'BEGIN { printf "%.1f", r / m }')
        echo "RESULT liggghts_particles $l_m2"
        echo "RESULT liggghts_settling_wall_s $l_t1"
        echo "RESULT liggghts_settled_wall_s $l_t2"
        echo "RESULT liggghts_settling_particle_steps_per_s $lig_settle"
        echo "RESULT liggghts_settled_particle_steps_per_s $lig_settled"
        echo "RESULT liggghts_peak_rss_bytes_per_particle $lig_bpp"
        echo "RESULT liggghts_process_cpu_s $(cpu_time "$work/lig/time.txt")"
    fi
fi

if [ $do_ours = 1 ]; then
    if [ ! -x "$demrun" ]; then
        echo "SKIP ours: $demrun not found (build with cmake -S . -B build && cmake --build build)"
        do_ours=0
    else
        cp -r "$here/case50k" "$work/case50k-copy"
        echo "INFO running ours ($nsettle + $nsettled steps) in $work/case50k-copy" >&2
        nice /usr/bin/time -v -o "$work/time_ours.txt" "$demrun" "$work/case50k-copy" \
            -phases "1,$nsettle,$nsettled" > "$work/ours.txt" 2>&1 || {
            echo "demRun failed; tail of its output:" >&2; tail -20 "$work/ours.txt" >&2; exit 1; }
        # PHASE <k> steps=<n> particles=<N> wall_s=<s> particle_steps_per_s=<x>
        read -r o_t1 o_n1 o_m1 o_x1 o_t2 o_n2 o_m2 o_x2 < <(awk '
            /^PHASE / { k++; for (i = 3; i <= NF; i++) { split($i, kv, "="); v[k, kv[1]] = kv[2] } }
            END { if (k < 3) exit 1
                  print v[k-1,"wall_s"], v[k-1,"steps"], v[k-1,"particles"], v[k-1,"particle_steps_per_s"],
                        v[k,"wall_s"], v[k,"steps"], v[k,"particles"], v[k,"particle_steps_per_s"] }' \
            "$work/ours.txt") || { echo "could not parse PHASE lines of demRun" >&2; exit 1; }
        o_rss=$(peak_rss "$work/time_ours.txt")
        ours_bpp=$(awk -v r="$o_rss" -v m="$o_m2" 'BEGIN { printf "%.1f", r / m }')
        echo "RESULT ours_particles $o_m2"
        echo "RESULT ours_settling_wall_s $o_t1"
        echo "RESULT ours_settled_wall_s $o_t2"
        echo "RESULT ours_settling_particle_steps_per_s $o_x1"
        echo "RESULT ours_settled_particle_steps_per_s $o_x2"
        echo "RESULT ours_peak_rss_bytes_per_particle $ours_bpp"
        echo "RESULT ours_process_cpu_s $(cpu_time "$work/time_ours.txt")"
        if [ -n "$snapshot" ]; then cp "$work/case50k-copy/particles.h5" "$snapshot"; fi
    fi
fi

if [ $do_lig = 1 ] && [ $do_ours = 1 ]; then
    awk -v a="$o_x1" -v b="$lig_settle" 'BEGIN { printf "RESULT ratio_ours_over_liggghts_settling %.4g\n", a / b }'
    awk -v a="$o_x2" -v b="$lig_settled" 'BEGIN { printf "RESULT ratio_ours_over_liggghts_settled %.4g\n", a / b }'
fi
