#!/bin/bash
#------------------------------------------------------------------------------
# uniformFluidizationSnider <runDir>
# tutorials/validation/uniformFluidization with mfixSnider (-packing
# mfixSnider: MFiX-PIC's Snider stress, and the gas, on the solids
# fraction deposited with its linear hat (averagingMethod linearHat,
# solidsFractionFrom averaging), slip to the previous step's mean solids
# velocity,
# slip factor 0.9, MFiX's collision damping, and by default our capacity
# limit and held packs) for 2 s (about 2 minutes).
# Before mfixSnider slipped against the mean of the step's own velocities,
# this bed collapsed onto the distributor (cell solids fraction 5-6) and the
# gas carried 0.049 of it; before the capacity limit its cells reached 1.20.
# checks: uniformFluidizationSnider.py ((deltaP - gas head)/weight over
# 1.2-2 s in [0.90, 1.10]; parcels, mass, the largest cell solids fraction
# within half a parcel of close pack and the linear-hat field within 0.69 at
# every step), after uniformFluidizationResults.py runs.
#------------------------------------------------------------------------------
runDir="${1:?usage: uniformFluidizationSnider.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial validation/uniformFluidization "$runDir/case"
runAllrun "$runDir/case" 2 -packing mfixSnider || exit 1

cd "$runDir/case" || exit 1
/usr/bin/python3 uniformFluidizationResults.py --from 1.2 --label test
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/uniformFluidizationSnider.py"
