#!/bin/bash
# badInput-missingKey <runDir>: constantProperties/rho0 removed from
# constant/kinematicCloudProperties -> FatalIOError naming the file and the
# keyword, non-zero exit, no crash.
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
foamDictionary "$runDir/case/constant/kinematicCloudProperties" \
    -entry constantProperties/rho0 -remove > /dev/null
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "rho0" "kinematicCloudProperties"
