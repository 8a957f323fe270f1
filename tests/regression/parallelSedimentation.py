#!/usr/bin/python3
"""Checks of tests/regression/parallelSedimentation.sh for one decomposed run
of tutorials/verification/sedimentation with coloringFunction (2 ranks side
by side to 1 s, or 4 quarters to 0.5 s), each line prefixed "<n> ranks: ":
  - more than 4000 x endTime steps logged (dt 2e-4 s: 5000 a second);
  - the largest cell solids fraction of the whole domain (the solver's log,
    every step) <= 0.6 + 1e-9, the serial run's bound (the serial run keeps
    every cell at 0.6 = close pack; before the parcel records were exchanged
    between processors the 2-way split reached 2.36);
  - 2400 parcels at every step; the cloud mass at the end (packingMonitor)
    = the seeded solids volume x 2500 kg/m3 to 1e-9;
  - (endTime 1 s) the bed height within 3 % of the inventory height
        V_solids/(alpha_cp A) = 5.625e-6/(0.6 x 0.05 x 0.005) = 0.0375 m,
    as serial.

Usage: parallelSedimentation.py <n ranks> <endTime>   (in the case)
"""
import re
import sys

sys.path.insert(0, ".")
from sedimentationResults import read_monitor, bed_profile, post, \
    surface_height, seeded_solids_volume  # noqa: E402 (the case's copy)
import checks  # noqa: E402


def check_decomposed_run(n, end):
    def check(ok, what):
        checks.report(ok, "%s ranks: " % n + what)
    steps = [(int(m.group(1)), float(m.group(2))) for m in re.finditer(
        r"^Cloud: parcels = (\d+), max solids fraction = (\S+)$",
        open("log.mppicPimpleFoam").read(), re.M)]
    check(len(steps) > 4000*end, "%d steps logged" % len(steps))
    check(all(p == 2400 for p, _ in steps), "2400 parcels at every step")
    largest = max(a for _, a in steps)
    check(largest <= 0.6 + 1e-9,
          "largest cell solids fraction %.9g <= 0.6 (serial) at every step" % largest)
    cp, rows = read_monitor(".")
    mass = rows[-1][2]
    check(abs(mass/(seeded_solids_volume(".")*2500) - 1) < 1e-9,
          "cloud mass %.10g kg = seeded volume * 2500" % mass)
    if end >= 1:
        ys, prof, dy, _, _ = bed_profile(".", post.latest_time("."))
        h = surface_height(ys, prof, 0.5*cp, dy)
        check(abs(h/0.0375 - 1) <= 0.03, "bed height %.4f m within 3 %% of 0.0375 m" % h)


if __name__ == "__main__":
    check_decomposed_run(sys.argv[1], float(sys.argv[2]))
    sys.exit(checks.status())
