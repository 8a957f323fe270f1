#!/bin/bash
#------------------------------------------------------------------------------
# coloringFunctionMPPICFoam <runDir>
# Stock MPPICFoam selects packingModel coloringFunction and the
# packingMonitor function object from libmppicModels (libs in controlDict):
# the sedimentation case for 0.05 s (250 steps) ends normally; checks:
# coloringFunctionMPPICFoam.py (the monitor MPPICFoam wrote: a row a step,
# the 2400 seeded parcels and the seeded mass).
#------------------------------------------------------------------------------
runDir="${1:?usage: coloringFunctionMPPICFoam.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial verification/sedimentation "$runDir/case"
setEntry "$runDir/case" system/controlDict application MPPICFoam
setEntry "$runDir/case" system/controlDict endTime 0.05
runAllrun "$runDir/case" || exit 1
grep -q '^End' "$runDir/case/log.MPPICFoam" || { echo "MPPICFoam did not end"; exit 1; }
grep -q 'Selecting packing model coloringFunction' "$runDir/case/log.MPPICFoam" \
    || { echo "coloringFunction not selected"; exit 1; }

/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/coloringFunctionMPPICFoam.py" \
    "$runDir/case"
