#!/bin/bash
#------------------------------------------------------------------------------
# validationMatrix <runDir>
# bin/validate on the terminal-velocity case (about 15 s), its run and
# records under <runDir> (-runRoot, -records), then checks of what the
# matrix's tooling writes (tutorials/lib/validationRecord.py,
# validationReport.py):
#   - the record: the case's name, this checkout's commit, two rows with
#     the terminal velocity against RK4 (goal within 0.5 %, met) and the
#     y(t) error (goal <= 0.005, met), the plot named and copied;
#   - the page: the summary row "2 of 2" with GitHub's anchor of the title,
#     the case's table with its command, the plot linked beside the records;
#     the cases with no record marked "not run";
#   - -list shows the record; -resultsOnly on a case never run fails with
#     exit status 1 and leaves no record.
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

/usr/bin/python3 - "$runDir" "$rc" "$rcMissing" \
    "$(git -C "$MPPIC_PROJECT_DIR" rev-parse --short=10 HEAD)" <<'PY'
import json, os, sys
from checks import report, status
run_dir, rc, rc_missing, commit = sys.argv[1], int(sys.argv[2]), \
    int(sys.argv[3]), sys.argv[4]
records = os.path.join(run_dir, "docs", "validation")
report(rc == 0, "bin/validate terminalVelocity exit status %d" % rc)
path = os.path.join(records, "terminalVelocity.json")
report(os.path.exists(path), "record %s written" % path)
r = json.load(open(path))
report(r["case"] == "terminalVelocity", "record's case %s" % r["case"])
report(r["commit"] == commit, "record's commit %s (checkout %s)"
       % (r["commit"], commit))
report(r["command"] == "bin/validate terminalVelocity",
       "record's command '%s'" % r["command"])
report(len(r["rows"]) == 2, "%d rows (2)" % len(r["rows"]))
v, y = r["rows"]
report(v["goal"] == "within 0.5 %" and v["met"] is True
       and abs(v["ours"] - v["reference"]) <= 0.005*abs(v["reference"]),
       "terminal velocity %.6f against RK4 %.6f, goal '%s', met %s"
       % (v["ours"], v["reference"], v["goal"], v["met"]))
# v_t = v_g - sqrt(4/3 g d (rho_p - rho_g)/(rho_g Cd)) = -1.0760 m/s, and at
# 0.3 s the parcel is within 3 % of it (RK4: 97.1 %)
report(0.95 < v["reference"]/-1.0760 < 1,
       "RK4 reference %.4f m/s within 5 %% below the terminal velocity "
       "-1.0760 m/s" % v["reference"])
report(y["goal"] == "<= 0.005" and y["met"] is (y["ours"] <= 0.005),
       "y(t) error %.2e, goal '%s', met %s" % (y["ours"], y["goal"], y["met"]))
report(r["plots"] == ["terminalVelocity.png"]
       and os.path.exists(os.path.join(records, "terminalVelocity.png")),
       "plot named and copied: %s" % r["plots"])
page = open(os.path.join(run_dir, "docs", "VALIDATION.md")).read()
row = ("| [Terminal velocity (seed 2 §2.1)](#terminal-velocity-seed-2-21) "
       "| 2 of 2 | `%s` |" % commit)
report(row in page, "summary row: %s" % row)
report("## Terminal velocity (seed 2 §2.1)" in page
       and "by `bin/validate terminalVelocity`" in page,
       "the case's section with its command")
report("![terminalVelocity.png](validation/terminalVelocity.png)" in page,
       "the plot linked beside the records")
report("| [Vortex advection (seed 2 §2.2.1)](#vortex-advection-seed-2-221) "
       "| not run |" in page, "a case with no record: not run")
listing = open(os.path.join(run_dir, "list.log")).read()
report(any(l.split()[:3] == ["terminalVelocity", "short", "record"]
           for l in listing.splitlines()), "-list shows the record")
report(rc_missing == 1 and not os.path.exists(
    os.path.join(records, "vortexAdvection.json")),
       "-resultsOnly on a case never run: exit status %d, no record"
       % rc_missing)
sys.exit(status())
PY
