#!/bin/bash
#------------------------------------------------------------------------------
# uniformFluidizationPacksToGas <runDir>
# tutorials/validation/uniformFluidization with -packsToGas (coloringFunction
# with conserveMomentum gas: the packs take the reactions, and those no
# support holds hand them to the gas; PIMPLE balanceImplicitDrag true) at
# 3 parcels per packed cell (2880
# parcels of 382 particles), 2 s (about 2 minutes). checks:
# uniformFluidizationPacksToGas.py (over 1.2-2 s the gas pressure drop
# within 2 % of the weight, the packs' reactions the gas took, what is left
# to the supports; parcels, mass, the largest cell solids fraction and no
# cell above close pack at every step), after uniformFluidizationResults.py
# runs.
#------------------------------------------------------------------------------
runDir="${1:?usage: uniformFluidizationPacksToGas.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial validation/uniformFluidization "$runDir/case"
runAllrun "$runDir/case" 2 -packsToGas -perCell 3 || exit 1

cd "$runDir/case" || exit 1
/usr/bin/python3 uniformFluidizationResults.py --from 1.2 --label test
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/uniformFluidizationPacksToGas.py"
