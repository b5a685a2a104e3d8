# The tutorials' parallel runs (issue 23), sourced by their Allrun:
#
#   take_np "$@"; set -- "${ARGS[@]}"
#       NP = N from `-np N` anywhere in the arguments (default 1), ARGS = the others; also
#       `-decompose simple|hierarchical|manual` (default simple), in DECOMPOSE.
#   run_solver <solver> <axis>
#       NP = 1: the solver, as before, its output in log.voidPimpleFoam.
#       NP > 1: system/decomposeParDict for NP subdomains (written here: simple cuts along
#       <axis> (x, y or z, the case's long side); hierarchical cuts it into 2 along the first
#       other axis and NP/2 along <axis>; manual gives each cell the rank of a slanted cut
#       (boundaries that are not planes of the mesh and subdomains that are not boxes), from
#       the cell centres), decomposePar, mpirun -np NP <solver> -parallel (log.voidPimpleFoam),
#       reconstructPar (the fields in the case's time directories, for ParaView and the checks).
#       The particles are written by the solver into the case itself (particles.h5), whatever
#       NP is.
# mpirun as root needs OMPI_ALLOW_RUN_AS_ROOT and OMPI_ALLOW_RUN_AS_ROOT_CONFIRM (set here);
# more ranks than cores need --oversubscribe (given when NP exceeds the core count).
# scotch and metis are stubs in Debian's OpenFOAM; `manual` stands in for their non-box shapes.

take_np() {
    NP=1
    DECOMPOSE=simple
    ARGS=()
    while [ $# -gt 0 ]; do
        case "$1" in
        -np)
            [[ "${2:-}" =~ ^[1-9][0-9]*$ ]] || { echo "Allrun: -np needs a rank count (1, 2, 4, ...), got '${2:-}'" >&2; exit 2; }
            NP=$2; shift 2 ;;
        -decompose)
            case "${2:-}" in simple|hierarchical|manual) DECOMPOSE=$2 ;;
            *) echo "Allrun: -decompose simple|hierarchical|manual, got '${2:-}'" >&2; exit 2 ;; esac
            shift 2 ;;
        *) ARGS+=("$1"); shift ;;
        esac
    done
}

write_decompose_dict() {
    local axis=$1 n
    case "$axis" in
    x) n="($NP 1 1)" ;; y) n="(1 $NP 1)" ;; z) n="(1 1 $NP)" ;;
    *) echo "parallel.sh: axis '$axis' is not x, y or z" >&2; exit 2 ;;
    esac
    local hn=$n
    if [ "$DECOMPOSE" = hierarchical ]; then
        [ $((NP % 2)) -eq 0 ] || { echo "Allrun: -decompose hierarchical needs an even -np" >&2; exit 2; }
        case "$axis" in
        x) hn="($((NP / 2)) 2 1)" ;; y) hn="(2 $((NP / 2)) 1)" ;; z) hn="(2 1 $((NP / 2)))" ;;
        esac
    fi
    cat > system/decomposeParDict <<EOF
// Written by tutorials/tools/parallel.sh for -np $NP -decompose $DECOMPOSE
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains $NP;
method          $DECOMPOSE;
simpleCoeffs       { n $n; delta 0.001; }
hierarchicalCoeffs { n $hn; delta 0.001; order xyz; }
manualCoeffs       { dataFile "cellDecomposition"; }
EOF
    if [ "$DECOMPOSE" = manual ]; then
        postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1 || { tail -20 log.writeCellCentres; exit 1; }
        /usr/bin/python3 "$(dirname "${BASH_SOURCE[0]}")/manual_decomposition.py" "$NP" "$axis"
    fi
}

# decompose_case <axis>: system/decomposeParDict and decomposePar (NP > 1)
decompose_case() {
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    write_decompose_dict "$1"
    rm -rf processor*
    decomposePar -force > log.decomposePar 2>&1 || { tail -20 log.decomposePar; exit 1; }
}

# parallel_solver <solver>: the solver on NP ranks (mpirun ... -parallel) or, for NP = 1, alone;
# its output to stdout
parallel_solver() {
    if [ "$NP" -eq 1 ]; then
        "$1"
        return
    fi
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    local over=()
    [ "$NP" -gt "$(nproc)" ] && over=(--oversubscribe)
    mpirun "${over[@]}" -np "$NP" "$1" -parallel
}

# reconstruct_case: the fields of the new times into the case's time directories (NP > 1)
reconstruct_case() {
    reconstructPar -newTimes > log.reconstructPar 2>&1 || { tail -20 log.reconstructPar; exit 1; }
}

# run_solver <solver> <axis>: decompose, run, reconstruct; the solver's output in log.voidPimpleFoam
run_solver() {
    [ "$NP" -gt 1 ] && decompose_case "$2"
    parallel_solver "$1" > log.voidPimpleFoam 2>&1 || { tail -30 log.voidPimpleFoam; exit 1; }
    [ "$NP" -gt 1 ] && reconstruct_case
    return 0
}
