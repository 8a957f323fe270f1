#!/bin/bash
# badInput-gasMassSources <runDir>: constant/gasMassSources with a radius of
# 0, a negative flow, a sphere that holds no cell centre, an entry that
# is not a sub-dictionary and a misspelt keyword (radus) -> FatalIOError naming the dictionary, the keyword
# (or source), the value and the allowed range; exit status 1 before the
# first time step, no crash.
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
sources="$runDir/case/constant/gasMassSources"
header='FoamFile { version 2.0; format ascii; class dictionary; object gasMassSources; }'
status=0

tryGasSource()   # text-of-the-sources-dictionary texts-to-find...
{
    echo "$header sources { $1 }" > "$sources"
    shift
    runBroken "$runDir/case" mppicPimpleFoam
    check fatal "$runDir/case/log.broken" $rc "gasMassSources" "$@" \
        || status=1
    stoppedBeforeFirstStep "$runDir/case/log.broken" $rc || status=1
}

tryGasSource "port { centre (0 0.1 0); radius 0; volumetricFlowRate 1e-4; }" \
    "radius" "value 0" "(0, inf)"
tryGasSource "port { centre (0 0.1 0); radius 0.01; volumetricFlowRate -1e-4; }" \
    "volumetricFlowRate" "value -0.0001" "[0, inf)"
tryGasSource "port { centre (5 5 5); radius 0.01; volumetricFlowRate 1e-4; }" \
    "no cell centre" "radius 0.01" "(5 5 5)"
tryGasSource "port 1e-4;" "port" "not a sub-dictionary"
tryGasSource "port { centre (0 0.1 0); radus 0.01; volumetricFlowRate 1e-4; }" \
    "unknown keyword radus" "radius"
rm -f "$sources"
exit $status
