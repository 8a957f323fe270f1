#!/usr/bin/python3
"""The shuffled positions and the checks of tests/regression/sortParcels.sh:
sortParcelsEvery (LeanMPPICCloud) puts the parcel list in cell order and
changes nothing else. The Kuipers jet's seeded parcels are injected in a
shuffled order (the positions file permuted with numpy's default_rng(19))
and run for 3 steps with sortParcelsEvery 0 and 1 (every0/, every1/). The
bed is seeded full (5 parcels in every cell), so no capacity decision
depends on the order in which parcels come, and at 0.0015 s:
  - the same 38000 parcels (by origId) in both runs;
  - every parcel's position and velocity, matched by origId, the same to
    1e-9 of the largest value, max|a - b|/max|a|;
  - the sorted run's written list in cell order but for the parcels that
    changed cell in the last step: fewer than 1 % of neighbouring pairs out
    of order (the cell, the fifth column of coordinates, decreasing);
  - the unsorted (shuffled) one not: more than 30 % (the check can fail).
(The gas fields: checks.py sameState, in the script.)

Usage:
    sortParcels.py shuffle <kinematicCloudPositions>   (rewritten in place)
    sortParcels.py compare <every0 time dir> <every1 time dir>
"""
import os
import sys

import numpy as np

import checks
from checks import read_rows, report


def shuffle_positions(path):
    """The positions list in the order of a fixed random permutation."""
    lines = open(path).read().split("\n")
    start = next(i for i, l in enumerate(lines)
                 if l.strip().isdigit() and lines[i + 1].strip() == "(")
    n = int(lines[start])
    rows = lines[start + 2:start + 2 + n]
    assert lines[start + 2 + n].strip() == ")" and all(r.startswith("(") for r in rows)
    order = np.random.default_rng(19).permutation(n)
    lines[start + 2:start + 2 + n] = [rows[i] for i in order]
    open(path, "w").write("\n".join(lines))
    print("shuffled %d parcel positions" % len(rows))


def cloud(time):
    """origId, position and U by origId; the cells in the written order."""
    d = os.path.join(time, "lagrangian", "kinematicCloud")
    ids = np.array(read_rows(os.path.join(d, "origId")))[:, 0].astype(int)
    pos = np.array(read_rows(os.path.join(d, "positions")))[:, :3]
    U = np.array(read_rows(os.path.join(d, "U")))
    cells = np.array(read_rows(os.path.join(d, "coordinates")))[:, 4].astype(int)
    order = np.argsort(ids)
    return ids[order], pos[order], U[order], cells


def out_of_order(cells):
    return np.count_nonzero(np.diff(cells) < 0)/(len(cells) - 1)


def check_sorted_equals_unsorted(time0, time1):
    i0, x0, u0, c0 = cloud(time0)
    i1, x1, u1, c1 = cloud(time1)
    report(len(i0) == len(i1) == 38000 and (i0 == i1).all(),
           "the same %d parcels (by origId) in both runs" % len(i1))
    for name, a, b in (("position", x0, x1), ("velocity", u0, u1)):
        d = np.abs(a - b).max()/np.abs(a).max()
        report(d <= 1e-9, "parcel %s: largest difference %.2e of the largest value"
               " (tolerance 1e-9)" % (name, d))
    report(out_of_order(c1) < 0.01, "sorted list in cell order: %.4f of neighbouring"
           " pairs out of order (< 0.01)" % out_of_order(c1))
    report(out_of_order(c0) > 0.30, "unsorted (shuffled) list: %.4f of neighbouring"
           " pairs out of order (> 0.30)" % out_of_order(c0))


def main(argv):
    return checks.run_command(argv, {
        "shuffle": shuffle_positions,
        "compare": check_sorted_equals_unsorted})


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
