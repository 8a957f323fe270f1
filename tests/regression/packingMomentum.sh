#!/bin/bash
#------------------------------------------------------------------------------
# packingMomentum <runDir>
# processes: 2 (MPI ranks at most; tests/Alltest runs it alone)
# tutorials/verification/packingMomentum: a layer (7.5e-4 kg at
# (0.1, -0.5, 0) m/s) thrown onto a pack at rest in a box periodic in x and
# y, no forces, 40 steps. With coloringFunction conserveMomentum packs the
# cloud's linear momentum stays the hand value P0 = (7.5e-5, -3.75e-4, 0)
# kg m/s to 1e-12 relative while the collisions remove kinetic energy; with
# none (MFiX-PIC's form) it changes by more than half of |P0|, by exactly
# the packing monitor's summed packing momentum (1e-10). Cells stay at close
# pack 0.6 in both. Then conserveMomentum gas (./Allrun gas): no support holds the pack, so its share goes to the gas; the cloud's
# momentum plus the monitor's summed gasPackingMomentum stays P0 to 1e-12
# (measured 2.8e-16), and that sum's y lies within the hand bounds
# [-5.625e-4, -3.75e-4] kg m/s (packingMomentumResults.py; measured
# -5.278e-4; 0 if the pack's parcels took the share: the check can fail);
# the same on 2 processes, with the gas's share the serial run's to 1e-12.
# Then conserveMomentum none with solids sub-cycling (CFL 0.02: 3 to 5
# sub-steps per gas step): the monitor's packing momentum is the gas step's,
# summed over its sub-steps, so the same budget closes (before 2026-11-26 it
# held the last sub-step's only: 1.1e-15 now, FAIL with the old library).
# Then conserveMomentum packs on 2 processes (./Allrun packs -parallel: the cut
# along the top of the pack, where the layer lands): the same checks, and
# the final kinetic energy equal to the serial run's to 1e-12 relative
# (measured: 5.2e-15 drift, the energy equal to all 15 printed digits;
# before the packs took reactions across processor faces the drift was
# 1.47: the check can fail).
#------------------------------------------------------------------------------
runDir="${1:?usage: packingMomentum.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
for conserve in packs none gas
do
    case="$runDir/$conserve"
    copyTutorial verification/packingMomentum "$case"
    runAllrun "$case" $conserve || exit 1
    (cd "$case" && /usr/bin/python3 packingMomentumResults.py --check) \
        || status=1
done

case="$runDir/none.subCycled"
copyTutorial verification/packingMomentum "$case"
echo "solidsSubCycling { active true; CFL 0.02; }" \
    >> "$case/constant/kinematicCloudProperties"
runAllrun "$case" none || exit 1
subSteps=$(sed -n 's/^Solids sub-cycling: \([0-9]*\) sub-step.*/\1/p' \
    "$case/log.mppicPimpleFoam" | sort -n | tail -1)
if [ "${subSteps:-1}" -ge 2 ]
then
    echo "PASS sub-cycled run: up to $subSteps sub-steps per gas step"
else
    echo "FAIL sub-cycled run: ${subSteps:-no} sub-steps"
    status=1
fi
(cd "$case" && /usr/bin/python3 packingMomentumResults.py --check) || status=1

case="$runDir/packs.parallel"
copyTutorial verification/packingMomentum "$case"
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1
runAllrun "$case" packs -parallel || exit 1
[ -d "$case/processor1" ] || { echo "no parallel run"; exit 1; }
(cd "$case" && /usr/bin/python3 packingMomentumResults.py --check) || status=1

finalEnergy()
{
    sed -n 's/^ *Linear kinetic energy *= *//p' "$1/log.mppicPimpleFoam" | tail -1
}
serialEnergy=$(finalEnergy "$runDir/packs")
parallelEnergy=$(finalEnergy "$case")
if awk -v a="$serialEnergy" -v b="$parallelEnergy" \
    'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a > 0 && d <= 1e-12*a) }'
then
    echo "PASS final kinetic energy serial $serialEnergy, 2 processes $parallelEnergy"
else
    echo "FAIL final kinetic energy serial $serialEnergy, 2 processes $parallelEnergy"
    status=1
fi

# The packs' reactions to the gas on 2 processes: the same checks, and the
# gas's summed share (packingMomentum.txt) the serial run's to 1e-12 relative
case="$runDir/gas.parallel"
copyTutorial verification/packingMomentum "$case"
runAllrun "$case" gas -parallel || exit 1
[ -d "$case/processor1" ] || { echo "no parallel run"; exit 1; }
(cd "$case" && /usr/bin/python3 packingMomentumResults.py --check) || status=1
gasShare()
{
    sed -n 's/^summed to the gas *(\(.*\))$/\1/p' "$1/packingMomentum.txt" \
        | awk '{ print $2 }'
}
serialGas=$(gasShare "$runDir/gas")
parallelGas=$(gasShare "$case")
if awk -v a="$serialGas" -v b="$parallelGas" \
    'BEGIN { d = a - b; if (d < 0) d = -d; m = (a < 0 ? -a : a);
             exit !(m > 0 && d <= 1e-12*m) }'
then
    echo "PASS gas's share (y) serial $serialGas, 2 processes $parallelGas"
else
    echo "FAIL gas's share (y) serial $serialGas, 2 processes $parallelGas"
    status=1
fi
exit $status
