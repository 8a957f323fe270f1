#!/usr/bin/python3
"""Checks of tests/regression/seedParcels.sh: mppicSeedParcels on the
1 x 2 x 0.1 m box (4 x 8 x 1 cells of 0.25 x 0.25 x 0.1 m), region box
(0 0 0) (1 1 0.1): the 16 cells of the lower half; solids fraction 0.3,
d = 0.01 m. From the positions and nParticle it wrote
(constant/kinematicCloudPositions, constant/seededParcels), with
nParticle = 0.3 x 0.1/(n pi/6 1e-6) for n parcels on the 0.1 m3 region
(to 1e-12):
  seeding lattice (10 parcels per cell): target 10 x 16 = 160 points on the
    1 x 1 x 0.1 box; spacing (0.1/160)^(1/3) = 0.0855 gives
    nz = round(0.1/0.0855) = 1, then sqrt(1 x 1 x 1/160) = 0.0791 gives
    ny = round(12.65) = 13 and nx = round(160/13) = 12: 156 parcels, all in
    the region, 8-12 per cell; nParticle = 367.2806379...
  seeding cell (arrangement cell, same region): exactly 10 parcels in each
    of the 16 cells; the split of a cell closest to cubes is 2 x 5 x 1
    (sides 0.125, 0.05, 0.1: ratio 2.5, tied with 5 x 2 x 1, the first in
    the search; 10 x 1 x 1 gives 10, 1 x 1 x 10 gives 25), so the parcels of
    a cell lie within +-0.25 sub-spacing of x = 0.0625 + 0.125 i,
    y = 0.025 + 0.05 j; nParticle = 358.09862195...
  weight (statisticalWeight 1000 instead of parcelsPerCell, lattice): the
    lattice density is 0.3/(1000 pi/6 1e-6) per m3, 57.30 points on the
    box: nz = round(0.1/(0.1/57.30)^(1/3)) = round(0.83) = 1,
    ny = round(1/sqrt(1/57.30)) = round(7.57) = 8, nx = round(57.30/8) = 7:
    56 parcels, nParticle = 1023.1786..., within the lattice's rounding
    (2.5 %) of the weight;
  volume (arrangement volume: round(N V_cell/V_mean) random points per
    cell), parcels per cell by column of cells (edges in x):
      - uniform box: 10 in each of the 16 cells, 160;
      - statisticalWeight 490 on the uniform box:
        0.3 x 0.1/(490 pi/6 1e-6 x 16) = 7.31 per cell, so 7 in each cell,
        112 parcels, nParticle = 511.5870...;
      - the box graded 3:1 in x (simpleGrading (3 1 1): cell widths
        0.13294, 0.19172, 0.27652, 0.39882 m, mean 0.25 m):
        round(10 w/0.25) = 5, 8, 11, 16 per cell by column, 160 in all.
(The bad inputs are checked in the script: check fatal.)

Usage:
    seedParcels.py seeding <case> lattice|cell
    seedParcels.py weight <case>
    seedParcels.py volume <case> <label> "<column edges>" "<counts per column>" <n>
"""
import bisect
import math
import sys

import checks
from checks import report as check, seeded_parcels


def check_seeding(case, mode):
    """The lattice's 156 parcels (8-12 a cell) or arrangement cell's 10 a
    cell on the 2 x 5 x 1 sub-box centres; nParticle."""
    pts, nParticle = seeded_parcels(case)
    counts = {}
    for x, y, z in pts:
        key = (min(int(x/0.25), 3), min(int(y/0.25), 3))
        counts[key] = counts.get(key, 0) + 1
    check(all(0 <= x <= 1 and 0 <= y <= 1 and 0 <= z <= 0.1 for x, y, z in pts),
          "all parcels in the region box")
    if mode == "lattice":
        n = 156
        check(len(counts) == 16 and all(8 <= c <= 12 for c in counts.values()),
              "16 cells with 8-12 parcels each: %s" % sorted(counts.values()))
    else:
        n = 160
        check(len(counts) == 16 and all(c == 10 for c in counts.values()),
              "arrangement cell: 10 parcels in each of the 16 cells: %s"
              % sorted(counts.values()))

        def near(v, h, origin):
            k = round((v - origin)/h)
            return abs(v - origin - k*h) <= 0.25*h + 1e-6
        check(all(near(x, 0.125, 0.0625) and near(y, 0.05, 0.025) for x, y, z in pts),
              "parcels within a quarter sub-spacing of the 2 x 5 x 1 sub-box centres")
    check(len(pts) == n, "%d parcels (%d)" % (n, len(pts)))
    expected = 0.3*0.1/(n*math.pi/6*1e-6)
    check(abs(nParticle/expected - 1) < 1e-12,
          "nParticle %.15g = 0.3*0.1/(%d*pi/6*1e-6) = %.15g" % (nParticle, n, expected))


def check_statistical_weight(case):
    """statisticalWeight 1000: 56 parcels, nParticle within 2.5 % of it."""
    pts, nParticle = seeded_parcels(case)
    n = len(pts)
    expected = 0.3*0.1/(56*math.pi/6*1e-6)
    check(n == 56, "statisticalWeight 1000: 56 parcels (%d)" % n)
    check(abs(nParticle/expected - 1) < 1e-12,
          "nParticle %.15g = 0.3*0.1/(56*pi/6*1e-6) = %.15g" % (nParticle, expected))
    check(abs(nParticle/1000 - 1) < 0.025,
          "nParticle within 2.5 % of the statistical weight 1000")


def check_volume_arrangement(case, label, edges, counts, n):
    """arrangement volume: the parcels per cell of each column of cells
    (edges in x) and their number; nParticle."""
    edges = [float(e) for e in edges.split()]
    counts = [int(c) for c in counts.split()]
    n = int(n)
    pts, nParticle = seeded_parcels(case)
    cells = {}
    for x, y, z in pts:
        key = (bisect.bisect_right(edges, x) - 1, int(y/0.25))
        cells[key] = cells.get(key, 0) + 1
    check(len(pts) == n, "%s: %d parcels (%d)" % (label, n, len(pts)))
    check(all(0 <= x <= 1 and 0 <= y <= 1 and 0 <= z <= 0.1 for x, y, z in pts),
          "%s: all parcels in the region" % label)
    check(sorted(cells) == [(i, j) for i in range(4) for j in range(4)]
          and all(cells[(i, j)] == counts[i] for i, j in cells),
          "%s: parcels per cell by column %s: %s" % (label, counts,
          [[cells.get((i, j), 0) for j in range(4)] for i in range(4)]))
    expected = 0.3*0.1/(n*math.pi/6*1e-6)
    check(abs(nParticle/expected - 1) < 1e-12,
          "%s: nParticle %.15g = 0.3*0.1/(%d*pi/6*1e-6) = %.15g"
          % (label, nParticle, n, expected))


def main(argv):
    return checks.run_command(argv, {
        "seeding": check_seeding, "weight": check_statistical_weight,
        "volume": lambda *a: check_volume_arrangement(*a[:5])})


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
