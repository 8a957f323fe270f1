#!/usr/bin/python3
"""Checks of tests/regression/coloringFunctionImpulses.sh, for one run of
tutorials/verification/sedimentation (1 s) with one of coloringFunction's
impulses (gradient, faceGradient, cornerNodeGradient), read with the
tutorial's sedimentationResults helpers:
  - 2400 parcels at the end (packingMonitor);
  - the cloud mass = the seeded solids volume x 2500 kg/m3 to 1e-9;
  - the final bed height (where the bed profile crosses half close pack)
    within 10 % of the inventory height
        V_solids/(alpha_cp A) = 5.625e-6/(0.6 x 0.05 x 0.005) = 0.0375 m
    (without the capacity limit a bed may pack above alpha_cp: measured
    +6.6 % with gradient, README).

Usage: coloringFunctionImpulses.py   (in the case)
"""
import sys

sys.path.insert(0, ".")
from sedimentationResults import read_monitor, bed_profile, post, \
    surface_height, seeded_solids_volume  # noqa: E402 (the case's copy)
import checks  # noqa: E402
from checks import report as check  # noqa: E402


def check_parcels_mass_and_bed_height():
    cp, rows = read_monitor(".")
    check(rows[-1][1] == 2400, "2400 parcels at the end (%d)" % rows[-1][1])
    mass = rows[-1][2]
    check(abs(mass/(seeded_solids_volume(".")*2500) - 1) < 1e-9,
          "cloud mass %.10g kg = seeded volume * 2500" % mass)
    ys, prof, dy, _, _ = bed_profile(".", post.latest_time("."))
    h = surface_height(ys, prof, 0.5*cp, dy)
    check(abs(h/0.0375 - 1) <= 0.10, "bed height %.4f m within 10 %% of 0.0375 m" % h)


if __name__ == "__main__":
    check_parcels_mass_and_bed_height()
    sys.exit(checks.status())
