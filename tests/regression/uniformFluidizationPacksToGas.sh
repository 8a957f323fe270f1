#!/bin/bash
#------------------------------------------------------------------------------
# uniformFluidizationPacksToGas <runDir>
# tutorials/validation/uniformFluidization with -packsToGas (coloringFunction
# with conserveMomentum gas: the packs take the reactions, and those no
# support holds hand them to the gas; PIMPLE balanceImplicitDrag true) at
# 3 parcels per packed cell (2880
# parcels of 382 particles), 2 s (about 2 minutes). Checks, over 1.2-2 s:
#   - (deltaP - gas head)/(m g/A) within 2 % of 1,
#     m g/A = 0.1*0.12*0.01*0.6*2500*9.81/0.001 = 1765.8 Pa;
#   - the packs' reactions the gas took (packingMonitor's
#     gasPackingMomentum) at least 0.05 of the weight downward (measured
#     -0.131: the falling parcels' landings on the packs; 0 if the packs'
#     parcels took them);
#   - what the packing step leaves to the supports, its force on the
#     parcels plus the part the gas took, below 0.02 of the weight
#     (measured 0.004);
#   - 2880 parcels and the cloud mass 0.18 kg at every step; the largest
#     cell solids fraction at most max(1.05*0.6, 0.6 + one parcel 0.2) = 0.8
#     (measured 0.600), and the packing monitor's count of cells above
#     close pack 0 at every step: its full cells hold 3 x 0.2 = 0.6 to
#     round-off, which is not above it (counted as computed, all 960 full
#     cells were, from the first step).
#------------------------------------------------------------------------------
runDir="${1:?usage: uniformFluidizationPacksToGas.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial validation/uniformFluidization "$runDir/case"
runAllrun "$runDir/case" 2 -packsToGas -perCell 3 || exit 1

cd "$runDir/case" || exit 1
/usr/bin/python3 uniformFluidizationResults.py --from 1.2 --label test
/usr/bin/python3 - <<'PY'
import sys
sys.path.insert(0, ".")
import uniformFluidizationResults as u
import checks
from checks import report as check
res = u.summary(".", 1.2)
check(abs(res["ratio"] - 1) <= 0.02,
      "(deltaP - gas head)/weight over 1.2-2 s %.4f within 2 %% of 1"
      % res["ratio"])
check(res["toGas"] <= -0.05,
      "the gas took the packs' reactions: %.4f of the weight (<= -0.05)"
      % res["toGas"])
supports = res["packing"] + res["toGas"]
check(abs(supports) < 0.02,
      "the packing step leaves the supports %.4f of the weight (< 0.02)"
      % supports)
mon = u.monitor(".")
check(all(r[1] == 2880 for r in mon), "2880 parcels at every step")
check(all(abs(r[2]/0.18 - 1) < 1e-9 for r in mon),
      "cloud mass 0.18 kg at every step")
bound = max(1.05*0.6, 0.6 + 0.6/3)
check(max(r[4] for r in mon) <= bound + 1e-12,
      "max cell solids fraction %.4f <= %.4f at every step"
      % (max(r[4] for r in mon), bound))
check(all(r[5] == 0 for r in mon),
      "no cell above close pack by more than round-off at any step "
      "(largest count %d)" % max(r[5] for r in mon))
sys.exit(checks.status())
PY
