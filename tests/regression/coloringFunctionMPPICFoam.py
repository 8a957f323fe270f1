#!/usr/bin/python3
"""Checks of tests/regression/coloringFunctionMPPICFoam.sh: stock MPPICFoam
with packingModel coloringFunction and the packingMonitor function object
from libmppicModels, on tutorials/verification/sedimentation for 0.05 s
(250 steps of 2e-4 s). The monitor MPPICFoam wrote
(postProcessing/packingMonitor/0/packingMonitor.dat) holds 250 rows (one a
step), each with the 2400 seeded parcels, and the cloud mass at the end is
the seeded mass 5.625e-6 m3 x 2500 kg/m3 = 0.0140625 kg to 1e-9.

Usage: coloringFunctionMPPICFoam.py <case>
"""
import sys

import checks
from checks import read_dat, report as check


def check_monitor(case):
    rows = read_dat(case + "/postProcessing/packingMonitor/0/packingMonitor.dat")
    check(len(rows) == 250, "250 monitor rows (%d)" % len(rows))
    check(all(int(r[1]) == 2400 for r in rows), "2400 parcels in every row")
    mass = rows[-1][2]
    check(abs(mass/0.0140625 - 1) < 1e-9, "cloud mass %.10g kg = 0.0140625 kg" % mass)


if __name__ == "__main__":
    check_monitor(sys.argv[1])
    sys.exit(checks.status())
