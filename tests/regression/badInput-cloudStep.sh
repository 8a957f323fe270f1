#!/bin/bash
# badInput-cloudStep <runDir>: the lean cloud step's keywords in
# constant/kinematicCloudProperties (LeanMPPICCloud) -> mppicPimpleFoam stops
# before the first step with a FatalIOError naming the keyword, the value and
# what is allowed, exit status 1:
#   cloudStep misspelt (leen): allowed values lean, MPPICCloud;
#   sortParcelsEvery -1: allowed range integer >= 0.
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
status=0

cp -r "$runDir/case" "$runDir/step"
echo "cloudStep leen;" >> "$runDir/step/constant/kinematicCloudProperties"
runBroken "$runDir/step" mppicPimpleFoam
check fatal "$runDir/step/log.broken" $rc "cloudStep leen in" \
    "allowed values 2(MPPICCloud lean)" || status=1
stoppedBeforeFirstStep "$runDir/step/log.broken" $rc || status=1

cp -r "$runDir/case" "$runDir/sort"
echo "sortParcelsEvery -1;" >> "$runDir/sort/constant/kinematicCloudProperties"
runBroken "$runDir/sort" mppicPimpleFoam
check fatal "$runDir/sort/log.broken" $rc "sortParcelsEvery -1 in" \
    "allowed range integer >= 0" || status=1
stoppedBeforeFirstStep "$runDir/sort/log.broken" $rc || status=1
exit $status
