#!/bin/bash
# badInput-compareSolvers <runDir>: bin/compareSolvers -jobs with a value
# that is not a whole number 1 to 99 (0, 100, two) stops before any run,
# exit 1, with a message naming -jobs, the value and the allowed range.
runDir="${1:?usage: badInput-compareSolvers.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
for jobs in 0 100 two
do
    out=$("$MPPIC_PROJECT_DIR/bin/compareSolvers" \
        -case "$MPPIC_PROJECT_DIR/tutorials/validation/uniformFluidization" \
        -results uniformFluidizationResults.py -runDir "$runDir/compare" \
        -jobs "$jobs" coloringFunction 2>&1)
    rc=$?
    if [ $rc = 1 ] && echo "$out" | grep -q -- "-jobs $jobs: a whole number 1 to 99" \
        && [ ! -d "$runDir/compare/coloringFunction" ]
    then
        echo "PASS -jobs $jobs: exit 1, '$out'"
    else
        echo "FAIL -jobs $jobs: exit $rc, '$out'"
        status=1
    fi
done
exit $status
