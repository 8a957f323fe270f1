#!/bin/bash
#------------------------------------------------------------------------------
# packingMomentum <runDir>
# tutorials/verification/packingMomentum: a layer (7.5e-4 kg at
# (0.1, -0.5, 0) m/s) thrown onto a pack at rest in a box periodic in x and
# y, no forces, 40 steps. With coloringFunction conserveMomentum true the
# cloud's linear momentum stays the hand value P0 = (7.5e-5, -3.75e-4, 0)
# kg m/s to 1e-12 relative while the collisions remove kinetic energy; with
# false (MFiX-PIC's form) it changes by more than half of |P0|, by exactly
# the packing monitor's summed packing momentum (1e-10). Cells stay at close
# pack 0.6 in both.
#------------------------------------------------------------------------------
runDir="${1:?usage: packingMomentum.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
for conserve in true false
do
    case="$runDir/$conserve"
    copyTutorial verification/packingMomentum "$case"
    runAllrun "$case" $conserve || exit 1
    (cd "$case" && /usr/bin/python3 packingMomentumResults.py --check) \
        || status=1
done
exit $status
