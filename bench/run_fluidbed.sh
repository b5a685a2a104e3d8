#!/bin/bash
# Fluidised-bed benchmark: DPMFoam's own Goldschmidt tutorial (Debian's openfoam-examples) against
# our tutorials/fluidisedBed (the same bed in voidPimpleFoam + our DEM), and pimpleFoam on the same
# mesh, one after the other in this script, each serially on one core.
#
# usage: bench/run_fluidbed.sh [--time T] [--skip-dpmfoam] [--no-cellpoint] [--skip-pimplefoam] [--np N]
#
#   DPMFoam:   a copy of /usr/share/doc/openfoam-examples/examples/lagrangian/DPMFoam/Goldschmidt
#              as shipped (deltaT 2e-5 s, its 24,750 parcels from kinematicCloudPositions), run
#              from t = 0 to T (default 0.05 s) with one write at the end;
#   ours:      a copy of tutorials/fluidisedBed (the same lattice, fluid deltaT 1e-4 s, DEM step
#              5e-6 s), from t = 0 to T, one write at the end; its log gives the time split
#              (DEM, coupling, fluid); then the same with interpolation cellPoint, for the
#              coupling's cost of cellPoint against cell;
#   pimpleFoam: the same mesh, fvSchemes and fvSolution (the same correctors, no momentum
#              predictor, as the face form), no particles, the inlet at 1.875 m/s, the fluid
#              deltaT of ours: the cost of a fluid step without particles.
#   --np N:    ours again on N ranks (issue 23: decomposePar cutting the column across its height,
#              simple; AXIS=x|y|z and DECOMPOSE=simple|hierarchical|manual change that),
#              mpirun -np N voidPimpleFoam -parallel, and its speed-up over the serial run of the
#              same case, wall and CPU, per part; the bytes each rank sent per fluid step. (Cut
#              across the width, y, the gas's 5,400 cells scaled 1.41x on 2 ranks against 1.94x
#              cut across the height: a processor patch of 180 faces against 60.)
# Each under /usr/bin/time -f: wall and CPU (user + system) seconds. The machine is shared and
# noisy; the ratios are what the script is for.
# Output: RESULT lines, then the ratios DPMFoam/ours (wall and CPU per simulated second), ours'
# fluid step against pimpleFoam's, and cellPoint's coupling time against cell's.
# KEEP_WORK=1 keeps the temp dir with the logs.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
T=0.05; do_dpm=1; do_cellpoint=1; do_pimple=1; np=1
while [ $# -gt 0 ]; do
    case "$1" in
        --time) T="$2"; shift ;;
        --skip-dpmfoam) do_dpm=0 ;;
        --no-cellpoint) do_cellpoint=0 ;;
        --skip-pimplefoam) do_pimple=0 ;;
        --np) np="$2"; [[ "$np" =~ ^[1-9][0-9]*$ ]] || { echo "run_fluidbed.sh: --np needs a rank count" >&2; exit 2; }; shift ;;
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1' "$0"; exit 0 ;;
        *) echo "run_fluidbed.sh: unknown argument '$1'" >&2; exit 2 ;;
    esac
    shift
done

solver=$repo/build/foam/bin/voidPimpleFoam
[ -x "$solver" ] || "$repo/Allwmake"
export WM_PROJECT_DIR=${OF_DEV_DIR:-/opt/of/OpenFOAM-v1912}
[ -f "$WM_PROJECT_DIR/etc/controlDict" ] || export WM_PROJECT_DIR=/usr/share/openfoam
gold=/usr/share/doc/openfoam-examples/examples/lagrangian/DPMFoam/Goldschmidt
if [ $do_dpm = 1 ] && [ ! -d "$gold" ]; then
    echo "run_fluidbed.sh: $gold is missing (apt-get install openfoam-examples, or ./Allwmake)" >&2
    exit 1
fi
[ -x /usr/bin/time ] || { echo "run_fluidbed.sh: /usr/bin/time is missing (apt-get install time)" >&2; exit 1; }

work=$(mktemp -d /tmp/benchfluidbed.XXXXXX)
[ "${KEEP_WORK:-0}" = 1 ] || trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1
echo "INFO date $(date -Is) host $(hostname) cpus $(grep -c ^processor /proc/cpuinfo) simulated time $T s (work $work)"

# timed <name> <dir> <command...>: run in <dir> under /usr/bin/time, log to <dir>/log.run
timed() {
    local name=$1 dir=$2; shift 2
    echo "INFO running $name in $dir" >&2
    ( cd "$dir" && /usr/bin/time -f "TIME wall=%e user=%U sys=%S" -o time.txt nice "$@" > log.run 2>&1 ) || {
        tail -20 "$dir/log.run" >&2; echo "run_fluidbed.sh: $name failed" >&2; exit 1; }
    awk -v n="$name" -v T="$T" '{ split($2, w, "="); split($3, u, "="); split($4, s, "=");
        printf "RESULT %s wall_s %.1f cpu_s %.1f wall_per_simulated_s %.1f cpu_per_simulated_s %.1f\n",
        n, w[2], u[2] + s[2], w[2] / T, (u[2] + s[2]) / T }' "$dir/time.txt"
}
secs() { awk '{ split($2, w, "="); split($3, u, "="); split($4, s, "="); print (k == "wall" ? w[2] : u[2] + s[2]) }' k="$2" "$1/time.txt"; }
set_end() {   # set_end <case dir>: endTime T, a single write at the end
    sed -i -e "s/^endTime .*/endTime         $T;/" -e "s/^writeInterval .*/writeInterval   $T;/" \
           -e "s/^startFrom .*/startFrom       startTime;/" "$1/system/controlDict"
}

# --- DPMFoam, its own tutorial
if [ $do_dpm = 1 ]; then
    mkdir "$work/dpm"
    cp -r "$gold"/0 "$gold"/constant "$gold"/system "$work/dpm"/
    set_end "$work/dpm"
    (cd "$work/dpm" && blockMesh > log.blockMesh 2>&1)
    timed DPMFoam "$work/dpm" DPMFoam
fi

# --- ours
ours_case() {   # ours_case <dir> <interpolation>
    mkdir -p "$1"
    cp -r "$repo"/tutorials/fluidisedBed/{0,constant,system} "$1"/
    set_end "$1"
    sed -i "s/^interpolation .*/interpolation $2;/" "$1/constant/couplingProperties"
    (cd "$1" && blockMesh > log.blockMesh 2>&1)
}
split() {   # the solver's time split: DEM coupling fluid total [s]
    awk '/^Time split/ { on = 1 } on && $1 == "DEM" { d = $2 } on && $1 == "coupling" { c = $2 }
         on && $1 == "fluid" { f = $2 } on && $1 == "total" { t = $2; on = 0 } END { print d, c, f, t }' "$1/log.run"
}
ours_case "$work/ours" cell
timed ours "$work/ours" "$solver"
read -r dem cpl fluid total <<< "$(split "$work/ours")"
nfluid=$(awk '/^Time split over/ { print $4 }' "$work/ours/log.run")
printf "RESULT ours_split DEM_s %.1f coupling_s %.1f fluid_s %.1f total_s %.1f fluid_steps %d\n" "$dem" "$cpl" "$fluid" "$total" "$nfluid"
if [ "$np" -gt 1 ]; then
    ours_case "$work/ours_np$np" cell
    (cd "$work/ours_np$np" && source "$repo/tutorials/tools/parallel.sh" && NP=$np DECOMPOSE=${DECOMPOSE:-simple} && decompose_case "${AXIS:-z}")
    over=(); [ "$np" -gt "$(nproc)" ] && over=(--oversubscribe)
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timed "ours_np$np" "$work/ours_np$np" mpirun "${over[@]}" -np "$np" "$solver" -parallel
    read -r dem_p cpl_p fluid_p total_p <<< "$(split "$work/ours_np$np")"
    printf "RESULT ours_np%d_split DEM_s %.1f coupling_s %.1f fluid_s %.1f total_s %.1f\n" "$np" "$dem_p" "$cpl_p" "$fluid_p" "$total_p"
    grep "^Bytes sent per rank" "$work/ours_np$np/log.run" | sed 's/^/RESULT /'
    awk -v w1="$(secs "$work/ours" wall)" -v wn="$(secs "$work/ours_np$np" wall)" -v c1="$(secs "$work/ours" cpu)" \
        -v cn="$(secs "$work/ours_np$np" cpu)" -v n="$np" -v d1="$dem" -v dn="$dem_p" -v f1="$fluid" -v fn="$fluid_p" \
        -v k1="$cpl" -v kn="$cpl_p" 'BEGIN {
        printf "RESULT speedup_np%d wall %.2f (serial %.1f s, %d ranks %.1f s), CPU per rank %.2f; DEM %.2f, coupling %.2f, fluid %.2f\n",
               n, w1 / wn, w1, n, wn, c1 / (cn / n), d1 / dn, k1 / kn, f1 / fn }'
fi
if [ $do_cellpoint = 1 ]; then
    ours_case "$work/ours_cellPoint" cellPoint
    timed ours_cellPoint "$work/ours_cellPoint" "$solver"
    read -r dem_cp cpl_cp fluid_cp total_cp <<< "$(split "$work/ours_cellPoint")"
    printf "RESULT ours_cellPoint_split DEM_s %.1f coupling_s %.1f fluid_s %.1f total_s %.1f\n" "$dem_cp" "$cpl_cp" "$fluid_cp" "$total_cp"
fi

if [ $do_pimple = 1 ]; then
# --- pimpleFoam on the same mesh, no particles
mkdir -p "$work/pimple/constant"
cp -r "$repo"/tutorials/fluidisedBed/{0,system} "$work/pimple"/
set_end "$work/pimple"
sed -i -e 's/^application .*/application     pimpleFoam;/' -e '/^functions/,$d' "$work/pimple/system/controlDict"
cat > "$work/pimple/0/U" <<'UFILE'
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions      [0 1 -1 0 0 0 0];
internalField   uniform (0 0 1.875);
boundaryField
{
    bottom          { type fixedValue; value uniform (0 0 1.875); }
    top             { type pressureInletOutletVelocity; inletValue uniform (0 0 0); value uniform (0 0 0); }
    walls           { type noSlip; }
    frontAndBack    { type symmetry; }
}
UFILE
sed -i -e 's/div(alphaPhi,U)/div(phi,U)/' -e 's/div(((alpha\*nuEff)\*dev2(T(grad(U)))))/div((nuEff*dev2(T(grad(U)))))/' \
       "$work/pimple/system/fvSchemes"
sed -i -e '/faceMomentum/d' -e 's/^\( *nCorrectors .*\)$/\1\n    momentumPredictor no;/' "$work/pimple/system/fvSolution"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }\ntransportModel Newtonian;\nnu 1e-05;\n' \
    > "$work/pimple/constant/transportProperties"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object turbulenceProperties; }\nsimulationType laminar;\n' \
    > "$work/pimple/constant/turbulenceProperties"
cp "$repo"/tutorials/fluidisedBed/constant/g "$work/pimple/constant/"
(cd "$work/pimple" && blockMesh > log.blockMesh 2>&1)
timed pimpleFoam "$work/pimple" pimpleFoam
# pimpleFoam's cost per step from its own clock (ExecutionTime, CPU), first to last step, so that
# its start-up is not counted (ours' fluid time excludes start-up too)
pimple_step=$(awk '/^ExecutionTime/ { n++; t = $3; if (n == 1) t1 = $3 } END { print (n > 1 ? (t - t1) / (n - 1) : t) }' "$work/pimple/log.run")
fi

# --- ratios
awk -v d="$dem" -v c="$cpl" -v f="$fluid" -v t="$total" 'BEGIN {
    printf "RESULT ours_split_percent DEM %.1f coupling %.1f fluid %.1f\n", 100 * d / t, 100 * c / t, 100 * f / t }'
[ $do_pimple = 1 ] && awk -v f="$fluid" -v n="$nfluid" -v p="$pimple_step" 'BEGIN {
    printf "RESULT fluid_step_ms ours %.2f pimpleFoam %.2f ratio_ours_over_pimpleFoam %.2f\n", 1e3 * f / n, 1e3 * p, (f / n) / p }'
if [ $do_cellpoint = 1 ]; then
    awk -v a="$cpl_cp" -v b="$cpl" 'BEGIN { printf "RESULT coupling_cellPoint_over_cell %.2f (%.2f s / %.2f s)\n", a / b, a, b }'
fi
if [ $do_dpm = 1 ]; then
    awk -v dw="$(secs "$work/dpm" wall)" -v dc="$(secs "$work/dpm" cpu)" -v ow="$(secs "$work/ours" wall)" \
        -v oc="$(secs "$work/ours" cpu)" 'BEGIN {
        printf "RESULT ratio_DPMFoam_over_ours wall %.1f cpu %.1f\n", dw / ow, dc / oc }'
fi
