#!/bin/bash
#------------------------------------------------------------------------------
# badInput-positions <runDir>: two of the manualInjection's positions
# (constant/kinematicCloudPositions, elements 4 and 8 of 3200) moved outside
# the mesh -> mppicPimpleFoam stops before the first step with a
# FatalIOError naming the keyword positionsFile, the file, how many are
# outside and the first, exit status 1 (cloudInputChecks::
# injectionPositions; OpenFOAM names the first position only). With
# ignoreOutOfBounds yes the run goes on and OpenFOAM drops the two.
# (the two positions moved by badInput-positions.py)
#------------------------------------------------------------------------------
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/prepared"
status=0
case="$runDir/outside"
rm -rf "$case"
cp -r "$runDir/prepared" "$case"

/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/badInput-positions.py" \
    "$case/constant/kinematicCloudPositions"

runBroken "$case" mppicPimpleFoam > /dev/null
sed -n '/FOAM FATAL/,/^$/p' "$case/log.broken"
check fatal "$case/log.broken" $rc "keyword positionsFile" \
    "constant/kinematicCloudPositions" "2 of 3200 positions" \
    "outside the mesh" "element 4" "(0.5 0.2 0.0025)" || status=1
stoppedBeforeFirstStep "$case/log.broken" $rc || status=1

setEntry "$case" constant/kinematicCloudProperties \
    subModels/injectionModels/lattice/ignoreOutOfBounds yes
(cd "$case" && mppicPimpleFoam > log.ignored 2>&1)
rc=$?
if [ $rc = 0 ] && grep -q "2 particles ignored, out of bounds" "$case/log.ignored"
then
    echo "PASS ignoreOutOfBounds yes: runs, OpenFOAM drops the 2 positions"
else
    echo "FAIL ignoreOutOfBounds yes: exit status $rc (log.ignored)"
    status=1
fi

exit $status
