#!/bin/bash
#------------------------------------------------------------------------------
# faceInterpolatedDragClosedBox <runDir>
# tutorials/verification/settlingShocks at eps_s0 = 0.10 with PIMPLE
# faceInterpolatedDrag true (1 s, about 2 minutes): a closed box, whose
# pressure needs a reference. With the switch a wall's phiHbyA carries its
# half cell's H, which the walls' fixedFluxPressure balances; the solver
# must not take it for a continuity error (adjustPhi stopped the run at the
# first step). checks: the fronts at 1 s within 0.005 m of the exact
# solution of the problem as posed (settlingShocksResults.py, written out
# there): the settling front of eq 6 with the parcels' start from rest
# (0.4888 m), the filling front of a packed bed at rest on the bottom wall
# (0.0668 m).
#------------------------------------------------------------------------------
runDir="${1:?usage: faceInterpolatedDragClosedBox.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial verification/settlingShocks "$runDir/case"
setEntry "$runDir/case" system/fvSolution PIMPLE/faceInterpolatedDrag true
runAllrun "$runDir/case" 0.10 || exit 1
cd "$runDir/case" && /usr/bin/python3 settlingShocksResults.py --check \
    --reference exact --tolerance 0.005
