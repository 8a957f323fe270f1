#!/bin/bash
# badInput-missingField <runDir>: 0/U.air deleted -> FatalError naming the
# file, non-zero exit, no crash; for our solver and for stock MPPICFoam.
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
rm "$runDir/case/0/U.air"
ok=0
for solver in mppicPimpleFoam MPPICFoam
do
    runBroken "$runDir/case" $solver
    check fatal "$runDir/case/log.broken" $rc "U.air" "0/U.air" || ok=1
done
exit $ok
