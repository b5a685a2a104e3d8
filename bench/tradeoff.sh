#!/bin/bash
# The speed/accuracy trade (issue 22): every knob of each validation case, one at a time from the
# case's reference, with wall and CPU time and each check's error; the full sweep writes
# docs/tradeoff.md, docs/tradeoff/<case>.png (Pareto plots) and docs/tradeoff/tradeoff_full.csv, the
# other modes bench/results/tradeoff_<mode>.{md,csv} and <case>.png. bench/tradeoff.py says what
# each knob does.
# Usage: bench/tradeoff.sh [-quick | -smoke | -extremes | -regression] [-j N] [--cases a,b] [--knobs a,b]
#   (full: settling, ergun, fluidisedBed, every knob and the extremes past the sweep; -extremes: only
#    those; -quick: fewer points, under 10 minutes on
#    2 cores; -smoke: the settling sphere, three runs, seconds: what ctest runs; -regression: the
#    extremes ctest keeps, each checked to stop with its message or fail with its number)
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/foam/bin/voidPimpleFoam ] || ./Allwmake
exec /usr/bin/python3 bench/tradeoff.py "$@"
