#!/usr/bin/python3
"""Check of tests/regression/leanCloudStep.sh beside its sameState
comparisons: the lean cloud step's correction pass must have left parcels
out. Its log line of each step, "correction pass: <a> of <b> parcels", must
appear once a step, endTime/5e-4 steps (the Kuipers jet's dt), with a < b
at every one.

Usage: leanCloudStep.py <lean run's log.mppicPimpleFoam> <endTime>
"""
import re
import sys

import checks
from checks import report


def check_correction_pass_leaves_parcels_out(log, end_time):
    passes = [(int(a), int(b)) for a, b in
              re.findall(r"correction pass: (\d+) of (\d+) parcels", open(log).read())]
    steps = round(float(end_time)/5e-4)
    ok = len(passes) == steps and all(a < b for a, b in passes)
    report(ok, "lean correction pass over fewer parcels than the"
           " cloud at each of %d steps (last: %d of %d)" % (len(passes), *passes[-1]))


if __name__ == "__main__":
    check_correction_pass_leaves_parcels_out(sys.argv[1], sys.argv[2])
    sys.exit(checks.status())
