#!/bin/bash
# badInput-statisticalWeight <runDir>: the injection model's nParticle (the
# statistical weight, parcelBasisType fixed) set to 0 in
# constant/kinematicCloudProperties -> mppicPimpleFoam stops with a
# FatalIOError naming the keyword, the value and the range (0, inf)
# (libmppicModels' cloudInputChecks; OpenFOAM would inject nothing, silently).
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
injector=$(foamDictionary "$runDir/case/constant/kinematicCloudProperties" \
    -entry subModels/injectionModels -keywords | head -1)
foamDictionary "$runDir/case/constant/kinematicCloudProperties" \
    -entry subModels/injectionModels/$injector/nParticle -set 0 > /dev/null
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "nParticle" "value 0" "(0, inf)"
