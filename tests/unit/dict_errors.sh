#!/bin/sh
# Runs every dictionary case in dict_cases/ through `test_dict --read` and checks the outcome.
#   usage: dict_errors.sh <test_dict binary> [cases dir]
# Each case's first line is "// expect: <text>":
#   OK      the file must read cleanly (exit 0);
#   <text>  the run must exit with status 1 (not crash) and stderr must contain "/<text>",
#           i.e. "<file>:<line>: error: ..." with the file, the line and the key.
# *.inc files are only included by cases and are not run on their own.
bin=$1
dir=${2:-$(dirname "$0")/dict_cases}
if [ ! -x "$bin" ] || [ ! -d "$dir" ]; then
    echo "usage: $0 <test_dict binary> [cases dir]" >&2
    exit 2
fi
pass=0
fail=0
err=$(mktemp) || exit 2
trap 'rm -f "$err"' EXIT

check() {   # name rc expect
    if [ "$3" = OK ]; then
        if [ "$2" -eq 0 ]; then pass=$((pass + 1)); return; fi
        echo "FAIL $1: expected success, got exit status $2:" >&2
    elif [ "$2" -ne 1 ]; then
        echo "FAIL $1: expected exit status 1, got $2:" >&2
    elif ! grep -qF -- "$3" "$err"; then
        echo "FAIL $1: stderr does not contain: $3" >&2
    else
        pass=$((pass + 1))
        return
    fi
    sed 's/^/    /' "$err" >&2
    fail=$((fail + 1))
}

for f in "$dir"/*.dict; do
    expect=$(sed -n '1s|^// expect: ||p' "$f")
    if [ -z "$expect" ]; then
        echo "FAIL $f: first line is not '// expect: ...'" >&2
        fail=$((fail + 1))
        continue
    fi
    "$bin" --read "$f" >/dev/null 2>"$err"
    rc=$?
    [ "$expect" = OK ] || expect="/$expect"
    check "$(basename "$f")" "$rc" "$expect"
done

# A missing top-level file.
"$bin" --read "$dir/no_such_file" >/dev/null 2>"$err"
check no_such_file $? "/no_such_file: error: cannot read dictionary file: No such file or directory"

echo "dict_errors: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
