#!/bin/bash
#------------------------------------------------------------------------------
# badInput-cloudSolution <runDir>: the solution dictionary of
# constant/kinematicCloudProperties broken one way at a time ->
# mppicPimpleFoam stops before the first step with a FatalIOError naming the
# keyword, the value and the allowed range or names, exit status 1
# (cloudInputChecks::solutionControls):
#   maxCo 0 (OpenFOAM: the first step never ends); averagingMethod dula
#   (OpenFOAM: aborts in the first step, exit 134); interpolationSchemes
#   U.air cellPiont and rho.air cel (OpenFOAM: exit 1 in the first step);
#   diffusionCoeffs with a misspelt bandwith (stops in the first step,
#   where the averaging is built); solidsSubCycling with a misspelt
#   maxSubCycle (unknown keyword, the valid ones listed).
#------------------------------------------------------------------------------
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/prepared"
status=0

tryBroken zeroMaxCo solution/maxCo 0 \
    "kinematicCloudProperties.solution" "keyword maxCo" "value 0" "(0, inf)"
tryBroken averagingMethodMisspelt solution/averagingMethod dula \
    "kinematicCloudProperties.solution" "keyword averagingMethod" \
    "value dula" "basic" "diffusion" "dual" "linearHat" "moment"
tryBroken vectorInterpolationMisspelt solution/interpolationSchemes/U.air \
    cellPiont "interpolationSchemes" "keyword U.air" "value cellPiont" \
    "cell" "cellPoint" "cellPointFace" "linearHat"
tryBroken scalarInterpolationMisspelt solution/interpolationSchemes/rho.air \
    cel "interpolationSchemes" "keyword rho.air" "value cel" "cellPoint"
foamDictionary "$runDir/prepared/constant/kinematicCloudProperties" \
    -entry solution/averagingMethod -set diffusion > /dev/null
# (the averaging is built in the first step: no stoppedBeforeFirstStep)
foamDictionary "$runDir/prepared/constant/kinematicCloudProperties" \
    -entry solution/diffusionCoeffs -set "{ bandwith 0.01; bandwidth 0.01; }" \
    > /dev/null
runBroken "$runDir/prepared" mppicPimpleFoam > /dev/null
check fatal "$runDir/prepared/log.broken" $rc "diffusionCoeffs" \
    "unknown keyword bandwith" "bandwidth" "nSteps" || status=1
[ $rc = 1 ] || { echo "FAIL exit status $rc, not 1"; status=1; }
foamDictionary "$runDir/prepared/constant/kinematicCloudProperties" \
    -entry solution/averagingMethod -set dual > /dev/null
tryBroken subCyclingMisspelt solidsSubCycling \
    "{ active true; maxSubCycle 10; }" "solidsSubCycling" \
    "unknown keyword maxSubCycle" "maxSubCycles" "relaxationTimeFactor"

exit $status
