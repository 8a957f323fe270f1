#!/bin/bash
# badInput-monitorAndSwitches <runDir>: a packingMonitor naming a cloud that
# does not exist, one with closePackFraction 1.5, one with writePackingForce
# maybe, writePackingForce true with writeInterval 10 and with writeControl
# runTime (the field sums every step), and coloringFunction with
# case1a maybe -> FatalIOError naming the keyword (and the range), exit
# status 1, no crash (mppicPimpleFoam); likewise capacityLimit perhaps and
# solidsFractionFrom maybe (the message lists cell and averaging); the
# solver's PIMPLE switches faceInterpolatedDrag maybe,
# superficialFluxCoupling maybe and balanceImplicitDrag maybe, both face
# coefficients true (at most one), and balanceImplicitDrag true with the
# cloud's U coupled explicitly (nothing to balance: the error names the
# keyword and semiImplicit); a misspelt PIMPLE keyword,
# superficialFluxCoupeling (the message lists the valid keywords, the
# solver's own and pimpleControl's; stopped before the first step);
# superficialFluxCoupling true with ddtSchemes backward (Euler only).
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
case="$runDir/case"
status=0

# monitorStops "<entries>" <words...>: a packingMonitor with these entries
# stops the run with a FatalIOError that names the words
monitorStops()
{
    local entries="$1"
    shift
    setEntry "$case" system/controlDict functions/monitor \
        "{ type packingMonitor; libs (\"libmppicModels.so\"); $entries }"
    runBroken "$case" mppicPimpleFoam
    check fatal "$case/log.broken" $rc "$@"
}

monitorStops "cloud noSuchCloud;" "cloud" "noSuchCloud" || status=1
monitorStops "closePackFraction 1.5;" "closePackFraction" "1.5" "(0, 1)" \
    || status=1
monitorStops "writePackingForce maybe;" "writePackingForce" "maybe" || status=1
monitorStops "writePackingForce true; writeInterval 10;" \
    "writeInterval" "10" "allowed: 1" || status=1
monitorStops \
    "writePackingForce true; writeControl runTime; writeInterval 0.1;" \
    "writeControl" "runTime" "timeStep" || status=1

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

setEntry "$case" system/fvSolution PIMPLE/faceInterpolatedDrag true
setEntry "$case" system/fvSolution PIMPLE/superficialFluxCoupling true
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "faceInterpolatedDrag" \
    "superficialFluxCoupling" "at most one" || status=1

foamDictionary "$case/system/fvSolution" \
    -entry PIMPLE/faceInterpolatedDrag -remove > /dev/null
setEntry "$case" system/fvSolution PIMPLE/superficialFluxCoupling maybe
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "superficialFluxCoupling" "maybe" || status=1

foamDictionary "$case/system/fvSolution" \
    -entry PIMPLE/superficialFluxCoupling -remove > /dev/null
setEntry "$case" system/fvSolution PIMPLE/balanceImplicitDrag maybe
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "balanceImplicitDrag" "maybe" || status=1

setEntry "$case" system/fvSolution PIMPLE/balanceImplicitDrag true
setEntry "$case" constant/kinematicCloudProperties \
    solution/sourceTerms/schemes/U "explicit 1"
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "balanceImplicitDrag" "semiImplicit" || status=1

foamDictionary "$case/system/fvSolution" \
    -entry PIMPLE/balanceImplicitDrag -remove > /dev/null
setEntry "$case" system/fvSolution PIMPLE/superficialFluxCoupeling true
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "unknown keyword superficialFluxCoupeling" \
    "superficialFluxCoupling" "nOuterCorrectors" || status=1
stoppedBeforeFirstStep "$case/log.broken" $rc || status=1

foamDictionary "$case/system/fvSolution" \
    -entry PIMPLE/superficialFluxCoupeling -remove > /dev/null
setEntry "$case" system/fvSolution PIMPLE/superficialFluxCoupling true
setEntry "$case" system/fvSchemes ddtSchemes/default backward
runBroken "$case" mppicPimpleFoam
check fatal "$case/log.broken" $rc "ddtSchemes" "backward" \
    "superficialFluxCoupling supports Euler only" || status=1

exit $status
