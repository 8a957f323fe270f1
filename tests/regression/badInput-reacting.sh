#!/bin/bash
#------------------------------------------------------------------------------
# badInput-reacting <runDir>: mppicReactingPimpleFoam on the closed wet-bulb
# case (tutorials/verification/wetBulb) with one entry broken at a time ->
# FatalIOError naming the keyword (and the value), non-zero exit, no crash:
#   thermophysicalProperties: inertSpecie missing; inertSpecie N2 (not a
#   specie); liquids { H2X; } (not in OpenFOAM's liquid database);
#   reactingCloudProperties: singlePhaseMixtureCoeffs/phases missing;
#   injection nParticle -25 (statistical weight, range (0, inf));
#   droplet diameter -2e-4 (range (0, inf); OpenFOAM ran on, exit 0) and
#   averagingMethod basci (OpenFOAM aborted in the first step, exit 134),
#   both stopped before the first step with exit status 1;
#   system/controlDict: reactingCloudBalance species (H2X), cloud noCloud;
#   system/fvSolution: PIMPLE nCorector (misspelt; the message lists the
#   valid keywords), stopped before the first step.
#------------------------------------------------------------------------------
runDir="${1:?usage: badInput-reacting.sh <runDir>}"
. "${0%/*}/badInputFunctions"
status=0

copyTutorial verification/wetBulb "$runDir/prepared"
runAllrun "$runDir/prepared" -closed -endTime 0.002 || exit 1
rm -rf "$runDir"/prepared/0.0*

breakAndRun()   # name dict entry value(-remove for none) texts...
{
    local name="$1" dict="$2" entry="$3" value="$4"
    shift 4
    local dir="$runDir/$name"
    rm -rf "$dir"
    cp -r "$runDir/prepared" "$dir"
    if [ "$value" = -remove ]
    then
        foamDictionary "$dir/constant/$dict" -entry "$entry" -remove > /dev/null
    else
        foamDictionary "$dir/constant/$dict" -entry "$entry" -set "$value" \
            > /dev/null
    fi
    (cd "$dir" && mppicReactingPimpleFoam > log.broken 2>&1)
    rc=$?
    echo "== $name"
    check fatal "$dir/log.broken" $rc "$@" || status=1
}

breakAndRun inertSpecieMissing thermophysicalProperties inertSpecie -remove \
    "inertSpecie" "thermophysicalProperties"
breakAndRun inertSpecieUnknown thermophysicalProperties inertSpecie N2 \
    "inertSpecie" "N2"
breakAndRun liquidUnknown thermophysicalProperties liquids "{ H2X; }" \
    "liquids" "H2X"
breakAndRun phasesMissing reactingCloudProperties \
    subModels/singlePhaseMixtureCoeffs/phases -remove \
    "phases" "singlePhaseMixtureCoeffs"
breakAndRun negativeWeight reactingCloudProperties \
    subModels/injectionModels/droplet/nParticle -25 \
    "nParticle" "-25" "(0, inf)"

droplet=subModels/injectionModels/droplet
breakAndRun negativeDiameter reactingCloudProperties \
    $droplet/sizeDistribution/fixedValueDistribution/value -2e-4 \
    "keyword value" "value -0.0002" "(0, inf)"
stoppedBeforeFirstStep "$runDir/negativeDiameter/log.broken" $rc || status=1
breakAndRun averagingMisspelt reactingCloudProperties \
    solution/averagingMethod basci "keyword averagingMethod" "value basci" \
    "basic" "dual"
stoppedBeforeFirstStep "$runDir/averagingMisspelt/log.broken" $rc || status=1

breakAndRun balanceSpecies ../system/controlDict functions/balance/species \
    "(H2X)" "species" "H2X"
breakAndRun balanceCloud ../system/controlDict functions/balance/cloud \
    noCloud "keyword cloud" "noCloud"
breakAndRun pimpleMisspelt ../system/fvSolution PIMPLE/nCorector 2 \
    "unknown keyword nCorector" "nCorrectors" "momentumPredictor"
stoppedBeforeFirstStep "$runDir/pimpleMisspelt/log.broken" $rc || status=1

exit $status
