#!/bin/bash
#------------------------------------------------------------------------------
# uniformFluidization <runDir>
# tutorials/validation/uniformFluidization (mppicPimpleFoam, coloringFunction,
# GidaspowDrag, 7680 parcels) for 2 s (about 3 minutes): a bed of 0.5 mm
# glass fluidized uniformly at 0.5 m/s = 2.35 Umf (Ergun, README).
# Checks:
#   - the time-mean of (deltaP - gas head)/(m g/A) over 1.2-2 s, after the
#     start-up (the packed bed first lifts, 2.2 x its weight at t = 0),
#     within 3 % of 1, m g/A = 0.1*0.12*0.01*0.6*2500*9.81/0.001 = 1765.8 Pa
#     (measured 0.9869 on 2026-11-27; with fixedFluxPressure on the inlet,
#     which leaves out the first row's drag, 0.966, and with cellPoint
#     interpolation of the gas velocity 0.78: both fail here);
#   - 7680 parcels and the cloud mass 0.18 kg at every step;
#   - the largest cell solids fraction at most max(1.05*0.6, 0.6 + one
#     parcel = 0.6/8) = 0.675 (cell-based field).
# What this short window cannot show (deltaP/weight over 4-10 s within 1.00 +-
# 0.02) is the validation matrix's: bin/validate uniformBed-3, -8 and -16
# (docs/VALIDATION.md).
#------------------------------------------------------------------------------
runDir="${1:?usage: uniformFluidization.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial validation/uniformFluidization "$runDir/case"
runAllrun "$runDir/case" 2 || exit 1

cd "$runDir/case" || exit 1
/usr/bin/python3 uniformFluidizationResults.py --from 1.2 --label test
/usr/bin/python3 - <<'PY'
import sys
sys.path.insert(0, ".")
import uniformFluidizationResults as u
import checks
from checks import report as check
weight = 0.1*0.12*0.01*0.6*2500*9.81/0.001
rows = u.post.read_table("postProcessing/bedPressureDrop/0/bedPressureDrop.dat")
check(all(abs(r[5]/weight - 1) < 1e-9 for r in rows),
      "weight per area %.4f Pa = %.4f Pa at every step" % (rows[-1][5], weight))
res = u.summary(".", 1.2)
check(abs(res["ratio"] - 1) <= 0.03,
      "(deltaP - gas head)/weight over 1.2-2 s %.4f within 3 %% of 1" % res["ratio"])
mon = u.monitor(".")
check(all(r[1] == 7680 for r in mon), "7680 parcels at every step")
check(all(abs(r[2]/0.18 - 1) < 1e-9 for r in mon), "cloud mass 0.18 kg at every step")
bound = max(1.05*0.6, 0.6 + 0.6/8)
check(max(r[4] for r in mon) <= bound + 1e-12,
      "max cell solids fraction %.4f <= %.4f at every step"
      % (max(r[4] for r in mon), bound))
sys.exit(checks.status())
PY
