#!/bin/bash
# badInput-sniderCoeffs <runDir>: mfixSnider with pSolid -1, gamma -1,
# slipVelocityFactor 1.5, collisionDamping maybe, capacityLimit often,
# holdSupportedPacks rarely, releaseAbove 0.6 and 1.2 (outside
# (closePackFraction, 1]), supportPatches (nowhere), conserveMomentum
# perhaps, a misspelt keyword (colisionDamping) and removed ones
# (capFactor 1.15, supportAngle 40) -> FatalIOError naming the keyword and
# the value (or the allowed range or keywords; unknown keyword capFactor),
# exit status 1, no crash (mppicPimpleFoam).
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepareCase "$runDir/case"
case="$runDir/case"
status=0
setEntry "$case" constant/kinematicCloudProperties \
    subModels/packingModel mfixSnider

tryCoeffs()
{
    setEntry "$case" constant/kinematicCloudProperties \
        subModels/mfixSniderCoeffs "{ closePackFraction 0.6; $1 }"
    runBroken "$case" mppicPimpleFoam
    shift
    check fatal "$case/log.broken" $rc "$@" || status=1
}

tryCoeffs "pSolid -1;" "pSolid" "-1" "[0,"
tryCoeffs "gamma -1;" "gamma" "-1" "[0,"
tryCoeffs "slipVelocityFactor 1.5;" "slipVelocityFactor" "1.5" "[0, 1]"
tryCoeffs "capFactor 1.15;" "unknown keyword capFactor"
tryCoeffs "collisionDamping maybe;" "collisionDamping" "maybe"
tryCoeffs "capacityLimit often;" "capacityLimit" "often"
tryCoeffs "holdSupportedPacks rarely;" "holdSupportedPacks" "rarely"
tryCoeffs "supportAngle 40;" "unknown keyword supportAngle"
tryCoeffs "supportPatches (nowhere);" "supportPatches" "nowhere"
tryCoeffs "conserveMomentum perhaps;" "conserveMomentum" "perhaps" "packs"
tryCoeffs "releaseAbove 0.6;" "releaseAbove" "0.6" "(0.6, 1]"
tryCoeffs "releaseAbove 1.2;" "releaseAbove" "1.2" "(0.6, 1]"
tryCoeffs "colisionDamping true;" "colisionDamping" "collisionDamping"
exit $status
