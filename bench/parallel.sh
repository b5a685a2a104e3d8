#!/bin/bash
# The DEM's parallel speed-up (issue 23): the 50k-sphere scene of run_bench.sh (bench/case50k),
# serially and with `mpirun -np N demRun`, in one script, so that both see the same machine.
#
# usage: bench/parallel.sh [--quick] [--np N] [--repeat K] [--demrun PATH]
#
#   Each run: demRun <copy of bench/case50k> -phases 1,20000,2000 (insertion, settling, settled);
#   --quick divides the step counts by 10. N (default 2) ranks under mpirun (as root: the
#   OMPI_ALLOW_RUN_AS_ROOT variables are set here). Wall times are the PHASE lines' own timers,
#   CPU times /usr/bin/time's user + system of the whole run (all ranks). The serial and the
#   parallel run take turns K times (default 2) and the best wall time of each counts: these
#   machines are shared, and a run slowed by a neighbour says nothing about the code.
#
# Output: RESULT lines: particle-steps per second per phase and run, the speed-up of N ranks over
# one in wall time per phase (best against best) and in all, the CPU time of each run, and the
# bytes each rank sent per step against an all-gather of every particle.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
quick=0; np=2; repeat=2
demrun="$repo/build/dem/demRun"
while [ $# -gt 0 ]; do
    case "$1" in
        --quick) quick=1 ;;
        --np) np="$2"; shift ;;
        --repeat) repeat="$2"; shift ;;
        --demrun) demrun="$2"; shift ;;
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1' "$0"; exit 0 ;;
        *) echo "parallel.sh: unknown argument '$1'" >&2; exit 2 ;;
    esac
    shift
done
[ -x "$demrun" ] || { echo "parallel.sh: $demrun not found (./Allwmake builds it)" >&2; exit 2; }
nsettle=20000; nsettled=2000
if [ $quick = 1 ]; then nsettle=2000; nsettled=200; fi
. "$here/timing.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
work=$(mktemp -d /tmp/bench_parallel.XXXXXX)
[ "${KEEP_WORK:-0}" = 1 ] || trap 'rm -rf "$work"' EXIT
echo "INFO date $(date -Is) host $(hostname) cpus $(grep -c ^processor /proc/cpuinfo) quick=$quick np=$np"

run() {   # name ranks
    local name=$1 ranks=$2
    rm -rf "$work/$name"
    cp -r "$here/case50k" "$work/$name"
    local launch=()
    [ "$ranks" -gt 1 ] && launch=(mpirun -np "$ranks" --oversubscribe)
    echo "INFO running $name ($nsettle + $nsettled steps on $ranks rank(s))" >&2
    /usr/bin/time -v -o "$work/$name.time" "${launch[@]}" "$demrun" "$work/$name" -phases "1,$nsettle,$nsettled" \
        > "$work/$name.log" 2>&1 || { echo "demRun failed; tail of its output:" >&2; tail -20 "$work/$name.log" >&2; exit 1; }
    awk -v name="$name" '/^PHASE / { k++; for (i = 3; i <= NF; i++) { split($i, kv, "="); v[k, kv[1]] = kv[2] } }
        END { printf "RESULT %s_settling_wall_s %s\nRESULT %s_settled_wall_s %s\n", name, v[2, "wall_s"], name, v[3, "wall_s"]
              printf "RESULT %s_settling_particle_steps_per_s %s\nRESULT %s_settled_particle_steps_per_s %s\n",
                     name, v[2, "particle_steps_per_s"], name, v[3, "particle_steps_per_s"] }' "$work/$name.log"
    echo "RESULT ${name}_cpu_s $(cpu_time "$work/$name.time")"
    echo "RESULT ${name}_elapsed_s $(elapsed "$work/$name.time")"
    grep -E "^(exchange|decomposition)" "$work/$name.log" | sed "s/^/INFO $name: /" || true
}
for k in $(seq 1 "$repeat"); do
    run serial 1 > "$work/res_serial_$k"; sed "s/^RESULT /RESULT run$k\_/" "$work/res_serial_$k"
    run ranks$np "$np" > "$work/res_par_$k"; sed "s/^RESULT /RESULT run$k\_/" "$work/res_par_$k"
done
# the best (lowest) of each figure over the repetitions, the rates the highest
awk '$1 == "RESULT" { k = $2; v = $3 + 0
        if (!(k in best) || (k ~ /per_s$/ && v > best[k]) || (k !~ /per_s$/ && v < best[k])) best[k] = v }
     END { for (k in best) print "RESULT", k, best[k] }' "$work"/res_serial_* | sort > "$work/serial.res"
awk '$1 == "RESULT" { k = $2; v = $3 + 0
        if (!(k in best) || (k ~ /per_s$/ && v > best[k]) || (k !~ /per_s$/ && v < best[k])) best[k] = v }
     END { for (k in best) print "RESULT", k, best[k] }' "$work"/res_par_* | sort > "$work/par.res"
echo "INFO the best of $repeat runs each:"
cat "$work/serial.res" "$work/par.res"
grep -h "^INFO" "$work"/res_par_* | sort -u || true
get() { awk -v k="$2" '$2 == k { print $3 }' "$1"; }
for phase in settling settled; do
    awk -v a="$(get "$work/serial.res" serial_${phase}_wall_s)" -v b="$(get "$work/par.res" ranks${np}_${phase}_wall_s)" \
        -v p=$phase -v n="$np" 'BEGIN { printf "RESULT speedup_%s_%d_ranks %.3f\n", p, n, a / b }'
done
awk -v a="$(get "$work/serial.res" serial_elapsed_s)" -v b="$(get "$work/par.res" ranks${np}_elapsed_s)" -v n="$np" \
    'BEGIN { printf "RESULT speedup_whole_run_%d_ranks %.3f (wall, start-up and output included)\n", n, a / b }'
awk -v a="$(get "$work/serial.res" serial_cpu_s)" -v b="$(get "$work/par.res" ranks${np}_cpu_s)" -v n="$np" \
    'BEGIN { printf "RESULT cpu_ratio_%d_ranks_over_serial %.3f\n", n, b / a }'
