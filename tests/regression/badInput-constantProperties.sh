#!/bin/bash
#------------------------------------------------------------------------------
# badInput-constantProperties <runDir>: constantProperties in
# constant/kinematicCloudProperties broken one way at a time ->
# mppicPimpleFoam stops before the first step with a FatalIOError naming the
# keyword, the value and the allowed range, exit status 1
# (cloudInputChecks::constantProperties):
#   rho0 0 (OpenFOAM: floating-point exception in the drag, exit 136);
#   rho0 -2500 (OpenFOAM runs on); alphaMax 1.5 and alphaMax 0 (the
#   solvers ran on with a gas fraction bounded by -0.5 or by 1).
#------------------------------------------------------------------------------
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/prepared"
status=0

tryBroken zeroDensity constantProperties/rho0 0 \
    "constantProperties" "keyword rho0" "value 0" "(0, inf)"
tryBroken negativeDensity constantProperties/rho0 -2500 \
    "constantProperties" "keyword rho0" "value -2500" "(0, inf)"
tryBroken alphaMaxAboveOne constantProperties/alphaMax 1.5 \
    "constantProperties" "keyword alphaMax" "value 1.5" "(0, 1]"
tryBroken alphaMaxZero constantProperties/alphaMax 0 \
    "constantProperties" "keyword alphaMax" "value 0" "(0, 1]"

exit $status
