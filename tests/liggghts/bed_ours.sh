#!/bin/bash
# Settled-bed scene (tests/liggghts/bed_case) with our demRun; the same RESULT lines and the same
# post-processing (bed_post.py) as "run_reference.sh bed" for LIGGGHTS.
#
# usage: tests/liggghts/bed_ours.sh <demRun>
# Exit 0 on success, 77 (with "SKIP ...") when demRun or python3-h5py is missing, 1 on failure.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
[ $# -eq 1 ] || { sed -n '2,6p' "$0" >&2; exit 2; }
demrun=$1
if [ ! -x "$demrun" ]; then
    echo "SKIP demRun not found: $demrun"
    exit 77
fi
if ! /usr/bin/python3 -c 'import h5py' 2>/dev/null; then
    echo "SKIP python3-h5py missing for /usr/bin/python3 (apt-get install -y python3-h5py)"
    exit 77
fi

work=$(mktemp -d /tmp/bedours.XXXXXX)
[ "${KEEP_WORK:-0}" = 1 ] && echo "INFO work dir $work" >&2 || trap 'rm -rf "$work"' EXIT
cp -r "$here/bed_case" "$work/bed_case"

t0=$(date +%s.%N)
if ! "$demrun" "$work/bed_case" > "$work/demRun.txt" 2>&1; then
    echo "demRun failed; tail of its output:" >&2
    tail -20 "$work/demRun.txt" >&2
    exit 1
fi
t1=$(date +%s.%N)
echo "RESULT requested 2500"
awk -v a="$t0" -v b="$t1" 'BEGIN { printf "RESULT wall_s %.1f\n", b - a }'
/usr/bin/python3 "$here/bed_post.py" ours "$work/bed_case/particles.h5"
