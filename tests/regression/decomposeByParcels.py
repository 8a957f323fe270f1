#!/usr/bin/python3
"""Checks of tests/regression/decomposeByParcels.sh: mppicDecomposeByParcels
on tutorials/validation/uniformFluidization, 20 x 80 x 2 cubic cells (3200,
rows of 40), a bed 24 rows high of exactly 8 parcels per cell (960 cells,
7680 parcels), cut in two along y, from its table in the logs
("proc  cells  parcels  weight" rows).
  - parcelWeight 1 (log.weighted): each bed cell weighs 1 + 8 = 9 and each
    gas cell 1, in all 960 x 9 + 2240 = 10880, 5440 a processor; processor
    0 takes the lowest 5440/9 = 604.4 bed cells: 604 or 605 cells, 4832 or
    4840 parcels; the two with 3200 cells and 7680 parcels in all, both
    weights within half a bed cell (4.5) of 5440;
  - parcelWeight 0 (log.unweighted): simple's cut, 1600 cells each;
  - mppicPimpleFoam on 2 ranks on the manual decomposition
    (log.mppicPimpleFoam): 7680 parcels at each of its 10 steps.

Usage: decomposeByParcels.py   (in the case)
"""
import re

import checks
from checks import report as check


def table(log):
    """The rows (processor, cells, parcels, weight) of the tool's table."""
    rows = re.findall(r"^(\d+)  (\d+)  (\d+)  ([0-9.e+]+)$", open(log).read(), re.M)
    return [(int(a), int(b), int(c), float(d)) for a, b, c, d in rows]


def check_weighted_cut():
    w = table("log.weighted")
    check(len(w) == 2 and sum(r[1] for r in w) == 3200 and sum(r[2] for r in w) == 7680,
          "two processors with 3200 cells and 7680 parcels in all: %s" % w)
    check(w[0][1] in (604, 605) and w[0][2] in (4832, 4840),
          "processor 0: %d cells (604 or 605), %d parcels (4832 or 4840)" % w[0][1:3])
    check(all(abs(r[3] - 5440) <= 4.5 for r in w),
          "weights %s within 4.5 of 5440" % [r[3] for r in w])


def check_unweighted_cut():
    u = table("log.unweighted")
    check([r[1] for r in u] == [1600, 1600], "parcelWeight 0: cells %s = simple's 1600, 1600"
          % [r[1] for r in u])


def check_parallel_run():
    log = open("log.mppicPimpleFoam").read()
    counts = re.findall(r"Cloud: parcels = (\d+)", log)
    check(len(counts) == 10 and all(int(c) == 7680 for c in counts),
          "2 ranks on the manual decomposition: 7680 parcels at each of %d steps" % len(counts))


if __name__ == "__main__":
    check_weighted_cut()
    check_unweighted_cut()
    check_parallel_run()
    raise SystemExit(checks.status())
