#!/usr/bin/python3
"""validateResultsOnly.py <first.json> <second.json>: the record bin/validate
wrote from its run and the one -resultsOnly wrote from the same run hold the
same figures (validateResultsOnly.sh)."""
import json
import sys

import checks

first, second = (json.load(open(path)) for path in sys.argv[1:3])
checks.report(first["case"] == second["case"] == "terminalVelocity",
              "both records are terminalVelocity's")
checks.report(first["command"] == second["command"]
              == "bin/validate terminalVelocity",
              "both name the command that makes the run: '%s', '%s'"
              % (first["command"], second["command"]))
checks.report(first["wallTime"] == second["wallTime"] > 0,
              "both carry the run's wall time: %s s, %s s"
              % (first["wallTime"], second["wallTime"]))
rowsA, rowsB = first["rows"], second["rows"]
checks.report(len(rowsA) == len(rowsB) > 0,
              "%d and %d rows" % (len(rowsA), len(rowsB)))
for a, b in zip(rowsA, rowsB):
    same = (a["figure"] == b["figure"] and a["goal"] == b["goal"]
            and a["met"] == b["met"]
            and abs(a["ours"] - b["ours"]) <= 1e-12*abs(a["ours"]))
    checks.report(same, "%s: %.12g, then %.12g (%s, met %s)"
                  % (a["figure"], a["ours"], b["ours"], a["goal"], b["met"]))
sys.exit(checks.status())
