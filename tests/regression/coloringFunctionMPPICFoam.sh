#!/bin/bash
#------------------------------------------------------------------------------
# coloringFunctionMPPICFoam <runDir>
# Stock MPPICFoam selects packingModel coloringFunction and the
# packingMonitor function object from libmppicModels (libs in controlDict):
# the sedimentation case for 0.05 s (250 steps) ends normally, and the
# monitor written by MPPICFoam holds 251 rows with the 2400 seeded parcels
# and the seeded mass 5.625e-6 m3 * 2500 kg/m3 = 0.0140625 kg.
#------------------------------------------------------------------------------
runDir="${1:?usage: coloringFunctionMPPICFoam.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial verification/sedimentation "$runDir/case"
setEntry "$runDir/case" system/controlDict application MPPICFoam
setEntry "$runDir/case" system/controlDict endTime 0.05
runAllrun "$runDir/case" || exit 1
grep -q '^End' "$runDir/case/log.MPPICFoam" || { echo "MPPICFoam did not end"; exit 1; }
grep -q 'Selecting packing model coloringFunction' "$runDir/case/log.MPPICFoam" \
    || { echo "coloringFunction not selected"; exit 1; }

/usr/bin/python3 - "$runDir/case" <<'PY'
import sys
rows = [l.split() for l in open(sys.argv[1] +
        "/postProcessing/packingMonitor/0/packingMonitor.dat")
        if l.strip() and not l.startswith("#")]
import checks
from checks import report as check
check(len(rows) == 250, "250 monitor rows (%d)" % len(rows))
check(all(int(r[1]) == 2400 for r in rows), "2400 parcels in every row")
mass = float(rows[-1][2])
check(abs(mass/0.0140625 - 1) < 1e-9, "cloud mass %.10g kg = 0.0140625 kg" % mass)
sys.exit(checks.status())
PY
