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
