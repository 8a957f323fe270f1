#!/usr/bin/python3
"""Initial parcels of the Kuipers jet: exactly N parcels in every cell.

Usage:
    makeParcelPositions.py [--perCell 5] [--seed 1]

The bed, 0.57 m x 0.5 m x 0.015 m at solids fraction 0.6 on the 0.75 cm x
1 cm x 0.75 cm cells of jet.geo (76 x 50 x 2 cells), gets N parcels per cell
(MFiX-PIC's baseline: 5, 38 000 parcels of about 1030 particles each), each
at a random position in its own 1/N slice of the cell's height, so that
every cell starts at exactly 0.6 (MFiX-PIC seeds a fixed number of parcels
per cell too). mppicSeedParcels is not used here: its lattice (121 x 105 x
3 points for this bed) does not line up with these non-cubic cells and puts
2 to 12 parcels in a cell, a start at solids fraction up to 1.32.

Writes constant/kinematicCloudPositions and constant/seededParcels
(nParticle, nParcels, solidsVolume, regionVolume), as mppicSeedParcels does.
"""
import argparse
import math
import random

HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  mppicModels tutorial: kuipersJet (makeParcelPositions.py)
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "constant";
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--perCell", type=int, default=5)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    width, depth, bed_height = 0.57, 0.015, 0.5     # as jet.geo
    nx, nz, dy = 76, 2, 0.01                        # cells across, deep; cell height
    ny = int(round(bed_height/dy))
    dx, dz = width/nx, depth/nz
    solids_fraction, diameter = 0.6, 5e-4
    rng = random.Random(args.seed)

    positions = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                for n in range(args.perCell):
                    # kept 1 % of the cell away from its faces
                    positions.append((
                        (i + 0.01 + 0.98*rng.random())*dx,
                        (j + (n + 0.01 + 0.98*rng.random())/args.perCell)*dy,
                        (k + 0.01 + 0.98*rng.random())*dz))

    region = width*bed_height*depth
    solids = solids_fraction*region
    n_particle = solids/(len(positions)*math.pi*diameter**3/6)

    with open("constant/kinematicCloudPositions", "w") as f:
        f.write(HEADER % ("vectorField", "kinematicCloudPositions"))
        f.write("%d\n(\n" % len(positions))
        for p in positions:
            f.write("(%.8g %.8g %.8g)\n" % p)
        f.write(")\n")
    with open("constant/seededParcels", "w") as f:
        f.write(HEADER % ("dictionary", "seededParcels"))
        f.write("nParticle       %.15g;\n\nnParcels        %d;\n\n"
                "solidsVolume    %.15g;\n\nregionVolume    %.15g;\n"
                % (n_particle, len(positions), solids, region))
    print("%d parcels, %d per cell, nParticle %.6g, solids volume %.6g m3"
          % (len(positions), args.perCell, n_particle, solids))


if __name__ == "__main__":
    main()
