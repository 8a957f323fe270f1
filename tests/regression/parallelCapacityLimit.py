#!/usr/bin/python3
"""Checks of tests/regression/parallelCapacityLimit.sh beside its
sameState comparisons of the gas: the capacity limit makes serial's
decisions on any decomposition. tutorials/validation/circulatingFluidizedBed with
mfixSnider and capacityLimit refuse, continued from 0.005 s to 0.01 s
serially (serial/) and on 2 ranks (parallel/, reconstructed); at 0.01 s:
  - the same parcels, matched by (origProcId, origId), more than 10 000;
  - each at the serial run's place to 1e-6 m and with its velocity to
    1e-4 m/s (largest component difference; measured when written, four
    runs, four meshes: at most 1.4e-9 m and 8.0e-7 m/s, round-off grown
    over 15 steps; with the build before entrants of equal depth were
    ranked by pushOrderKey, the order of the parcel list decided which a
    full cell took: 17 895 of 18 206 parcels more than 1e-9 m apart, 1286
    more than 1e-6 m, up to 3.2 mm and 0.40 m/s: the check can fail).

Usage: parallelCapacityLimit.py   (in the run folder that holds serial/ and parallel/)
"""
import os
import sys

import checks
from checks import report as check, read_rows


def cloud(run):
    """{(origProcId, origId): (position, U)} of a run's cloud at 0.01 s."""
    d = os.path.join(run, "0.01", "lagrangian", "kinematicCloud")
    ids = zip((r[0] for r in read_rows(os.path.join(d, "origProcId"))),
              (r[0] for r in read_rows(os.path.join(d, "origId"))))
    rows = zip(read_rows(os.path.join(d, "positions")), read_rows(os.path.join(d, "U")))
    return {k: (pos[:3], U) for k, (pos, U) in zip(ids, rows)}


def check_same_parcels_places_velocities():
    s, p = cloud("serial"), cloud("parallel")
    check(len(s) > 10000 and set(s) == set(p),
          "the same %d parcels (origProcId, origId) serial and on 2 ranks (%d)" % (len(s), len(p)))
    common = [k for k in s if k in p]
    dx = max(max(abs(a - b) for a, b in zip(s[k][0], p[k][0])) for k in common)
    dU = max(max(abs(a - b) for a, b in zip(s[k][1], p[k][1])) for k in common)
    check(dx <= 1e-6, "each parcel at the serial run's place: largest difference %.3g m <= 1e-6" % dx)
    check(dU <= 1e-4, "each parcel with the serial run's velocity: largest difference %.3g m/s <= 1e-4" % dU)


if __name__ == "__main__":
    check_same_parcels_places_velocities()
    sys.exit(checks.status())
