#!/bin/bash
#------------------------------------------------------------------------------
# sedimentation <runDir>
# tutorials/verification/sedimentation with coloringFunction (1 s, the full
# case, about 50 s): a suspension at solids fraction 0.15 settles into a bed
# at close pack 0.6, 32 parcels per packed cell. checks: sedimentation.py
# (the gas fraction never below 0; the final bed height within 3 % of the
# inventory height 0.0375 m; the cloud mass; the largest solids fraction at
# every step within one parcel of close pack), after sedimentationResults.py
# runs.
# The validation matrix runs the same case: bin/validate sedimentation
# (docs/VALIDATION.md).
#------------------------------------------------------------------------------
runDir="${1:?usage: sedimentation.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial verification/sedimentation "$runDir/case"
runAllrun "$runDir/case" || exit 1

cd "$runDir/case" || exit 1
/usr/bin/python3 sedimentationResults.py --label coloringFunction
status=0
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/sedimentation.py" || status=1
exit $status
