#!/bin/bash
# badInput-unknownModel <runDir>: packingModel set to a name that does not
# exist -> FatalError naming the keyword and the bad name and listing the
# valid names (stock ones and ours), non-zero exit, no crash.
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/packingModel noSuchPackingModel
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc \
    "noSuchPackingModel" "packing" "explicit" "implicit" "kinematicCloudProperties"
