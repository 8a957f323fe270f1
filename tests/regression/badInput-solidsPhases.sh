#!/bin/bash
# badInput-solidsPhases <runDir>: the solids phases of a mixture, broken one
# entry at a time on tutorials/verification/bidisperseSedimentation (meshed
# and run for one step first); each stops with exit status 1 and a
# FatalIOError naming the keyword and the value:
#   mppicSeedParcels (system/mppicSeedParcelsDict):
#     - the phases' volumeFraction adding up to 1.1, not 1;
#     - a phase's diameter 0 (range (0, inf));
#     - a phase that places no parcel (statisticalWeight 1e12);
#     - a misspelt keyword in a phase (diametr);
#     - mixing stirred (mixed or layered); layerDirection (0 0 0);
#   mppicPimpleFoam (constant/kinematicCloudProperties, before the first step):
#     - a phase's density rho -2000 (range (0, inf));
#     - a phase index 0 (range [1, inf)) and 1.5 (an integer);
#     - an injectorID other than the phase.
. "${0%/*}/badInputFunctions"
runDir="${1:?}"
prepared="$runDir/prepared"
copyTutorial verification/bidisperseSedimentation "$prepared"
setEntry "$prepared" system/controlDict endTime 0.0005
runAllrun "$prepared" || exit 1
rm -rf "$prepared"/0.0*

status=0

# broken <name> <file> <application> <sed expression> <texts...>: a copy of
# the prepared case with <file> edited, run with <application>: exit status
# 1, a FatalIOError with the texts, and (the solver) no time step begun
broken()
{
    local name="$1" file="$2" application="$3" expression="$4"
    shift 4
    local dir="$runDir/$name"
    rm -rf "$dir"
    cp -r "$prepared" "$dir"
    sed -i "$expression" "$dir/$file"
    echo "== $name"
    runBroken "$dir" "$application" > /dev/null
    sed -n '/FOAM FATAL/,/^$/p' "$dir/log.broken" | sed -n 1,5p
    check fatal "$dir/log.broken" $rc "$@" || status=1
    stoppedBeforeFirstStep "$dir/log.broken" $rc || status=1
}

brokenSeeding()
{
    broken "$1" system/mppicSeedParcelsDict mppicSeedParcels "${@:2}"
}

brokenCloud()
{
    broken "$1" constant/kinematicCloudProperties mppicPimpleFoam "${@:2}"
}

brokenSeeding fractionsSum \
    '/small/,/}/s/^\( *volumeFraction\) .*/\1 0.6;/' \
    "volumeFraction" "add up to 1.1" "not 1"
brokenSeeding zeroDiameter \
    '/small/,/}/s/^\( *diameter\) .*/\1 0;/' \
    "keyword diameter" "value 0" "(0, inf)"
brokenSeeding phaseWithoutParcels \
    '/small/,/}/s/^\( *parcelsPerCell\) .*/    statisticalWeight 1e12;/' \
    "phases.small" "no parcel placed"
brokenSeeding unknownMixing \
    's/^mixing .*/mixing          stirred;/' \
    "keyword mixing" "stirred" "mixed" "layered"
brokenSeeding zeroLayerDirection \
    's/^mixing .*/mixing          layered;\nlayerDirection  (0 0 0);/' \
    "keyword layerDirection" "(0 0 0)" "must not be zero"
brokenSeeding misspeltKeyword \
    '/small/,/}/s/^\( *\)diameter /\1diametr /' \
    "unknown keyword diametr" "volumeFraction"

brokenCloud negativeDensity \
    '/^ *large$/,/sizeDistribution/s/^\( *rho\) .*/\1 -2000;/' \
    "keyword rho" "value -2000" "(0, inf)"
brokenCloud phaseZero \
    '/^ *small$/,/sizeDistribution/s/^\( *phase\) .*/\1 0;/' \
    "keyword phase" "value 0" "[1, inf)"
brokenCloud phaseNotInteger \
    '/^ *small$/,/sizeDistribution/s/^\( *phase\) .*/\1 1.5;/' \
    "keyword phase" "value 1.5" "integer"
brokenCloud injectorID \
    '/^ *small$/,/sizeDistribution/s/^\( *\)phase .*/&\n\1injectorID 7;/' \
    "keyword injectorID" "value 7" "phase's index 2"

exit $status
