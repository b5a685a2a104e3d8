#!/bin/bash
# LIGGGHTS 3.8.0 reference runs for the DEM core. Prints "RESULT <name> <value>" lines.
#
# usage: tests/liggghts/run_reference.sh <scenario> [params...]
#   restitution E nu rho radius e v        two equal spheres head-on, relative speed v
#   oblique     E nu rho radius e mu vn vt one sphere onto the plane z = 0
#   bed [seed]                             2500 spheres settled in a 40x40x200 mm box
#                                          (seed: a prime for insert/pack, to gauge scatter)
# Units SI. Exit 0 on success, 77 (with "SKIP ...") when liggghts is not installed,
# 2 on bad usage, 1 when the run fails.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1' "$0" >&2; exit 2; }
[ $# -ge 1 ] || usage

if ! command -v liggghts >/dev/null 2>&1; then
    echo "SKIP liggghts not installed"
    exit 77
fi

work=$(mktemp -d /tmp/ligref.XXXXXX)
[ "${KEEP_WORK:-0}" = 1 ] && echo "INFO work dir $work" >&2 || trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1

# check_contact_ended <nparticles>: the run must end with the contact over and no sphere lost
check_contact_ended() {
    awk -v n="$1" '$1 == "RESULT" && $2 == "final_gap" { g = $3 + 0; seen_g = 1 }
        $1 == "RESULT" && $2 == "particles" { p = $3 + 0; seen_p = 1 }
        END { if (!seen_g || !seen_p) { print "no final_gap/particles RESULT" > "/dev/stderr"; exit 1 }
              if (p != n) { print "a sphere left the box (" p " of " n " left)" > "/dev/stderr"; exit 1 }
              if (g <= 0) { print "the contact had not ended at the end of the run" > "/dev/stderr"; exit 1 } }' \
        "$work/screen.txt" || exit 1
}

# run_lig <input> [-var name value ...]: runs LIGGGHTS in $work, screen output to $work/screen.txt
run_lig() {
    local in=$1; shift
    if ! (cd "$work" && liggghts -in "$in" -echo none "$@" > screen.txt 2>&1); then
        echo "liggghts failed; tail of its output:" >&2
        tail -20 "$work/screen.txt" >&2
        exit 1
    fi
    if grep -q '^ERROR' "$work/screen.txt"; then
        grep '^ERROR' "$work/screen.txt" >&2
        exit 1
    fi
}

scenario=$1; shift
case "$scenario" in
    restitution)
        [ $# -eq 6 ] || usage
        run_lig "$here/restitution.in" -var E "$1" -var nu "$2" -var rho "$3" -var r "$4" \
            -var e "$5" -var v "$6"
        check_contact_ended 2
        grep '^RESULT' "$work/screen.txt"
        ;;
    oblique)
        [ $# -eq 8 ] || usage
        run_lig "$here/oblique.in" -var E "$1" -var nu "$2" -var rho "$3" -var r "$4" \
            -var e "$5" -var mu "$6" -var vn "$7" -var vt "$8"
        check_contact_ended 1
        grep '^RESULT' "$work/screen.txt"
        ;;
    bed)
        [ $# -le 1 ] || usage
        t0=$(date +%s.%N)
        if [ $# -eq 1 ]; then run_lig "$here/bed.in" -var seed "$1"; else run_lig "$here/bed.in"; fi
        t1=$(date +%s.%N)
        grep '^RESULT' "$work/screen.txt"
        awk '$1 == "RESULT" && $2 == "requested" { q = $3 } $1 == "RESULT" && $2 == "inserted" { n = $3 }
             END { if (q == "" || n != q) { print "inserted " n " of " q " particles" > "/dev/stderr"; exit 1 } }' \
            "$work/screen.txt" || exit 1
        awk -v a="$t0" -v b="$t1" 'BEGIN { printf "RESULT wall_s %.1f\n", b - a }'
        /usr/bin/python3 "$here/bed_post.py" liggghts "$work/final.dump"
        ;;
    *)
        echo "run_reference.sh: unknown scenario '$scenario'" >&2
        usage
        ;;
esac
