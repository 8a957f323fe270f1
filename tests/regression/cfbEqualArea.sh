#!/bin/bash
#------------------------------------------------------------------------------
# cfbEqualArea <runDir>
# tutorials/circulatingFluidizedBed's coarse mesh as its Allrun makes it, with
# and without -equalArea (a few steps each, -endTime 0.002): the meshed
# cross-section of the 1" standpipe (the cells whose centres lie in
# y 0.3-0.8 m, x < 0.15 m: their volume over 0.5 m) and of the 2" riser
# (y 0.3-1.0 m, x > 0.2 m, over 0.7 m), from the mesh's own cell centres and
# volumes (0/C, 0/V), against the pipes' areas pi/4 d^2 (d = 0.0254 and
# 0.0508 m, cfb_geometry.md).
# Checks:
#   - with -equalArea both within 2 % of the pipe's area;
#   - without it the standpipe's is more than 10 % short (the tetrahedra's
#     inscribed hexagon, 17 % measured): the option is what makes the
#     difference, and the check can fail.
#------------------------------------------------------------------------------
runDir="${1:?usage: cfbEqualArea.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

for variant in nominal equalArea
do
    copyTutorial circulatingFluidizedBed "$runDir/$variant"
    args="-endTime 0.002"
    [ "$variant" = equalArea ] && args="$args -equalArea"
    PROGRESS_EVERY=0 runAllrun "$runDir/$variant" $args || exit 1
done

cd "$runDir" || exit 1
/usr/bin/python3 - <<'PY'
import math, sys
sys.path.insert(0, "nominal")
import cfbResults as c
import checks
from checks import report as check

def areas(case):
    C = c.post.internal_field(case + "/0/C")
    V = c.post.internal_field(case + "/0/V")
    stand = math.fsum(v for x, v in zip(C, V) if 0.3 < x[1] < 0.8 and x[0] < 0.15)/0.5
    riser = math.fsum(v for x, v in zip(C, V) if 0.3 < x[1] < 1.0 and x[0] > 0.2)/0.7
    return stand, riser

a1, a2 = math.pi/4*0.0254**2, math.pi/4*0.0508**2
s, r = areas("equalArea")
check(abs(s/a1 - 1) <= 0.02, "-equalArea: standpipe cross-section %.4e m2 = 1\" %.4e (%+.1f %%, within 2 %%)"
      % (s, a1, 100*(s/a1 - 1)))
check(abs(r/a2 - 1) <= 0.02, "-equalArea: riser cross-section %.4e m2 = 2\" %.4e (%+.1f %%, within 2 %%)"
      % (r, a2, 100*(r/a2 - 1)))
s0, r0 = areas("nominal")
check(s0/a1 - 1 < -0.10, "nominal: standpipe cross-section %.4e m2, %+.1f %% of 1\" (more than 10 %% short)"
      % (s0, 100*(s0/a1 - 1)))
print("nominal riser cross-section %.4e m2 (%+.1f %% of 2\")" % (r0, 100*(r0/a2 - 1)))
sys.exit(checks.status())
PY
