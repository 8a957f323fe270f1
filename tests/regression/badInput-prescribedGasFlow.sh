#!/bin/bash
# badInput-prescribedGasFlow <runDir>: constant/prescribedGasFlowProperties
# with an unknown type -> FatalIOError naming it and listing the valid
# types; then the vortex with period 0 -> FatalIOError naming the keyword,
# the value and the allowed range; non-zero exit, no crash.
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
props="$runDir/case/constant/prescribedGasFlowProperties"
header='FoamFile { version 2.0; format ascii; class dictionary; object prescribedGasFlowProperties; }'

echo "$header type noSuchFlow;" > "$props"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc \
    "noSuchFlow" "vortex" "uniform" "prescribedGasFlowProperties" || exit 1

echo "$header type vortex; period 0;" > "$props"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc \
    "period" "value 0" "(0, inf)" "prescribedGasFlowProperties" || exit 1

echo "$header type vortex; period 0.25; length -1;" > "$props"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc \
    "length" "value -1" "(0, inf)" "prescribedGasFlowProperties"
