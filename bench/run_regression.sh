#!/bin/bash
# Non-regression of the default models (hertz + history): our demRun at <old-commit> against
# the current build, on the 50k scene of run_bench.sh, alternating old/new runs (old, new, old,
# new, ...) so that slow drifts of the machine hit both alike, plus one LIGGGHTS run for the
# ratio. Prints each run's particle-steps/s and the ratio new/old of the medians.
#
# usage: bench/run_regression.sh <old-commit> [repeats (default 2)] [--quick]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
old=${1:?usage: run_regression.sh <old-commit> [repeats] [--quick]}
repeats=${2:-2}
quick=${3:-}
new_demrun="$repo/build/dem/demRun"
[ -x "$new_demrun" ] || { echo "build first: ./Allwmake" >&2; exit 1; }

tree=$(mktemp -d /tmp/bench_old.XXXXXX)
trap 'git -C "$repo" worktree remove --force "$tree" >/dev/null 2>&1 || true; rm -rf "$tree"' EXIT
git -C "$repo" worktree add --detach "$tree" "$old" >/dev/null 2>&1
cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$tree/build" --target demRun -j 2 >/dev/null
old_demrun="$tree/build/dem/demRun"
echo "INFO old $(git -C "$repo" rev-parse --short "$old"), new $(git -C "$repo" rev-parse --short HEAD)$(git -C "$repo" diff --quiet HEAD -- dem || echo ' + uncommitted dem/ changes')"

run() {   # label demRun
    "$here/run_bench.sh" --ours-only --demrun "$2" $quick | awk -v l="$1" '/^RESULT ours_(settling|settled)_particle/ { print "RUN", l, $2, $3 }'
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
