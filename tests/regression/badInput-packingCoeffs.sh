#!/bin/bash
# badInput-packingCoeffs <runDir>: coloringFunction with e1 = 1.5, then
# with impulse sideways -> FatalIOError naming the keyword and the allowed
# range or names; coloringFunction with randomVelocity 0.2 -> FatalIOError
# naming it, 0.2 and [0, 0.1]; coloringFunction and mfixSnider with overfill 1.5 ->
# FatalIOError naming overfill, 1.5 and [0, 1]; coloringFunction with
# pushThrough true on 2 processes -> FatalIOError naming pushThrough and
# "serial only"; exit status 1 (2 processes: mpirun's), no crash
# (mppicPimpleFoam).
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
    "{ closePackFraction 0.6; randomVelocity 0.2; }"
runBroken "$runDir/case" mppicPimpleFoam
check fatal "$runDir/case/log.broken" $rc "randomVelocity" "0.2" "[0, 0.1]" \
    || status=1

# overfill outside [0, 1] (CapacityLimit), both models
for model in coloringFunction mfixSnider
do
    setEntry "$runDir/case" constant/kinematicCloudProperties \
        subModels/packingModel $model
    setEntry "$runDir/case" constant/kinematicCloudProperties \
        subModels/${model}Coeffs "{ closePackFraction 0.6; overfill 1.5; }"
    runBroken "$runDir/case" mppicPimpleFoam
    check fatal "$runDir/case/log.broken" $rc "overfill" "1.5" "[0, 1]" \
        || status=1
done
# pushThrough: serial only for now (CapacityLimit)
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/packingModel coloringFunction
setEntry "$runDir/case" constant/kinematicCloudProperties \
    subModels/coloringFunctionCoeffs "{ closePackFraction 0.6; pushThrough true; }"
(cd "$runDir/case" && decomposePar -force > log.decomposePar 2>&1) || status=1
(cd "$runDir/case" && timeout 300 mpirun -np 2 mppicPimpleFoam -parallel \
    > log.broken 2>&1)
rc=$?
cat "$runDir/case/log.broken"
if [ $rc -ne 0 ] && grep -q "pushThrough" "$runDir/case/log.broken" \
    && grep -q "serial only" "$runDir/case/log.broken" \
    && grep -q "FOAM FATAL IO ERROR" "$runDir/case/log.broken" \
    && ! grep -q "^Time = " "$runDir/case/log.broken"
then
    echo "PASS pushThrough in parallel: FatalIOError naming it, serial only, exit status $rc"
else
    echo "FAIL pushThrough in parallel: exit status $rc, or the error does not name it"
    status=1
fi
exit $status
