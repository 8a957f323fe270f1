#!/bin/bash
# badInput-dragCoeffs <runDir>: constantCdDrag with Cd = -1,
# linearRelaxationDrag with C = -5, GidaspowDrag with switchFraction 1.2,
# with blend maybe, constantCdDrag with feedback maybe, SyamlalOBrienDrag
# with c1 -1, GidaspowDrag with slipFrom average, GidaspowDrag
# with alphac naming no field, GidaspowDrag with a misspelt switchFractoin
# and StokesDrag with slipForm, BVKDrag with polydisperseCorrection
# Sauter -> FatalError naming the keyword and its range (or the field, or
# for a misspelling one of the valid keywords, or the value and the
# allowed values), exit status 1, no crash.
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
status=0
for bad in "constantCdDrag { Cd -1; }:Cd:[0, inf)" \
           "linearRelaxationDrag { C -5; }:C:[0, inf)" \
           "GidaspowDrag { alphac alpha.air; switchFraction 1.2; }:switchFraction:(0, 1)" \
           "GidaspowDrag { alphac alpha.air; blend maybe; }:blend:maybe" \
           "constantCdDrag { Cd 1; feedback maybe; }:feedback:maybe" \
           "SyamlalOBrienDrag { alphac alpha.air; c1 -1; }:c1:(0, inf)" \
           "GidaspowDrag { alphac alpha.air; slipFrom average; }:slipFrom:average" \
           "GidaspowDrag { alphac alpha.gas; }:alphac:alpha.gas" \
           "GidaspowDrag { alphac alpha.air; switchFractoin 0.8; }:unknown keyword switchFractoin:switchFraction" \
           "StokesDrag { alphac alpha.air; slipForm cellMean; }:unknown keyword slipForm:voidageExponent" \
           "BVKDrag { alphac alpha.air; polydisperseCorrection Sauter; }:keyword polydisperseCorrection:value Sauter is not one of 2(none Beetstra)"
do
    force="${bad%%:*}"
    rest="${bad#*:}"
    keyword="${rest%%:*}"
    range="${rest#*:}"
    setEntry "$runDir/case" constant/kinematicCloudProperties \
        subModels/particleForces "{ $force gravity; }"
    runBroken "$runDir/case" mppicPimpleFoam
    check fatal "$runDir/case/log.broken" $rc "$keyword" "$range" \
        || status=1
    [ $rc = 1 ] || { echo "FAIL exit status $rc, not 1"; status=1; }
done
exit $status
