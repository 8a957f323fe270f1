#!/bin/bash
#------------------------------------------------------------------------------
# badInput-sizeDistribution <runDir>: the injection model's sizeDistribution
# in constant/kinematicCloudProperties broken one way at a time ->
# mppicPimpleFoam stops before the first step with a FatalIOError naming the
# keyword, the value and the allowed range, exit status 1
# (libmppicModels' cloudInputChecks::sizeDistributions):
#   fixedValue value -1e-4 (OpenFOAM: floating-point exception in the drag,
#   exit 136); uniform maxValue below minValue; RosinRammler n 0 and normal
#   variance 0 (OpenFOAM: floating-point exception sampling them);
#   general with a row of negative size.
#------------------------------------------------------------------------------
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/prepared"
status=0
sizes=subModels/injectionModels/lattice/sizeDistribution

tryBroken negativeDiameter $sizes/fixedValueDistribution/value -1e-4 \
    "fixedValueDistribution" "keyword value" "value -0.0001" "(0, inf)"
tryBroken maxBelowMin $sizes \
    "{ type uniform; uniformDistribution { minValue 2e-4; maxValue 1e-4; } }" \
    "uniformDistribution" "keyword maxValue" "value 0.0001" "[0.0002, inf)"
tryBroken zeroRosinRammlerN $sizes \
    "{ type RosinRammler; RosinRammlerDistribution
       { minValue 5e-5; maxValue 2e-4; d 1e-4; n 0; } }" \
    "RosinRammlerDistribution" "keyword n" "value 0" "(0, inf)"
tryBroken zeroNormalVariance $sizes \
    "{ type normal; normalDistribution
       { minValue 5e-5; maxValue 2e-4; expectation 1e-4; variance 0; } }" \
    "normalDistribution" "keyword variance" "value 0" "(0, inf)"
tryBroken negativeGeneralSize $sizes \
    "{ type general; generalDistribution
       { distribution ((-1e-4 1) (1e-4 1) (2e-4 1)); } }" \
    "generalDistribution" "keyword distribution" "row 0" "(-0.0001 1)" \
    "(0, inf)"

exit $status
