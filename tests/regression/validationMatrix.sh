#!/bin/bash
#------------------------------------------------------------------------------
# validationMatrix <runDir>
# bin/validate on the terminal-velocity case (about 15 s), its run and
# records under <runDir> (-runRoot, -records), then -list, and -resultsOnly
# on a case never run. checks: validationMatrix.py (the record, the page
# and the listing that the matrix's tooling writes, tutorials/lib/
# validationRecord.py and validationReport.py).
#------------------------------------------------------------------------------
runDir="${1:?usage: validationMatrix.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"
validate="$MPPIC_PROJECT_DIR/bin/validate"
records="$runDir/docs/validation"

"$validate" -runRoot "$runDir/runs" -records "$records" terminalVelocity \
    > "$runDir/validate.log" 2>&1
rc=$?
cat "$runDir/validate.log"
"$validate" -runRoot "$runDir/runs" -records "$records" -list \
    > "$runDir/list.log" 2>&1
"$validate" -runRoot "$runDir/runs" -records "$records" -resultsOnly \
    vortexAdvection > "$runDir/resultsOnly.log" 2>&1
rcMissing=$?

/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/validationMatrix.py" \
    "$runDir" "$rc" "$rcMissing" \
    "$(git -C "$MPPIC_PROJECT_DIR" rev-parse --short=10 HEAD)"
