#!/usr/bin/python3
"""Checks of tests/regression/parallelKuipersJet.sh: tutorials/validation/kuipersJet
for 0.05 s (100 steps) on 3 processes (simple (1 3 1)), from the solver's
log (log.mppicPimpleFoam):
  - nProcs 3, and 100 steps logged;
  - 38000 parcels at every step;
  - the largest cell solids fraction at every step <= 0.600 (+1e-6), the
    serial run's bound;
  - the cloud mass 0.6 x 0.57 x 0.5 x 0.015 x 2660 = 6.8229 kg at every
    step to 1e-9.

Usage: parallelKuipersJet.py   (in the case)
"""
import re
import sys

import checks
from checks import report as check


def check_three_rank_run():
    log = open("log.mppicPimpleFoam").read()
    check(re.search(r"^nProcs\s*:\s*3\s*$", log, re.M) is not None, "3 processes")
    steps = [(int(n), float(a)) for n, a in re.findall(
        r"^Cloud: parcels = (\d+), max solids fraction = (\S+)$", log, re.M)]
    check(len(steps) == 100, "100 steps (%d)" % len(steps))
    check(all(n == 38000 for n, _ in steps), "38000 parcels at every step")
    worst = max(a for _, a in steps)
    check(worst <= 0.6 + 1e-6,
          "largest cell solids fraction %.6f <= 0.600 at every step" % worst)
    mass = 0.6*0.57*0.5*0.015*2660
    masses = [float(m) for m in re.findall(r"Current mass in system\s*=\s*(\S+)", log)]
    check(len(masses) >= 100 and all(abs(m/mass - 1) < 1e-9 for m in masses),
          "cloud mass %.6g kg = %.6g kg at every step" % (masses[-1] if masses else -1, mass))


if __name__ == "__main__":
    check_three_rank_run()
    sys.exit(checks.status())
