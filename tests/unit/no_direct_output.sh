#!/bin/sh
# The libraries (dem/src, coupling/src) report only through the hooks of dem/src/error.h: no
# printf, puts, putchar, perror, exit or abort, and no use of stdout or stderr (so no fprintf,
# fputs or fflush to them either), outside error.c and error.h. fprintf to a file the library
# writes (XDMF, particles.dat) is output, not a report, and stays allowed; so does snprintf.
#   usage: no_direct_output.sh <project root>
root=${1:-$(dirname "$0")/../..}
cd "$root" || exit 2
[ -d dem/src ] && [ -d coupling/src ] || { echo "usage: $0 <project root>" >&2; exit 2; }
calls='(^|[^A-Za-z0-9_])(printf|vprintf|puts|putchar|perror|exit|_Exit|quick_exit|abort)[[:space:]]*\('
streams='(^|[^A-Za-z0-9_])(stdout|stderr)([^A-Za-z0-9_]|$)'
found=$(find dem/src coupling/src -name '*.[ch]' ! -path dem/src/error.c ! -path dem/src/error.h | sort |
        xargs grep -nE "$calls|$streams")
if [ -n "$found" ]; then
    echo "FAIL: printing or exiting outside the hooks of dem/src/error.h:"
    printf "%s\n" "$found" | sed 's/^/    /'
    exit 1
fi
echo "no_direct_output: $(find dem/src coupling/src -name '*.[ch]' | wc -l) files, none prints or exits outside error.c"
