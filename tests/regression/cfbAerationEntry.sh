#!/bin/bash
#------------------------------------------------------------------------------
# cfbAerationEntry <runDir>
# Where tutorials/circulatingFluidizedBed's Allrun puts the L-valve's aeration
# (FTC135, Case 1: 6 SLPM at the gas's own density, Q = 1e-4 m3/s) when it
# enters as a gas source (a few steps each, -endTime 0.002), read from the
# solver's report of its gas mass sources, against hand values from the
# geometry of record (cfb_geometry.md, cfb.geo: standpipe axis x 0.0727, bend
# start y 0.146, leg axis y 0.0176, z 0.075; bend radius 0.1284) and the
# half-inch port (A = pi/4 0.0127^2 = 1.26677e-4 m2, Q/A = 0.789410 m/s):
#   - -aeration leg -equalArea: half a pipe radius above the leg's floor at
#     its start, (0.2011, 0.0176 - 0.0127 x 1.07/2 = 0.0108055, 0.075),
#     blowing up at (0 0.789410 0) m/s, over at least 10 cells;
#   - -aeration source (nominal pipes): half a pipe radius inside the bend
#     port at 45 degrees, (0.2011 - 0.134750 cos 45, 0.146 - 0.134750 sin 45)
#     = (0.105817, 0.050717, 0.075), at 0.789410 (cos 45, sin 45, 0);
#   - both: 1e-4 m3/s from the source and none through the bend's port
#     (QaerationBendPort 0);
#   - -aeration bogus stops before meshing, exit 1, with a message naming the
#     value and the allowed ones.
#   - -continue -parallel where there are no processor folders stops, exit 1,
#     with a message naming them, and runs nothing.
# Positions to 1e-6 m, velocities and flows to 1e-5 relative.
#------------------------------------------------------------------------------
runDir="${1:?usage: cfbAerationEntry.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
bad="$runDir/bogus"
copyTutorial circulatingFluidizedBed "$bad"
allrunRefuses "$bad" "-aeration bogus: not patch, source or leg" cfb.msh \
    -aeration bogus || status=1
allrunRefuses "$bad" "-continue -parallel: no processor folders" log.mppicPimpleFoam \
    -continue -endTime 1 -parallel || status=1

copyTutorial circulatingFluidizedBed "$runDir/leg"
PROGRESS_EVERY=0 runAllrun "$runDir/leg" -endTime 0.002 -equalArea -aeration leg || exit 1
copyTutorial circulatingFluidizedBed "$runDir/source"
PROGRESS_EVERY=0 runAllrun "$runDir/source" -endTime 0.002 -aeration source || exit 1

cd "$runDir" || exit 1
/usr/bin/python3 - <<'PY' || status=1
import math, re, sys
import checks
from checks import report as check

A = math.pi/4*0.0127**2
v = 1e-4/A
s = math.sqrt(0.5)
expected = {
    "leg": ((0.2011, 0.0176 - 0.0127*1.07/2, 0.075), (0.0, v, 0.0)),
    "source": ((0.2011 - (0.1284 + 0.0127/2)*s, 0.146 - (0.1284 + 0.0127/2)*s, 0.075),
               (v*s, v*s, 0.0)),
}
number = r"([-+0-9.eE]+)"
vector = r"\(" + r"\s+".join([number]*3) + r"\)"
for case, (centre, velocity) in expected.items():
    log = open(case + "/log.mppicPimpleFoam").read()
    m = re.search(r"aerationBend: " + number + r" m3/s over (\d+) cells, " + number
                  + r" m3, within 0.0127 m of " + vector + r"; velocity " + vector, log)
    if not m:
        check(False, "%s: the solver's report of the aerationBend source" % case)
        continue
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
sys.exit(checks.status())
PY
exit $status
