#!/bin/bash
#------------------------------------------------------------------------------
# cfbSniderSeal <runDir>
# tutorials/validation/circulatingFluidizedBed with seed 2's model: ./Allrun -packing
# mfixSnider -riserBed 0.16 -standpipeLevel 0.576 -equalArea -endTime 0.1
# (coarse mesh, weight 64, Case 1; about 2 minutes). Allrun gives mfixSnider
# the cloud's diffusion averaging over the mesh's cell size (MFiX-PIC's hat
# deposit, which our linearHat makes only on hexahedra), with the case's
# capacityLimit push (push-through). With basic averaging (cell values of 2-4
# parcels) the Snider stress loosened the packed column within 0.1 s: this
# run with basic gave 0.527 over the standpipe and 0.428 over the lower
# bend below (without push-through 0.22 in the bend), and in the longer
# runs the riser's gas came back through the leg and up the standpipe.
# checks: cfbSniderSeal.py (the case's settings; the standpipe and the lower
# bend still packed at 0.1 s; the cloud's mass).
#------------------------------------------------------------------------------
runDir="${1:?usage: cfbSniderSeal.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

case="$runDir/case"
copyTutorial validation/circulatingFluidizedBed "$case"
PROGRESS_EVERY=0 runAllrun "$case" -packing mfixSnider -riserBed 0.16 \
    -standpipeLevel 0.576 -equalArea -endTime 0.1 || exit 1

cd "$case" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/cfbSniderSeal.py"
