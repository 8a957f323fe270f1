#!/bin/bash
# badInput-packingCoeffs <runDir>: coloringFunction with e1 = 1.5, then
# with impulse sideways -> FatalIOError naming the keyword and the allowed
# range or names; coloringFunction with randomVelocity 0 and both models
# with overfill 0.5 (removed keywords) -> FatalIOError naming the unknown
# keyword; coloringFunction with pushThrough sometimes -> FatalIOError
# naming pushThrough and sometimes;
# coloringFunction with packAtClosePack sometimes -> the same for it;
# coloringFunction and mfixSnider with followDrainingPacks true but
# holdSupportedPacks false -> FatalIOError naming followDrainingPacks, true
# and holdSupportedPacks (the drain acts on held packs only); both models
# with freePackReactionsToGas true but conserveMomentum false ->
# FatalIOError naming freePackReactionsToGas, true and conserveMomentum;
# coloringFunction with freePackReactionsToGas sometimes -> FatalIOError
# naming it and sometimes;
# mfixSnider with freePackReactionsToGas true (and conserveMomentum) ->
# FatalIOError naming freePackReactionsToGas, true and mfixSnider;
# both models with a misspelt keyword (pushThru) -> FatalIOError naming it
# and listing the valid ones (pushThrough among them);
# exit status 1 (both models' cases), no crash (mppicPimpleFoam).
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
props="$runDir/case/constant/kinematicCloudProperties"
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/packingModel coloringFunction
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/coloringFunctionCoeffs "{ closePackFraction 0.6; e1 1.5; }"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "e1" "1.5" "[0, 1]" || exit 1

setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/coloringFunctionCoeffs \
    "{ closePackFraction 0.6; impulse sideways; }"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "sideways" "impulse" "neighbour"
status=$?

setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/coloringFunctionCoeffs \
    "{ closePackFraction 0.6; randomVelocity 0; }"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "unknown keyword randomVelocity" \
    || status=1

# Both models with the given entries stop naming the given words:
# brokenInBoth <entries> <word>...
brokenInBoth()
{
    local model entries="$1"
    shift
    for model in coloringFunction mfixSnider
    do
        setEntry "$runDir/case" constant/kinematicCloudProperties \
            subModels/packingModel $model
        setEntry "$runDir/case" constant/kinematicCloudProperties \
            subModels/${model}Coeffs "{ closePackFraction 0.6; $entries }"
        runBroken "$runDir/case" mppicPimpleFoam
        check fatal "$runDir/case/log.broken" $rc "$@" || status=1
        [ $rc = 1 ] || { echo "FAIL $model: exit status $rc, not 1"; status=1; }
    done
}

# A misspelt keyword (MfixPackingModel's check of every entry)
brokenInBoth "pushThru true;" "unknown keyword pushThru" "pushThrough" \
    "closePackFraction"

# overfill, removed (fixed at 0.5: cellRoom), is unknown
brokenInBoth "overfill 0.5;" "unknown keyword overfill"

# pushThrough not a switch (read by CapacityLimit)
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/packingModel coloringFunction
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/coloringFunctionCoeffs "{ closePackFraction 0.6; pushThrough sometimes; }"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "pushThrough" "sometimes" || status=1
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/coloringFunctionCoeffs "{ closePackFraction 0.6; packAtClosePack sometimes; }"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "packAtClosePack" "sometimes" || status=1
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/coloringFunctionCoeffs "{ closePackFraction 0.6; conserveMomentum true; freePackReactionsToGas sometimes; }"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "freePackReactionsToGas" "sometimes" \
    || status=1

# followDrainingPacks without held packs (CapacityLimit)
brokenInBoth "holdSupportedPacks false; followDrainingPacks true;" \
    "followDrainingPacks" "true" "holdSupportedPacks"

# freePackReactionsToGas without conserveMomentum (MfixPackingModel)
brokenInBoth "freePackReactionsToGas true;" \
    "freePackReactionsToGas" "true" "conserveMomentum"

# freePackReactionsToGas is coloringFunction's: mfixSnider refuses it
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/packingModel mfixSnider
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/mfixSniderCoeffs \
    "{ closePackFraction 0.6; conserveMomentum true; freePackReactionsToGas true; }"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "freePackReactionsToGas" "true" \
    "mfixSnider" || status=1
exit $status
