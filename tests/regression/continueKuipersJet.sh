#!/bin/bash
#------------------------------------------------------------------------------
# continueKuipersJet <runDir>
# tutorials/validation/kuipersJet run to 0.01 s (20 steps), then continued to 0.02 s
# (./Allrun 0.02 -continue: from the written 0.01 s). Uninterrupted, no cell
# of this bed goes above 5 parcels, 0.600, in these steps. Continued, the
# coloring function must know where each parcel was at the end of the step
# before the stop (LeanMPPICCloud asks it to record the cells the parcels
# were read in); without that, the first step after the restart took a
# sixth and seventh parcel into a full cell (0.84, measured) and kept it.
# checks: continueKuipersJet.py (at every step of both pieces the parcels,
# the cloud mass and the largest cell solids fraction; the second piece from
# 0.01 s; mppicPost.function_object_table on hand-made continued pieces).
# ./Allrun 0.03 -continue -parallel on this serial run stops, exit 1, with a
# message that names the missing processor folders, and runs nothing.
#------------------------------------------------------------------------------
runDir="${1:?usage: continueKuipersJet.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial validation/kuipersJet "$runDir/case"
runAllrun "$runDir/case" 0.01 || exit 1
runAllrun "$runDir/case" 0.02 -continue || exit 1

# a serial run asked to continue on processor folders it does not have
status=0
allrunRefuses "$runDir/case" "-continue -parallel: no processor folders" 0.03 \
    0.03 -continue -parallel || status=1

cd "$runDir/case" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/continueKuipersJet.py" || status=1
exit $status
