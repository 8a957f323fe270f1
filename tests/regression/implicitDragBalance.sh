#!/bin/bash
#------------------------------------------------------------------------------
# implicitDragBalance <runDir>
# tutorials/validation/uniformFluidization at 3 parcels per packed cell
# (2880 parcels), 40 steps from the seeded bed with the fields written at
# every step, PIMPLE balanceImplicitDrag off and on (mppicPimpleFoam; about
# 1 minute). checks: implicitDragBalance.py (per step, the cloud's vertical
# momentum budget: its rest with the balance within 5e-4 of the weight, and
# the switch's difference equal to the impulse it logs; parcels and mass).
#------------------------------------------------------------------------------
runDir="${1:?usage: implicitDragBalance.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

for mode in off on
do
    case="$runDir/$mode"
    copyTutorial validation/uniformFluidization "$case"
    sed -i "s/^parcelsPerCell .*/parcelsPerCell  3;/" "$case/system/mppicSeedParcelsDict"
    [ "$mode" = on ] && setEntry "$case" system/fvSolution PIMPLE/balanceImplicitDrag true
    # mesh and seed with the case's own Allrun (one step), then 40 steps
    # from the seeded bed with the fields at every step
    runAllrun "$case" 0.0005 > /dev/null || exit 1
    rm -rf "$case/0.0005" "$case/postProcessing"
    setEntry "$case" system/controlDict writeInterval 5e-4
    setEntry "$case" system/controlDict endTime 0.02
    (cd "$case" && mppicPimpleFoam > log.steps 2>&1) || { echo "mppicPimpleFoam failed"; exit 1; }
done

cd "$runDir" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/implicitDragBalance.py"
