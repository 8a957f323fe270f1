#!/bin/bash
#------------------------------------------------------------------------------
# parallelCapacityLimit <runDir>
# processes: 2 (MPI ranks at most; tests/Alltest runs it alone)
# The capacity limit makes serial's decisions on any decomposition
# (ParcelEntries.H): tutorials/validation/circulatingFluidizedBed with -packing
# mfixSnider (diffusion averaging), capacityLimit refuse instead of the
# case's push (push-through's chains stay on their processor), the gas solved to 1e-13, run serially
# from the seeded start (riser bed and standpipe packed) to 0.01 s; from its
# written 0.005 s, on serially and on 2 ranks (simple (2 1 1), a cut near
# x = 0.11 through the crossover, cyclone and L-valve) to 0.01 s, 15 steps
# of entrants into full cells. Checks at 0.01 s:
#   - parallelCapacityLimit.py: the same parcels (origProcId, origId), each
#     at the same place to 1e-6 m and with the same velocity to 1e-4 m/s;
#   - alpha.air within 1e-6 and U.air within 1e-5 of the serial run's (each
#     column scaled by its largest magnitude; measured 0 and up to 7.9e-8;
#     the build of 06eae10: 0.054 and 0.080).
#------------------------------------------------------------------------------
runDir="${1:?usage: parallelCapacityLimit.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

start="$runDir/start"
copyTutorial validation/circulatingFluidizedBed "$start"
sed -i '/mfixSniderCoeffs/,/}/s/^\( *capacityLimit \+\)push;/\1refuse;/' \
    "$start/constant/kinematicCloudProperties"
[ "$(grep -c 'capacityLimit *refuse;' "$start/constant/kinematicCloudProperties")" = 1 ] \
    || { echo "capacityLimit not set to refuse"; exit 1; }
tightGasSolvers "$start" || exit 1
PROGRESS_EVERY=0 runAllrun "$start" -packing mfixSnider -riserBed 0.16 \
    -standpipeLevel 0.576 -equalArea -endTime 0.01 || exit 1
[ -d "$start/0.005/lagrangian" ] || { echo "no cloud written at 0.005 s"; exit 1; }

for mode in serial parallel
do
    dir="$runDir/$mode"
    mkdir -p "$dir"
    cp -r "$start/constant" "$start/system" "$start/0" "$start/0.005" "$dir"/
    sed -i -e 's/^startFrom .*/startFrom       latestTime;/' \
        -e 's/^writeInterval .*/writeInterval   0.005;/' "$dir/system/controlDict"
done
sed -i 's/^method .*/method          simple;/' "$runDir/parallel/system/decomposeParDict"

(cd "$runDir/serial" && runApplication mppicPimpleFoam) || exit 1
(
    cd "$runDir/parallel" && runApplication decomposePar -time 0.005 \
 && runParallel mppicPimpleFoam && runApplication reconstructPar -newTimes
) || exit 1
for mode in serial parallel
do
    [ -d "$runDir/$mode/0.01/lagrangian" ] || { echo "no $mode cloud at 0.01 s"; exit 1; }
done

status=0
check sameState "$runDir/serial" "$runDir/parallel" 0.01 1e-6 alpha.air || status=1
check sameState "$runDir/serial" "$runDir/parallel" 0.01 1e-5 U.air || status=1
cd "$runDir" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/parallelCapacityLimit.py" || status=1
exit $status
