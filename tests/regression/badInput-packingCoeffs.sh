#!/bin/bash
# badInput-packingCoeffs <runDir>: coloringFunction with e1 = 1.5, then
# with impulse sideways -> FatalIOError naming the keyword and the allowed
# range or names; coloringFunction with randomVelocity 0 and both models
# with overfill 0.5, pushThrough true, followDrainingPacks true,
# supportAngle 40, freePackReactionsToGas true (removed keywords; the
# first two fixed at their old defaults, the next three part of the
# defaults) and coloringFunction with packAtClosePack true -> FatalIOError
# naming the unknown keyword;
# both models with conserveMomentum true (a switch before, now none,
# packs or gas) -> FatalIOError naming conserveMomentum, true and the
# three values; mfixSnider with conserveMomentum gas -> FatalIOError
# naming conserveMomentum, gas and mfixSnider;
# both models with a misspelt keyword (holdSupportedPack) -> FatalIOError
# naming it and listing the valid ones (holdSupportedPacks among them);
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

# A misspelt keyword (DensePackingModel's check of every entry)
brokenInBoth "holdSupportedPack true;" "unknown keyword holdSupportedPack" \
    "holdSupportedPacks" "closePackFraction"

# Removed keywords are unknown: overfill (fixed at 0.5: cellRoom);
# push-through, the drain and the support angle are part of the limit
for entry in "overfill 0.5;" "pushThrough true;" "followDrainingPacks true;" \
    "supportAngle 40;" "freePackReactionsToGas true;"
do
    brokenInBoth "$entry" "unknown keyword ${entry%% *}"
done
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/packingModel coloringFunction
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/coloringFunctionCoeffs "{ closePackFraction 0.6; packAtClosePack true; }"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "unknown keyword packAtClosePack" \
    || status=1

# conserveMomentum takes none, packs or gas (DensePackingModel)
brokenInBoth "conserveMomentum true;" "conserveMomentum" "true" \
    "none" "packs" "gas"

# the packs' reactions to the gas are coloringFunction's: mfixSnider
# refuses them
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/packingModel mfixSnider
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/mfixSniderCoeffs "{ closePackFraction 0.6; conserveMomentum gas; }"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "conserveMomentum" "gas" \
    "mfixSnider" || status=1
exit $status
