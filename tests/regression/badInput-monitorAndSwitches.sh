#!/bin/bash
# badInput-monitorAndSwitches <runDir>: a packingMonitor naming a cloud that
# does not exist, one with closePackFraction 1.5, one with writePackingForce
# maybe, writePackingForce true with writeInterval 10 and with writeControl
# runTime (the field sums every step), and coloringFunction with
# case1a maybe -> FatalIOError naming the keyword (and the range), exit
# status 1, no crash (mppicPimpleFoam); likewise capacityLimit perhaps and
# solidsFractionFrom maybe (the message lists cell and averaging); the
# solver's PIMPLE switches faceInterpolatedDrag maybe and gasVelocityFromFlux
# perhaps.
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
case="$runDir/case"
status=0

setEntry "$case" system/controlDict functions/monitor \
    "{ type packingMonitor; libs (\"libmppicModels.so\"); cloud noSuchCloud; }"
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "cloud" "noSuchCloud" || status=1

setEntry "$case" system/controlDict functions/monitor \
    "{ type packingMonitor; libs (\"libmppicModels.so\"); closePackFraction 1.5; }"
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "closePackFraction" "1.5" "(0, 1)" || status=1

setEntry "$case" system/controlDict functions/monitor \
    "{ type packingMonitor; libs (\"libmppicModels.so\"); writePackingForce maybe; }"
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "writePackingForce" "maybe" || status=1

setEntry "$case" system/controlDict functions/monitor \
    "{ type packingMonitor; libs (\"libmppicModels.so\"); writePackingForce true; writeInterval 10; }"
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "writeInterval" "10" "allowed: 1" || status=1

setEntry "$case" system/controlDict functions/monitor \
    "{ type packingMonitor; libs (\"libmppicModels.so\"); writePackingForce true; writeControl runTime; writeInterval 0.1; }"
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "writeControl" "runTime" "timeStep" || status=1

foamDictionary "$case/system/controlDict" -entry functions/monitor -remove > /dev/null
setEntry "$case" constant/kinematicCloudProperties \
    subModels/packingModel coloringFunction
setEntry "$case" constant/kinematicCloudProperties \
    subModels/coloringFunctionCoeffs "{ closePackFraction 0.6; case1a maybe; }"
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "case1a" "maybe" || status=1

setEntry "$case" constant/kinematicCloudProperties \
    subModels/coloringFunctionCoeffs \
    "{ closePackFraction 0.6; capacityLimit perhaps; }"
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "capacityLimit" "perhaps" || status=1

foamDictionary "$case/constant/kinematicCloudProperties" \
    -entry subModels/coloringFunctionCoeffs -remove > /dev/null
setEntry "$case" constant/kinematicCloudProperties subModels/packingModel explicit
setEntry "$case" constant/kinematicCloudProperties solidsFractionFrom maybe
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "solidsFractionFrom" "maybe" "cell" "averaging" \
    || status=1

foamDictionary "$case/constant/kinematicCloudProperties" \
    -entry solidsFractionFrom -remove > /dev/null
setEntry "$case" system/fvSolution PIMPLE/faceInterpolatedDrag maybe
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "faceInterpolatedDrag" "maybe" || status=1

foamDictionary "$case/system/fvSolution" \
    -entry PIMPLE/faceInterpolatedDrag -remove > /dev/null
setEntry "$case" system/fvSolution PIMPLE/gasVelocityFromFlux perhaps
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "gasVelocityFromFlux" "perhaps" || status=1

exit $status
