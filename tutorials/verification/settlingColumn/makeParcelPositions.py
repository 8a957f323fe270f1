#!/usr/bin/python3
"""Write constant/kinematicCloudPositions for the settling column.

A regular lattice of parcels filling 0 < x < 0.04, 0.10 < y < 0.35,
0 < z < 0.01 m, one parcel at the centre of each lattice cell:
16 x 100 x 2 = 3200 parcels. Deterministic, so serial and parallel runs
(and both solvers) start from the same cloud.
"""
import sys

nx, ny, nz = 16, 100, 2
x0, x1 = 0.0, 0.04
y0, y1 = 0.10, 0.35
z0, z1 = 0.0, 0.01

header = """FoamFile
{
    version     2.0;
    format      ascii;
    class       vectorField;
    location    "constant";
    object      kinematicCloudPositions;
}

"""


def centres(n, lo, hi):
    step = (hi - lo)/n
    return [lo + (i + 0.5)*step for i in range(n)]


def main(path):
    points = [(x, y, z)
              for z in centres(nz, z0, z1)
              for y in centres(ny, y0, y1)
              for x in centres(nx, x0, x1)]
    with open(path, "w") as f:
        f.write(header)
        f.write("%d\n(\n" % len(points))
        for p in points:
            f.write("(%.6g %.6g %.6g)\n" % p)
        f.write(")\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "constant/kinematicCloudPositions")
