#!/bin/bash
#------------------------------------------------------------------------------
# uniformFluidization <runDir>
# tutorials/validation/uniformFluidization (mppicPimpleFoam, coloringFunction,
# GidaspowDrag, 7680 parcels) for 2 s (about 3 minutes): a bed of 0.5 mm
# glass fluidized uniformly at 0.5 m/s = 2.35 Umf (Ergun, README).
# checks: uniformFluidization.py ((deltaP - gas head)/weight over 1.2-2 s
# within 3 % of 1; parcels, mass and the largest cell solids fraction at
# every step), after uniformFluidizationResults.py runs.
# What this short window cannot show (deltaP/weight over 4-10 s within 1.00 +-
# 0.02) is the validation matrix's: bin/validate uniformBed-3, -8 and -16
# (docs/VALIDATION.md).
#------------------------------------------------------------------------------
runDir="${1:?usage: uniformFluidization.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial validation/uniformFluidization "$runDir/case"
runAllrun "$runDir/case" 2 || exit 1

cd "$runDir/case" || exit 1
/usr/bin/python3 uniformFluidizationResults.py --from 1.2 --label test
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/uniformFluidization.py"
