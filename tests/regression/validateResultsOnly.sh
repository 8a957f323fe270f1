#!/bin/bash
#------------------------------------------------------------------------------
# validateResultsOnly <runDir>
# processes: 1
# bin/validate -resultsOnly writes a case's record again from its finished
# run, without running the case: terminalVelocity (the quickest case of the
# matrix) run by bin/validate into <runDir>/runs with its record in
# <runDir>/records, then bin/validate -resultsOnly on that run. Checks:
#   - both exit 0, and the second does not run the case: the solver log and
#     the list of the case's files are unchanged;
#   - the two records hold the same figures: each row's own value equal to
#     1e-12 (relative), the same rows and goals, both naming the command
#     that makes the run (bin/validate terminalVelocity) and its wall time
#     (validateResultsOnly.py);
#   - the page beside the records (<runDir>/VALIDATION.md) names the case;
#   - -resultsOnly on a case with no finished run (vortexAdvection) exits 1,
#     says "no finished run here" and writes no record.
#------------------------------------------------------------------------------
runDir="${1:?usage: validateResultsOnly.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

validate="$MPPIC_PROJECT_DIR/bin/validate"
runs="$runDir/runs" records="$runDir/records"
rm -rf "$runs" "$records"
case="$runs/terminalVelocity"

"$validate" -runRoot "$runs" -records "$records" terminalVelocity \
    > "$runDir/log.run" 2>&1
rc=$?
[ $rc = 0 ] || { echo "FAIL bin/validate terminalVelocity: exit $rc"; exit 1; }
cp "$records/terminalVelocity.json" "$runDir/first.json"
fingerprint()
{
    (cd "$case" && md5sum log.* && find . -type f | sort | md5sum)
}
before="$(fingerprint)"

"$validate" -runRoot "$runs" -records "$records" -resultsOnly \
    terminalVelocity > "$runDir/log.resultsOnly" 2>&1
rc=$?
status=0
if [ $rc = 0 ]
then
    echo "PASS bin/validate -resultsOnly terminalVelocity: exit 0"
else
    echo "FAIL bin/validate -resultsOnly terminalVelocity: exit $rc"
    status=1
fi
if [ "$(fingerprint)" = "$before" ]
then
    echo "PASS -resultsOnly left the run as it was (solver log and files)"
else
    echo "FAIL -resultsOnly changed the run's files"
    status=1
fi
/usr/bin/python3 "${0%.sh}.py" "$runDir/first.json" \
    "$records/terminalVelocity.json" || status=1
if grep -q "terminalVelocity" "$runDir/VALIDATION.md" 2>/dev/null
then
    echo "PASS $runDir/VALIDATION.md names the case"
else
    echo "FAIL no VALIDATION.md naming the case beside the records"
    status=1
fi

"$validate" -runRoot "$runs" -records "$records" -resultsOnly \
    vortexAdvection > "$runDir/log.noRun" 2>&1
rc=$?
if [ $rc = 1 ] && grep -q "no finished run here" "$runDir/log.noRun" \
    && [ ! -f "$records/vortexAdvection.json" ]
then
    echo "PASS -resultsOnly without a run: exit 1, 'no finished run here'," \
        "no record"
else
    echo "FAIL -resultsOnly without a run: exit $rc (expected 1)"
    status=1
fi
exit $status
