#!/usr/bin/python3
"""Checks of tests/regression/validationMatrix.sh: bin/validate on the
terminal-velocity case, its run and records under <runDir> (-runRoot,
-records), then what the matrix's tooling writes
(tutorials/lib/validationRecord.py, validationReport.py):
  - bin/validate terminalVelocity exits 0;
  - the record <runDir>/docs/validation/terminalVelocity.json: the case's
    name, this checkout's commit, the command, two rows: the terminal
    velocity against RK4 (goal "within 0.5 %", met, and within 0.5 % of it)
    and the y(t) error (goal "<= 0.005", met as its value says); the plot
    terminalVelocity.png named and copied;
  - the RK4 reference within 5 % below the terminal velocity
        v_t = v_g - sqrt(4/3 g d (rho_p - rho_g)/(rho_g Cd)) = -1.0760 m/s
    (at 0.3 s the parcel is within 3 % of it; RK4: 97.1 %);
  - the page <runDir>/docs/VALIDATION.md: the summary row "2 of 2" with
    GitHub's anchor of the title and the commit, the case's section with its
    command, the plot linked beside the records, a case with no record
    (vortexAdvection) marked "not run";
  - -list (list.log) shows the record; -resultsOnly on a case never run
    exits 1 and leaves no record;
  - the page's comparison of code without its comments
    (validationReport.without_comments): a change of comments and layout
    gives the same text, a changed number or a changed string does not,
    a // inside a string is kept.

Usage: validationMatrix.py <runDir> <validate's exit status>
           <-resultsOnly's exit status> <commit>
"""
import json
import os
import sys

from checks import report, status

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "tutorials", "lib"))
from validationReport import without_comments


def check_record(records, rc, commit):
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


def check_page(run_dir, commit):
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


def check_list_and_results_only(run_dir, records, rc_missing):
    listing = open(os.path.join(run_dir, "list.log")).read()
    report(any(l.split()[:3] == ["terminalVelocity", "short", "record"]
               for l in listing.splitlines()), "-list shows the record")
    report(rc_missing == 1 and not os.path.exists(
        os.path.join(records, "vortexAdvection.json")),
           "-resultsOnly on a case never run: exit status %d, no record"
           % rc_missing)


def check_without_comments():
    code = 'word name("a//b"); // the name\nscalar x = 1.5; /* a\n b */ y = x;'
    layout = 'word name("a//b");\n/* other */ scalar   x = 1.5;\n\ny = x; // c'
    report(without_comments(code) == without_comments(layout)
           == 'word name("a//b"); scalar x = 1.5; y = x;',
           "comments and layout only: the same text '%s'"
           % without_comments(code))
    report(without_comments(code)
           != without_comments(code.replace("1.5", "1.6")),
           "a changed number is a change")
    report(without_comments(code)
           != without_comments(code.replace("a//b", "a//c")),
           "a changed string is a change")


if __name__ == "__main__":
    run_dir, rc, rc_missing, commit = sys.argv[1], int(sys.argv[2]), \
        int(sys.argv[3]), sys.argv[4]
    records = os.path.join(run_dir, "docs", "validation")
    check_record(records, rc, commit)
    check_page(run_dir, commit)
    check_list_and_results_only(run_dir, records, rc_missing)
    check_without_comments()
    sys.exit(status())
