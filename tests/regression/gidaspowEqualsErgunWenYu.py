#!/usr/bin/python3
"""Checks of tests/regression/gidaspowEqualsErgunWenYu.sh: GidaspowDrag
without blend is Ergun below gas fraction 0.8 and Wen-Yu above, which is
OpenFOAM's ErgunWenYuDrag. The settling column run 10 steps (0.005 s) with
each (runs GidaspowDrag/ and ErgunWenYuDrag/) gives the same bed pressure
drop (bedPressureDrop's deltaP) at every step: identical at the first step,
and within 1e-6 relative at every step (the two codes round differently and
the iterative pressure solver, tolerance 1e-7, carries that into the 8th
digit within 10 steps; it grows to 1e-5 by 0.1 s as the settling column is
chaotic). (The same parcels and mass: checks.py serialParallel, in the
script.)

Usage: gidaspowEqualsErgunWenYu.py <runDir>
"""
import sys

import checks
from checks import read_dat, report


def delta_p_series(case):
    """deltaP of every step (bedPressureDrop.dat's fourth column)."""
    return [r[3] for r in read_dat(case + "/postProcessing/"
                                   "bedPressureDrop/0/bedPressureDrop.dat")]


def check_same_pressure_drop(run_dir):
    a = delta_p_series(run_dir + "/GidaspowDrag")
    b = delta_p_series(run_dir + "/ErgunWenYuDrag")
    worst = max(abs(x - y)/abs(y) for x, y in zip(a, b))
    ok = len(a) == len(b) == 10 and a[0] == b[0] and worst <= 1e-6
    report(ok, "bed pressure drop, 10 steps: first step "
           "%.12g vs %.12g, largest relative difference %.3g <= 1e-6"
           % (a[0], b[0], worst))


if __name__ == "__main__":
    check_same_pressure_drop(sys.argv[1])
    sys.exit(checks.status())
