#!/usr/bin/python3
"""Checks of tests/regression/cfbAerationEntry.sh: where
tutorials/validation/circulatingFluidizedBed's Allrun puts the L-valve's aeration when
it enters as a gas source, read from the solver's report of its gas mass
sources ("aerationBend: Q m3/s over N cells, V m3, within 0.0127 m of
(centre); velocity (U)") in <case>/log.mppicPimpleFoam, for the runs "leg"
(-aeration leg -equalArea) and "source" (-aeration source, nominal pipes).

Hand values, from the geometry of record (cfb_geometry.md, cfb.geo:
standpipe axis x 0.0727, bend start y 0.146, leg axis y 0.0176, z 0.075;
bend radius 0.1284) and FTC135's Case 1 aeration (6 SLPM at the gas's own
density, Q = 1e-4 m3/s) through the half-inch port:
    A = pi/4 0.0127^2 = 1.26677e-4 m2,   v = Q/A = 0.789410 m/s
  - leg: half a pipe radius above the leg's floor at its start,
    (0.2011, 0.0176 - 0.0127 x 1.07/2 = 0.0108055, 0.075), blowing up at
    (0, v, 0), over at least 10 cells;
  - source: half a pipe radius inside the bend port at 45 degrees,
    (0.2011 - (0.1284 + 0.0127/2) cos 45, 0.146 - (0.1284 + 0.0127/2) sin 45,
    0.075) = (0.105817, 0.050717, 0.075), at v (cos 45, sin 45, 0);
  - both: Q = 1e-4 m3/s from the source, and none through the bend's port
    (QaerationBendPort 0 in constant/inletFlowRates).
Positions to 1e-6 m, velocities (over v) and flows to 1e-5 relative.

Usage: cfbAerationEntry.py   (in the run folder that holds leg/ and source/)
"""
import math
import re
import sys

import checks
from checks import report as check

A = math.pi/4*0.0127**2
v = 1e-4/A
s = math.sqrt(0.5)
EXPECTED = {
    "leg": ((0.2011, 0.0176 - 0.0127*1.07/2, 0.075), (0.0, v, 0.0)),
    "source": ((0.2011 - (0.1284 + 0.0127/2)*s, 0.146 - (0.1284 + 0.0127/2)*s, 0.075),
               (v*s, v*s, 0.0)),
}
number = r"([-+0-9.eE]+)"
vector = r"\(" + r"\s+".join([number]*3) + r"\)"


def check_aeration_source(case, centre, velocity):
    """The solver's report of the aerationBend source against the hand
    centre, velocity and flow; the bend's port closed."""
    log = open(case + "/log.mppicPimpleFoam").read()
    m = re.search(r"aerationBend: " + number + r" m3/s over (\d+) cells, " + number
                  + r" m3, within 0.0127 m of " + vector + r"; velocity " + vector, log)
    if not m:
        check(False, "%s: the solver's report of the aerationBend source" % case)
        return
    q, cells = float(m.group(1)), int(m.group(2))
    c = [float(m.group(i)) for i in (4, 5, 6)]
    u = [float(m.group(i)) for i in (7, 8, 9)]
    off = max(abs(a - b) for a, b in zip(c, centre))
    check(off <= 1e-6, "%s: source centre (%.7f %.7f %.7f) = (%.7f %.7f %.7f) (%.1e m <= 1e-6)"
          % ((case,) + tuple(c) + tuple(centre) + (off,)))
    du = max(abs(a - b) for a, b in zip(u, velocity))/v
    check(du <= 1e-5, "%s: source velocity (%.6g %.6g %.6g) = (%.6g %.6g %.6g) m/s (%.1e <= 1e-5)"
          % ((case,) + tuple(u) + tuple(velocity) + (du,)))
    check(abs(q/1e-4 - 1) <= 1e-5 and cells >= 10,
          "%s: %.6g m3/s (1e-4) over %d cells (at least 10)" % (case, q, cells))
    flows = open(case + "/constant/inletFlowRates").read()
    port = float(re.search(r"QaerationBendPort\s+" + number + ";", flows).group(1))
    check(port == 0.0, "%s: QaerationBendPort %g (the port closed)" % (case, port))


def main():
    for case, (centre, velocity) in EXPECTED.items():
        check_aeration_source(case, centre, velocity)
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
