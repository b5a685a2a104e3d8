# Sourced by the parallel checks (check_parallel_bed.sh, check_parallel_bodies.sh), which set
# demRun, mpiexec and work first.
#   run_ranks <ranks> <caseDir> [demRun arguments]
# runs demRun on that many ranks (mpirun, oversubscribed beyond the cores; 1: demRun alone), its
# output to $work/log (printed, and the check stopped, when it fails), and prints its summary
# lines (done, exchange, decomposition) marked with the rank count and the case.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1   # ../shared/docs: mpirun as root
run_ranks() {
    local np=$1; shift
    if [ "$np" = 1 ]; then "$demRun" "$@" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
    else "$mpiexec" -np "$np" --oversubscribe "$demRun" "$@" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
    fi
    grep -E "^(done|exchange|decomposition)" "$work/log" | sed "s|^|  $np rank(s), $(basename "$1"): |"
}
