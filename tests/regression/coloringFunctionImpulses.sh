#!/bin/bash
#------------------------------------------------------------------------------
# coloringFunctionImpulses <runDir>
# tutorials/verification/sedimentation (1 s, about 50 s a run) with
# coloringFunction's other three impulses, capacityLimit left at its default
# (true, which acts with impulse neighbour only): impulse gradient (seed 1
# eq 19 on the averaging's gradient), impulse faceGradient (MFiX-PIC's
# face gradient from the parcel's own cell) and impulse cornerNodeGradient
# (the same brought through the cell corners, as MFiX's GARG_2012, on the
# averagingMethod cornerNodes field as MFiX pairs them: measured 0.0375 m;
# on the cell counts (basic) the bed settles at 0.48 and 0.0451 m). Before 2026-11-26 faceGradient with the capacity limit
# stopped at its first step (the packing field unallocated): FAIL here.
# Checks for each: the run ends; checks: coloringFunctionImpulses.py (2400
# parcels and the cloud mass at the end; the final bed height within 10 % of
# the inventory height 0.0375 m).
#------------------------------------------------------------------------------
runDir="${1:?usage: coloringFunctionImpulses.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
for impulse in gradient faceGradient cornerNodeGradient
do
    case="$runDir/$impulse"
    copyTutorial verification/sedimentation "$case"
    sed -i "s/^\( *e2 \+0.9; .*\)$/\1\n        impulse         $impulse;/" \
        "$case/constant/kinematicCloudProperties"
    grep -q "^ *impulse *$impulse;" "$case/constant/kinematicCloudProperties" \
        || { echo "FAIL impulse $impulse not set"; exit 1; }
    if [ "$impulse" = cornerNodeGradient ]
    then
        # MFiX-PIC's pairing: the corner gradient of the corner-node field
        sed -i 's/^\( *averagingMethod \+\)basic;/\1cornerNodes;/' \
            "$case/constant/kinematicCloudProperties"
        grep -q "^ *averagingMethod cornerNodes;" \
            "$case/constant/kinematicCloudProperties" \
            || { echo "FAIL averagingMethod not set"; exit 1; }
    fi
    runAllrun "$case" || { echo "FAIL impulse $impulse: the run stopped"; status=1; continue; }
    grep -q "^End" "$case/log.mppicPimpleFoam" \
        || { echo "FAIL impulse $impulse: no End in the log"; status=1; continue; }

    echo "impulse $impulse:"
    (cd "$case" && /usr/bin/python3 \
        "$MPPIC_PROJECT_DIR/tests/regression/coloringFunctionImpulses.py") || status=1
done
exit $status
