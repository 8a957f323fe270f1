#!/bin/bash
#------------------------------------------------------------------------------
# badInput-injectionAmounts <runDir>: the injection model's massTotal -1,
# then parcelsPerSecond -10 in constant/kinematicCloudProperties ->
# mppicPimpleFoam stops before the first step with a FatalIOError naming the
# keyword, the value and the range [0, inf), exit status 1
# (cloudInputChecks::injectionAmounts; OpenFOAM runs on with either).
#------------------------------------------------------------------------------
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/prepared"
status=0
injector=subModels/injectionModels/lattice

tryBroken negativeMassTotal $injector/massTotal -1 \
    "injectionModels.lattice" "keyword massTotal" "value -1" "[0, inf)"
tryBroken negativeParcelsPerSecond $injector/parcelsPerSecond -10 \
    "injectionModels.lattice" "keyword parcelsPerSecond" "value -10" \
    "[0, inf)"

exit $status
