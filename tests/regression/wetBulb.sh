#!/bin/bash
#------------------------------------------------------------------------------
# wetBulb <runDir>
# tutorials/verification/wetBulb (seed 2 section 2.4; mppicReactingPimpleFoam,
# basicReactingMPPICCloud):
# - three humidities (0, 50, 90 %) run for 3 s (the droplet is steady after
#   about 1 s): its temperature within 0.5 K of seed 2's Table 5;
# - the closed variant (no inflow, dry air at 303.15 K, 3 s), the droplets
#   starting at 283.45 K, the wet-bulb temperature of that air: water
#   (vapour + droplets) and enthalpy (gas + droplets, reactingCloudBalance)
#   constant to 1e-10 relative, while the droplets lose at least 3 % of the
#   water to the gas. (Started at 303.15 K the droplets cool by 17 K in
#   0.5 s and the enthalpy moves by 2.3e-8: OpenFOAM's droplet step takes
#   Cp at the start of each track sub-step, an error of Cp' dT^2/2 per
#   sub-step, in proportion to the sub-step; tutorial README.)
# - the same closed case for 1 s with solids sub-cycling (10 sub-steps per
#   gas step, response-time limited): the enthalpy and species sources summed
#   over the sub-steps (CloudSourceSum), water and enthalpy again to 1e-10.
# What this short window cannot show (the 11 humidities over the seed's 15 s,
# within 0.3 K) is the validation matrix's: bin/validate wetBulb
# (docs/VALIDATION.md).
#------------------------------------------------------------------------------
runDir="${1:?usage: wetBulb.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"
status=0

copyTutorial verification/wetBulb "$runDir/case"
(cd "$runDir/case" && ./wetBulbSweep -humidities "0 50 90" -endTime 3 \
    -dir "$runDir/sweep" -check 0.5) || status=1
grep -l -E 'FOAM FATAL|FOAM aborting' "$runDir"/sweep/rh*/log.* && status=1

copyTutorial verification/wetBulb "$runDir/closed"
setEntry "$runDir/closed" constant/reactingCloudProperties \
    constantProperties/T0 283.45
runAllrun "$runDir/closed" -closed -endTime 3 || exit 1
check balance "$runDir/closed" H2O 1e-10 0.03 || status=1

copyTutorial verification/wetBulb "$runDir/subCycled"
setEntry "$runDir/subCycled" constant/reactingCloudProperties \
    constantProperties/T0 283.45
setEntry "$runDir/subCycled" constant/reactingCloudProperties \
    solidsSubCycling "{ active true; CFL 0.1; relaxationTimeFactor 10; }"
runAllrun "$runDir/subCycled" -closed -endTime 1 || exit 1
grep -q "Solids sub-cycling: 10 sub-step(s)" \
    "$runDir/subCycled/log.mppicReactingPimpleFoam" \
    && echo "PASS 10 solids sub-steps per gas step" \
    || { echo "FAIL not 10 solids sub-steps per gas step"; status=1; }
check balance "$runDir/subCycled" H2O 1e-10 0.01 || status=1

exit $status
