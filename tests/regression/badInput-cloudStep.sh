#!/bin/bash
# badInput-cloudStep <runDir>: the lean cloud step's keywords in
# constant/kinematicCloudProperties (LeanMPPICCloud) -> mppicPimpleFoam stops
# before the first step with a FatalIOError naming the keyword, the value and
# what is allowed, exit status 1:
#   cloudStep misspelt (leen): allowed values lean, MPPICCloud;
#   sortParcelsEvery -1: allowed range integer >= 0.
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/prepared"
status=0

tryBroken cloudStepMisspelt cloudStep leen \
    "cloudStep leen in" "allowed values 2(MPPICCloud lean)"
tryBroken negativeSortParcelsEvery sortParcelsEvery -1 \
    "sortParcelsEvery -1 in" "allowed range integer >= 0"
exit $status
