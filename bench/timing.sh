# Sourced by the benchmark scripts: /usr/bin/time (installed if missing) and the parsers of its
# -v report, so that every script reads wall, CPU and memory the same way.
if [ ! -x /usr/bin/time ]; then
    echo "installing package 'time' for /usr/bin/time" >&2
    apt-get install -y time >/dev/null
fi
# peak RSS [bytes], CPU time (user + system) [s] and elapsed wall time [s] from a /usr/bin/time -v report
peak_rss() { awk -F': *' '/Maximum resident set size/ { print $2 * 1024 }' "$1"; }
cpu_time() { awk -F': *' '/User time|System time/ { t += $2 } END { print t }' "$1"; }
elapsed() { awk '/Elapsed \(wall clock\)/ { n = split($NF, p, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + p[i]; print s }' "$1"; }
# timed_restart <demRun> <case dir> <steps> <log> [VAR=value ...]: demRun -restart of the case (from
# its particles.h5) for <steps> steps, under nice, with the given environment; prints
# "<the phase's wall s> <the process's CPU s>" (the PHASE line's wall_s, /usr/bin/time's user + sys)
timed_restart() {
    local demrun=$1 dir=$2 steps=$3 log=$4
    shift 4
    env "$@" nice /usr/bin/time -f "%U %S" -o "$dir/time.txt" "$demrun" "$dir" -restart -phases "$steps" > "$log" 2>&1 || {
        echo "demRun failed on a restart of $dir; tail of its output:" >&2; tail -5 "$log" >&2; return 1; }
    awk '/^PHASE/ { for (i = 3; i <= NF; i++) { split($i, kv, "="); if (kv[1] == "wall_s") w = kv[2] } }
         END { printf "%s ", w }' "$log"
    awk '{ print $1 + $2 }' "$dir/time.txt"
}
