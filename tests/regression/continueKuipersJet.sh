#!/bin/bash
#------------------------------------------------------------------------------
# continueKuipersJet <runDir>
# tutorials/kuipersJet run to 0.01 s (20 steps), then continued to 0.02 s
# (./Allrun 0.02 -continue: from the written 0.01 s). Uninterrupted, no cell
# of this bed goes above 5 parcels, 0.600, in these steps. Continued, the
# coloring function must know where each parcel was at the end of the step
# before the stop (LeanMPPICCloud asks it to record the cells the parcels
# were read in); without that, the first step after the restart took a
# sixth and seventh parcel into a full cell (0.84, measured) and kept it.
# (the case writes 12 digits: with 8 the continued cloud mass was 3e-8 off).
# Checks at every step of both pieces: 38 000 parcels, the cloud mass
# 0.6*0.57*0.5*0.015*2660 = 6.8229 kg to 1e-9, the largest cell solids
# fraction <= 0.600 (+1e-6); and that the second piece started from 0.01 s.
#------------------------------------------------------------------------------
runDir="${1:?usage: continueKuipersJet.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial kuipersJet "$runDir/case"
runAllrun "$runDir/case" 0.01 || exit 1
runAllrun "$runDir/case" 0.02 -continue || exit 1

cd "$runDir/case" || exit 1
/usr/bin/python3 - <<'PY'
import re, sys
import checks
from checks import report as check
log = open("log.mppicPimpleFoam").read()
starts = re.findall(r"Starting time loop", log)
steps = re.findall(r"^Time = ([0-9.e-]+)\s*$.*?Cloud: parcels = (\d+), max solids fraction = ([0-9.e+-]+)",
                   log, re.M | re.S)
times = [float(t) for t, _, _ in steps]
check(len(starts) == 2 and len(steps) == 40 and abs(times[20] - 0.0105) < 1e-9,
      "two pieces, 40 steps, the second from 0.01 s (first time %g)" % times[20])
check(all(int(n) == 38000 for _, n, _ in steps), "38000 parcels at every step")
worst = max(float(a) for _, _, a in steps)
after = max(float(a) for _, _, a in steps[20:])
check(worst <= 0.6 + 1e-6,
      "largest cell solids fraction %.6f <= 0.600 at every step (after the restart %.6f)"
      % (worst, after))
mass = 0.6*0.57*0.5*0.015*2660
masses = [float(m) for m in re.findall(r"Current mass in system\s*=\s*([0-9.e+-]+)", log)]
check(len(masses) >= 40 and all(abs(m/mass - 1) < 1e-9 for m in masses),
      "cloud mass %.6g kg = %.6g kg at every step" % (masses[-1] if masses else -1, mass))
sys.exit(checks.status())
PY
