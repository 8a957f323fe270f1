#!/usr/bin/python3
"""Checks of tests/regression/continueKuipersJet.sh: tutorials/validation/kuipersJet
run to 0.01 s (20 steps of 5e-4 s), then continued to 0.02 s (./Allrun 0.02
-continue), from the solver's log of both pieces (log.mppicPimpleFoam):
  - two pieces ("Starting time loop" twice), 40 steps, the second piece's
    first step at 0.0105 s (it started from the written 0.01 s);
  - 38 000 parcels at every step;
  - the largest cell solids fraction at every step <= 0.600 (+1e-6): no
    cell of this bed goes above 5 parcels uninterrupted, and the continued
    run must not either (the coloring function must know the cells the
    parcels were in before the stop: without that, 0.84 was measured);
  - the cloud mass 0.6 x 0.57 x 0.5 x 0.015 x 2660 = 6.8229 kg at every
    step to 1e-9 (the case writes 12 digits: with 8 the continued cloud
    mass was 3e-8 off);
and mppicPost.function_object_table on hand-made pieces: 0/x.dat (t 0-3),
2/x.dat (t 2, 2.5: a piece stopped), 2/x_2.dat (t 2-5: the piece continued
from the same 2 s, which OpenFOAM writes beside it) must read t 0, 1, 2, 3,
4, 5 with the values of x_2.dat from 2 on.

Usage: continueKuipersJet.py   (in the case)
"""
import os
import re
import sys
import tempfile

import checks
from checks import report as check


def check_both_pieces():
    log = open("log.mppicPimpleFoam").read()
    starts = re.findall(r"Starting time loop", log)
    steps = re.findall(r"^Time = ([0-9.e-]+)\s*$.*?Cloud: parcels = (\d+), max solids fraction = ([0-9.e+-]+)",
                       log, re.M | re.S)
    times = [float(t) for t, _, _ in steps]
    check(len(starts) == 2 and len(steps) == 40 and abs(times[20] - 0.0105) < 1e-9,
          "two pieces, 40 steps, the second from 0.01 s (first time %g)" % times[20])
    check(all(int(n) == 38000 for _, n, _ in steps), "38000 parcels at every step")
    worst = max(float(a) for _, _, a in steps)
    after = max(float(a) for _, _, a in steps[20:])
    check(worst <= 0.6 + 1e-6,
          "largest cell solids fraction %.6f <= 0.600 at every step (after the restart %.6f)"
          % (worst, after))
    mass = 0.6*0.57*0.5*0.015*2660
    masses = [float(m) for m in re.findall(r"Current mass in system\s*=\s*([0-9.e+-]+)", log)]
    check(len(masses) >= 40 and all(abs(m/mass - 1) < 1e-9 for m in masses),
          "cloud mass %.6g kg = %.6g kg at every step" % (masses[-1] if masses else -1, mass))


def check_function_object_table_of_pieces():
    sys.path.insert(0, os.path.join(os.environ["MPPIC_PROJECT_DIR"], "tutorials", "lib"))
    import mppicPost
    with tempfile.TemporaryDirectory() as case:
        pieces = {"0/x.dat": [(0, 0), (1, 0), (2, 0), (3, 0)], "2/x.dat": [(2, 1), (2.5, 1)],
                  "2/x_2.dat": [(2, 2), (3, 2), (4, 2), (5, 2)]}
        for name, rows in pieces.items():
            path = os.path.join(case, "postProcessing", "x", name)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            open(path, "w").write("# Time value\n" + "".join("%g %g\n" % r for r in rows))
        read = [tuple(r) for r in mppicPost.function_object_table(case, "x")]
    check(read == [(0, 0), (1, 0), (2, 2), (3, 2), (4, 2), (5, 2)],
          "function_object_table over a piece continued from where another stopped: %s" % read)


if __name__ == "__main__":
    check_both_pieces()
    check_function_object_table_of_pieces()
    sys.exit(checks.status())
