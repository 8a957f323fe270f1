#!/usr/bin/python3
"""Checks of tests/regression/cfbSniderSeal.sh: tutorials/
circulatingFluidizedBed with seed 2's model (./Allrun -packing mfixSnider
-riserBed 0.16 -standpipeLevel 0.576 -equalArea -endTime 0.1), at 0.1 s.
  - the case as Allrun set it: packingModel mfixSnider, averagingMethod
    diffusion, bandwidth 0.014 (the coarse cellSize), capacityLimit push
    (in mfixSniderCoeffs);
  - the seeded packed column still packed: the volume mean of
    1 - alpha.air, sum((1 - alpha) V)/sum(V), over the standpipe (y
    0.15-0.45 within 0.0127 of its axis x 0.0727, z 0.075) and over the
    lower half of the bend (within 0.0127 of the arc of radius 0.128 about
    (0.201, 0.146), y < 0.08, x < 0.201), each over at least 10 cells, at
    least 0.9 of close pack 0.6 = 0.54, where basic averaging gave 0.527 and
    0.428;
  - the cloud's mass at 0.1 s = the seeded mass, 0.6 x the seeded region's
    volume x 860 kg/m3 (solidsVolume of constant/seededParcels x 860), to
    1e-10 (checks.cloud_mass).

Usage: cfbSniderSeal.py   (in the case)
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ["MPPIC_PROJECT_DIR"], "tutorials", "lib"))
import numpy as np  # noqa: E402
import checks  # noqa: E402
from checks import report as check  # noqa: E402
from mppicPost import internal_field  # noqa: E402 (tutorials/lib)


def check_case_settings():
    """The packing model's settings Allrun wrote."""
    props = re.sub(r"//.*", "", open("constant/kinematicCloudProperties").read())
    for what, pattern in (("packingModel mfixSnider", r"\n\s+packingModel\s+mfixSnider;"),
                          ("averagingMethod diffusion", r"\n\s+averagingMethod\s+diffusion;"),
                          ("bandwidth 0.014", r"\n\s+bandwidth\s+0.014;"),
                          ):
        check(re.search(pattern, props) is not None, "the case sets " + what)
    check(re.search(r"mfixSniderCoeffs\s*\{[^}]*capacityLimit\s+push;", props)
          is not None, "the case sets capacityLimit push (mfixSniderCoeffs)")


def check_column_still_packed():
    """The standpipe's and the lower bend's solids fraction at 0.1 s."""
    C = np.array(internal_field("0/C"))
    V = np.array(internal_field("0/V"))
    a = np.array(internal_field("0.1/alpha.air"))
    x, y, z = C[:, 0], C[:, 1], C[:, 2]
    r = np.hypot(x - 0.201, y - 0.146)
    regions = {
        "standpipe y 0.15-0.45": (np.hypot(x - 0.0727, z - 0.075) < 0.0127) & (y > 0.15) & (y < 0.45),
        "lower bend": (np.hypot(r - 0.128, z - 0.075) < 0.0127) & (y < 0.08) & (x < 0.201),
    }
    for name, m in regions.items():
        s = np.sum((1 - a[m])*V[m])/np.sum(V[m])
        check(m.sum() >= 10 and s >= 0.54,
              "%s at 0.1 s: solids fraction %.3f >= 0.54 (0.9 x close pack; basic: 0.527, 0.428), %d cells"
              % (name, s, m.sum()))


def check_seeded_mass_kept():
    seeded = open("constant/seededParcels").read()
    solids = float(re.search(r"solidsVolume\s+([^;]+);", seeded).group(1))
    checks.cloud_mass(".", "0.1", solids*860, 1e-10)


def main():
    check_case_settings()
    check_column_still_packed()
    check_seeded_mass_kept()
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
