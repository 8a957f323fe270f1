#!/bin/bash
#------------------------------------------------------------------------------
# parallelCapacityLimit <runDir>
# processes: 2 (MPI ranks at most; tests/Alltest runs it alone)
# The capacity limit makes serial's decisions on any decomposition
# (ParcelEntries.H): tutorials/circulatingFluidizedBed with -packing
# mfixSnider (diffusion averaging), capacityLimit refuse instead of the
# case's push (push-through's chains stay on their processor), the gas solved to 1e-13, run serially
# from the seeded start (riser bed and standpipe packed) to 0.01 s; from its
# written 0.005 s, on serially and on 2 ranks (simple (2 1 1), a cut near
# x = 0.11 through the crossover, cyclone and L-valve) to 0.01 s, 15 steps
# of entrants into full cells. Checks at 0.01 s:
#   - the same parcels (origProcId, origId), each at the same place to
#     1e-6 m and with the same velocity to 1e-4 m/s (measured when written,
#     four runs, four meshes: at most 1.4e-9 m and 8.0e-7 m/s, round-off
#     grown over 15 steps); with the build before entrants of equal depth
#     (all that came from one cell) were ranked by pushOrderKey, the order
#     of the parcel list decided which a full cell took: 17 895 of
#     18 206 parcels more than 1e-9 m apart, 1286 more than 1e-6 m, up to
#     3.2 mm and 0.40 m/s (main's tutorial, the build of 06eae10): the check
#     can fail;
#   - alpha.air within 1e-6 and U.air within 1e-5 of the serial run's (each
#     column scaled by its largest magnitude; measured 0 and up to 7.9e-8;
#     the build of 06eae10: 0.054 and 0.080).
#------------------------------------------------------------------------------
runDir="${1:?usage: parallelCapacityLimit.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

start="$runDir/start"
copyTutorial circulatingFluidizedBed "$start"
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
/usr/bin/python3 - <<'PY' || status=1
import os, sys
import checks
from checks import report as check, read_rows

def cloud(run):
    d = os.path.join(run, "0.01", "lagrangian", "kinematicCloud")
    ids = zip((r[0] for r in read_rows(os.path.join(d, "origProcId"))),
              (r[0] for r in read_rows(os.path.join(d, "origId"))))
    rows = zip(read_rows(os.path.join(d, "positions")), read_rows(os.path.join(d, "U")))
    return {k: (pos[:3], U) for k, (pos, U) in zip(ids, rows)}

s, p = cloud("serial"), cloud("parallel")
check(len(s) > 10000 and set(s) == set(p),
      "the same %d parcels (origProcId, origId) serial and on 2 ranks (%d)" % (len(s), len(p)))
common = [k for k in s if k in p]
dx = max(max(abs(a - b) for a, b in zip(s[k][0], p[k][0])) for k in common)
dU = max(max(abs(a - b) for a, b in zip(s[k][1], p[k][1])) for k in common)
check(dx <= 1e-6, "each parcel at the serial run's place: largest difference %.3g m <= 1e-6" % dx)
check(dU <= 1e-4, "each parcel with the serial run's velocity: largest difference %.3g m/s <= 1e-4" % dU)
sys.exit(checks.status())
PY
exit $status
