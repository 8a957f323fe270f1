#!/bin/bash
#------------------------------------------------------------------------------
# badInput-cloudSolution <runDir>: the solution dictionary of
# constant/kinematicCloudProperties broken one way at a time ->
# mppicPimpleFoam stops before the first step with a FatalIOError naming the
# keyword, the value and the allowed range or names, exit status 1
# (cloudInputChecks::solutionControls):
#   maxCo 0 (OpenFOAM: the first step never ends); averagingMethod dula
#   (OpenFOAM: aborts in the first step, exit 134); interpolationSchemes
#   U.air cellPiont and rho.air cel (OpenFOAM: exit 1 in the first step).
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

exit $status
