#!/bin/bash
#------------------------------------------------------------------------------
# parallelKuipersJet <runDir>
# processes: 3 (MPI ranks at most; tests/Alltest runs it alone)
# tutorials/kuipersJet for 0.05 s (100 steps) decomposed into 3 with simple
# (1 3 1): two processor boundaries across the column, at 1/3 and 2/3 of its
# height, the lower one through the packed bed; 3 processes on the 2 cores.
# Stock MPPICFoam is reported to hang in KinematicParcel::move with a 3-way
# decomposition (OpenFOAM-8 issue 14): the run must end within 10 minutes.
# Checks at every step: 38000 parcels; the cloud mass
# 0.6*0.57*0.5*0.015*2660 = 6.8229 kg to 1e-9; the largest cell solids
# fraction <= 0.600 (+1e-6), the serial run's bound.
#------------------------------------------------------------------------------
runDir="${1:?usage: parallelKuipersJet.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1

case="$runDir/case"
copyTutorial kuipersJet "$case"
setEntry "$case" system/decomposeParDict numberOfSubdomains 3
setEntry "$case" system/decomposeParDict coeffs/n "(1 3 1)"
timeout 600 "$case/Allrun" 0.05 -parallel
rc=$?
[ $rc = 124 ] && { echo "FAIL: not finished within 600 s (a hang?)"; exit 1; }
grep -l -E 'FOAM FATAL|FOAM aborting' "$case"/log.* && exit 1
[ $rc = 0 ] && [ -d "$case/processor2/0.05" ] || { echo "FAIL: no 0.05 s"; exit 1; }

cd "$case" || exit 1
/usr/bin/python3 - <<'PY'
import re, sys
import checks
from checks import report as check
log = open("log.mppicPimpleFoam").read()
check(re.search(r"^nProcs\s*:\s*3\s*$", log, re.M) is not None, "3 processes")
steps = [(int(n), float(a)) for n, a in re.findall(
    r"^Cloud: parcels = (\d+), max solids fraction = (\S+)$", log, re.M)]
check(len(steps) == 100, "100 steps (%d)" % len(steps))
check(all(n == 38000 for n, _ in steps), "38000 parcels at every step")
worst = max(a for _, a in steps)
check(worst <= 0.6 + 1e-6,
      "largest cell solids fraction %.6f <= 0.600 at every step" % worst)
mass = 0.6*0.57*0.5*0.015*2660
masses = [float(m) for m in re.findall(r"Current mass in system\s*=\s*(\S+)", log)]
check(len(masses) >= 100 and all(abs(m/mass - 1) < 1e-9 for m in masses),
      "cloud mass %.6g kg = %.6g kg at every step" % (masses[-1] if masses else -1, mass))
sys.exit(checks.status())
PY
