#!/bin/bash
#------------------------------------------------------------------------------
# gidaspowEqualsErgunWenYu <runDir>
# GidaspowDrag without blend is Ergun below gas fraction 0.8 and Wen-Yu
# above, which is OpenFOAM's ErgunWenYuDrag: the settling column run 10
# steps (0.005 s) with each. checks: gidaspowEqualsErgunWenYu.py (the same
# bed pressure drop at every step, to 1e-6 relative), then checks.py
# serialParallel (the same parcels and mass).
#------------------------------------------------------------------------------
runDir="${1:?usage: gidaspowEqualsErgunWenYu.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

for drag in ErgunWenYuDrag GidaspowDrag
do
    copyTutorial verification/settlingColumn "$runDir/$drag"
    setEntry "$runDir/$drag" system/controlDict endTime 0.005
    setEntry "$runDir/$drag" system/controlDict writeInterval 0.005
    setEntry "$runDir/$drag" constant/kinematicCloudProperties \
        subModels/particleForces "{ $drag { alphac alpha.air; } gravity; }"
    runAllrun "$runDir/$drag" || exit 1
done

/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/gidaspowEqualsErgunWenYu.py" "$runDir"
[ $? = 0 ] || exit 1
check serialParallel "$runDir/GidaspowDrag" "$runDir/ErgunWenYuDrag" 0.005
