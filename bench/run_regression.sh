#!/bin/bash
# Non-regression of the default models (hertz + history): our demRun at <old-commit> against
# the current build, on the 50k scene of run_bench.sh, plus one LIGGGHTS run for the ratio.
#
# usage: bench/run_regression.sh <old-commit> [repeats (default 2)] [--quick] [--pairs N] [--steps S]
#
# 1. Whole runs (run_bench.sh --ours-only), alternating old/new `repeats` times: the median
#    particle-steps/s of the settling and the settled phase of each build, and new/old.
# 2. The kernel on the settled bed, paired: N pairs (default 40) of short restarts (S steps,
#    default 300) from each build's own settled snapshot (kept from its first whole run; both
#    builds run the same trajectory), the order swapped every pair (old-new, new-old, ...).
#    Each pair gives one ratio old time / new time (> 1: new faster); printed: their median
#    with its 95 % confidence interval (order statistics of the median, no assumption on the
#    distribution), from the phase's wall time and from the process's CPU time.
#    Why pairs of short runs: on these shared VMs one binary's 13-s settled phase scatters by
#    20 % from run to run, slowly (a whole run is fast or slow), so whole runs alternated three
#    times cannot tell 3 %; two restarts a few seconds apart see nearly the same machine.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
usage() { echo "usage: run_regression.sh <old-commit> [repeats] [--quick] [--pairs N] [--steps S]" >&2; exit 2; }
old=""; repeats=2; quick=""; pairs=40; steps=300
while [ $# -gt 0 ]; do
    case "$1" in
        --quick) quick=--quick ;;
        --pairs) pairs=${2:?}; shift ;;
        --steps) steps=${2:?}; shift ;;
        -*) usage ;;
        *) if [ -z "$old" ]; then old=$1; else repeats=$1; fi ;;
    esac
    shift
done
[ -n "$old" ] || usage
new_demrun="$repo/build/dem/demRun"
. "$here/timing.sh"   # timed_restart
[ -x "$new_demrun" ] || { echo "build first: ./Allwmake" >&2; exit 1; }

tree=$(mktemp -d /tmp/bench_old.XXXXXX)
trap 'git -C "$repo" worktree remove --force "$tree" >/dev/null 2>&1 || true; rm -rf "$tree"' EXIT
git -C "$repo" worktree add --detach "$tree" "$old" >/dev/null 2>&1
cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$tree/build" --target demRun -j 2 >/dev/null
old_demrun="$tree/build/dem/demRun"
echo "INFO old $(git -C "$repo" rev-parse --short "$old"), new $(git -C "$repo" rev-parse --short HEAD)$(git -C "$repo" diff --quiet HEAD -- dem || echo ' + uncommitted dem/ changes')"

snaps="$tree/snapshots"; mkdir -p "$snaps"
run() {   # label demRun
    local keep=""
    [ -f "$snaps/$1.h5" ] || keep="--snapshot $snaps/$1.h5"
    "$here/run_bench.sh" --ours-only --demrun "$2" $quick $keep | awk -v l="$1" '/^RESULT ours_(settling|settled)_particle/ { print "RUN", l, $2, $3 }'
}
lig=""
if command -v liggghts >/dev/null 2>&1; then
    lig=$("$here/run_bench.sh" --liggghts-only $quick | awk '/^RESULT liggghts_(settling|settled)_particle/ { print "RUN liggghts", $2, $3 }')
    echo "$lig"
fi
out=""
for k in $(seq "$repeats"); do
    r=$(run old "$old_demrun"); echo "$r"; out+="$r"$'\n'
    r=$(run new "$new_demrun"); echo "$r"; out+="$r"$'\n'
done
printf '%s%s\n' "$out" "$lig" | awk '
    $1 == "RUN" { split($3, a, "_"); ph = a[2]; v[$2, ph, ++n[$2, ph]] = $4 }
    function median(l, ph,   k, m, x, t, i, j) {
        m = n[l, ph]; for (i = 1; i <= m; i++) x[i] = v[l, ph, i]
        for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) if (x[j] < x[i]) { t = x[i]; x[i] = x[j]; x[j] = t }
        return m % 2 ? x[(m + 1) / 2] : 0.5 * (x[m / 2] + x[m / 2 + 1]) }
    END {
        for (p = 1; p <= 2; p++) {
            ph = p == 1 ? "settling" : "settled"
            o = median("old", ph); w = median("new", ph)
            printf "RESULT %s old %.4g new %.4g new/old %.4f", ph, o, w, w / o
            if (n["liggghts", ph]) printf " liggghts %.4g ratio_old %.3f ratio_new %.3f", v["liggghts", ph, 1], o / v["liggghts", ph, 1], w / v["liggghts", ph, 1]
            printf "\n"
        } }'

# 2. paired restarts of the settled bed
restart() {   # label demRun case-dir -> "<phase wall s> <process cpu s>"
    local dir="$tree/restart_$1"
    rm -rf "$dir"; mkdir -p "$dir"; cp -r "$3/constant" "$dir/"
    cp "$snaps/$1.h5" "$dir/particles.h5"
    sed -i 's/^endTime .*/endTime 1e3;/' "$dir/constant/demProperties"
    timed_restart "$2" "$dir" "$steps" "$dir/log.txt"
}
echo "INFO $pairs pairs of $steps-step restarts from the settled snapshots"
for k in $(seq "$pairs"); do
    if [ $((k % 2)) = 1 ]; then
        o=$(restart old "$old_demrun" "$tree/bench/case50k"); w=$(restart new "$new_demrun" "$repo/bench/case50k")
    else
        w=$(restart new "$new_demrun" "$repo/bench/case50k"); o=$(restart old "$old_demrun" "$tree/bench/case50k")
    fi
    echo "PAIR $k old $o new $w" >&2   # to the terminal or log as it goes (not tee /dev/stderr: that reopens a log file and truncates it)
    echo "PAIR $k old $o new $w"
done | awk '
    { wo[NR] = $4; co[NR] = $5; wn[NR] = $7; cn[NR] = $8; rw[NR] = $4 / $7; rc[NR] = $5 / $8 }
    function sort(a, n,   i, j, t) { for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t } }
    function median(a, n) { return n % 2 ? a[(n + 1) / 2] : 0.5 * (a[n / 2] + a[n / 2 + 1]) }
    END {
        n = NR; if (n == 0) exit 1
        # 95 % interval of the median: the order statistics n/2 -+ 0.98 sqrt(n) (binomial, p = 1/2)
        lo = int(n / 2 - 0.98 * sqrt(n)); hi = int(n / 2 + 1 + 0.98 * sqrt(n) + 0.999)
        if (lo < 1) lo = 1; if (hi > n) hi = n
        sort(rw, n); sort(rc, n); sort(wo, n); sort(wn, n)
        printf "RESULT kernel_settled pairs %d steps_each %s median_wall_s old %.3f new %.3f\n", n, "'"$steps"'", median(wo, n), median(wn, n)
        printf "RESULT kernel_settled new/old (wall) %.4f 95%%CI %.4f-%.4f\n", median(rw, n), rw[lo], rw[hi]
        printf "RESULT kernel_settled new/old (cpu)  %.4f 95%%CI %.4f-%.4f\n", median(rc, n), rc[lo], rc[hi]
    }'
