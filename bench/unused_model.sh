#!/bin/bash
# "An unused model costs nothing", measured (issue 22 part 4) on the settled 50k-sphere bed of
# run_bench.sh (Hertz, tangential history, 50,000 spheres, about 3 contacts each).
#
# usage: bench/unused_model.sh [--quick] [--rounds N (default 8)] [--steps S (default 300)]
#
# Variants, each a restart of S steps from the same settled snapshot:
#   off      the case as it is: cohesion none, rolling none. It runs the specialised kernel of
#            (hertz, history), in which the other models' code does not exist (evaluate.h: the
#            model ids are constants and the unused branches are compiled out). This is the
#            "build where the model does not exist".
#   generic  the same models, DEM_GENERIC_KERNELS=1: every model's code is present and the
#            kernel dispatches on the case's ids per contact (what a combination without a
#            specialised kernel runs)
#   sjkr0    cohesion sjkr with cohesionEnergyDensity 0: a model switched on at zero strength
#            (the same forces, its work done)
#   epsd     rolling epsd, rollingFriction 0.1: a model in use
# The variants run in rotating order within each round, and each round gives every variant's
# time over off's (paired: the runs of a round are seconds apart on the same machine). Printed:
# the median ratio over the rounds with its 95 % interval (order statistics), wall and CPU, and
# for sjkr0 and epsd the end-of-run probe's share of that model (dem_stage_report).
# --quick: 2,000 settling steps instead of 20,000, 3 rounds of 100 steps (a smoke test).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
rounds=8; steps=300; quick=""
while [ $# -gt 0 ]; do
    case "$1" in
        --quick) quick=--quick; rounds=3; steps=100 ;;
        --rounds) rounds=${2:?}; shift ;;
        --steps) steps=${2:?}; shift ;;
        *) echo "usage: unused_model.sh [--quick] [--rounds N] [--steps S]" >&2; exit 2 ;;
    esac
    shift
done
demrun="$repo/build/dem/demRun"
[ -x "$demrun" ] || "$repo/Allwmake"
. "$here/timing.sh"
work=$(mktemp -d /tmp/unused_model.XXXXXX)
[ "${KEEP_WORK:-0}" = 1 ] || trap 'rm -rf "$work"' EXIT
echo "INFO date $(date -Is) host $(hostname) cpus $(nproc); settling the bed (run_bench.sh --ours-only $quick)"
"$here/run_bench.sh" --ours-only $quick --snapshot "$work/settled.h5" | grep '^RESULT ours_' || true

variants="off generic sjkr0 epsd"
for v in $variants; do
    mkdir -p "$work/$v"
    cp -r "$repo/bench/case50k/constant" "$work/$v/"
    props="$work/$v/constant/demProperties"
    sed -i 's/^endTime .*/endTime 1e3;/' "$props"
    case $v in
        sjkr0) sed -i -e 's/^\( *cohesion *\)none;/\1sjkr;/' \
                      -e 's/^\( *default *{ restitution 0.5; friction 0.5;\) }/\1 cohesionEnergyDensity 0; }/' "$props" ;;
        epsd)  sed -i -e 's/^\( *rolling *\)none;/\1epsd;/' \
                      -e 's/^\( *default *{ restitution 0.5; friction 0.5;\) }/\1 rollingFriction 0.1; }/' "$props" ;;
    esac
done
grep -q 'cohesion *sjkr' "$work/sjkr0/constant/demProperties" && grep -q 'cohesionEnergyDensity 0' "$work/sjkr0/constant/demProperties" &&
    grep -q 'rolling *epsd' "$work/epsd/constant/demProperties" || { echo "unused_model.sh: editing the variants failed" >&2; exit 1; }

restart() {   # variant round -> "<phase wall s> <process cpu s>"
    local dir="$work/$1" env=""
    [ "$1" = generic ] && env="DEM_GENERIC_KERNELS=1"
    cp "$work/settled.h5" "$dir/particles.h5"
    rm -f "$dir/particles.xdmf"
    timed_restart "$demrun" "$dir" "$steps" "$dir/log.$2" $env
}

echo "INFO $rounds rounds of $steps-step restarts of each variant, rotating order"
set -- $variants
for k in $(seq "$rounds"); do
    line="ROUND $k"
    order=$(echo $variants | awk -v k="$k" '{ for (i = 0; i < NF; i++) printf "%s ", $((i + k - 1) % NF + 1) }')
    declare -A t=()
    for v in $order; do t[$v]=$(restart "$v" "$k"); done
    for v in $variants; do line+=" $v ${t[$v]}"; done
    echo "$line" >&2
    echo "$line"
done | awk -v vars="$variants" '
    { for (i = 3; i <= NF; i += 3) { w[$i, NR] = $(i + 1); c[$i, NR] = $(i + 2) } }
    function sort(a, n,   i, j, t) { for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t } }
    function median(a, n) { return n % 2 ? a[(n + 1) / 2] : 0.5 * (a[n / 2] + a[n / 2 + 1]) }
    END {
        n = NR; nv = split(vars, v, " ")
        lo = int(n / 2 - 0.98 * sqrt(n)); hi = int(n / 2 + 1 + 0.98 * sqrt(n) + 0.999)
        if (lo < 1) lo = 1; if (hi > n) hi = n
        for (k = 1; k <= nv; k++) {
            for (r = 1; r <= n; r++) { rw[r] = w[v[k], r] / w["off", r]; rc[r] = c[v[k], r] / c["off", r]; tw[r] = w[v[k], r] }
            sort(rw, n); sort(rc, n); sort(tw, n)
            printf "RESULT %-8s median wall %.3f s; over off: wall %.4f (95%% %.4f-%.4f), cpu %.4f (95%% %.4f-%.4f)\n",
                   v[k], median(tw, n), median(rw, n), rw[lo], rw[hi], median(rc, n), rc[lo], rc[hi]
        } }'
for v in sjkr0 epsd; do
    echo "PROBE $v (the end-of-run report of its last restart):"
    grep -E '^    (cohesion|rolling|tangential|the rest)' "$work/$v/log.$rounds" | sed 's/^/  /'
done
