#!/bin/bash
# badInput-cloudStep <runDir>: cloudStep misspelt (leen) in
# constant/kinematicCloudProperties -> mppicPimpleFoam stops before the first
# step with a FatalIOError naming the keyword, the value and the allowed
# values (lean, MPPICCloud), exit status 1 (LeanMPPICCloud).
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
echo "cloudStep leen;" >> "$runDir/case/constant/kinematicCloudProperties"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "cloudStep leen in" "allowed values 2(MPPICCloud lean)"
