#!/bin/bash
#------------------------------------------------------------------------------
# cfbAerationEntry <runDir>
# tutorials/validation/circulatingFluidizedBed's Allrun with the L-valve's aeration
# (FTC135, Case 1: 6 SLPM, Q = 1e-4 m3/s) entering as a gas source, a few
# steps each (-endTime 0.002): -aeration leg -equalArea and -aeration source
# (nominal pipes); checks: cfbAerationEntry.py (the source's centre,
# velocity and flow from the solver's report, against hand values).
# Here, in bash:
#   - -aeration bogus stops before meshing, exit 1, with a message naming the
#     value and the allowed ones.
#   - -continue -parallel where there are no processor folders stops, exit 1,
#     with a message naming them, and runs nothing.
#------------------------------------------------------------------------------
runDir="${1:?usage: cfbAerationEntry.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
bad="$runDir/bogus"
copyTutorial validation/circulatingFluidizedBed "$bad"
allrunRefuses "$bad" "-aeration bogus: not patch, source or leg" cfb.msh \
    -aeration bogus || status=1
allrunRefuses "$bad" "-continue -parallel: no processor folders" log.mppicPimpleFoam \
    -continue -endTime 1 -parallel || status=1

copyTutorial validation/circulatingFluidizedBed "$runDir/leg"
PROGRESS_EVERY=0 runAllrun "$runDir/leg" -endTime 0.002 -equalArea -aeration leg || exit 1
copyTutorial validation/circulatingFluidizedBed "$runDir/source"
PROGRESS_EVERY=0 runAllrun "$runDir/source" -endTime 0.002 -aeration source || exit 1

cd "$runDir" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/cfbAerationEntry.py" || status=1
exit $status
