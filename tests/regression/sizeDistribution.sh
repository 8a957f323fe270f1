#!/bin/bash
#------------------------------------------------------------------------------
# sizeDistribution <runDir>
# tutorials/verification/sedimentation with the sizes of OpenFOAM's
# MPPICFoam cyclone tutorial (./Allrun <model> -sizeDistribution: normal,
# 20-180 um), with coloringFunction and with mfixSnider (1 s each, about a
# minute): sizeDistributionResults.py --check, i.e. the largest cell solids
# fraction at every step within close pack plus the largest parcel over its
# cell (0.666), no cell above max(1.05 alpha_cp, alpha_cp + V_parcel/V_cell)
# at any written time, each size class's mass kept to 1e-12. And the seeded
# distribution itself: the volume mean diameter the seeder takes is 103.03 um
# (E[d^3] = mu^3 + 3 mu sigma^2 with mu 100 um, sigma 25/sqrt(2) um, the cut
# at 20 and 180 um negligible), and at least 95 % of the parcels lie in the
# two middle classes, 60-140 um (mu -/+ 2.26 sigma: 97.6 %).
#------------------------------------------------------------------------------
runDir="${1:?usage: sizeDistribution.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
for model in coloringFunction mfixSnider
do
    case="$runDir/$model"
    copyTutorial verification/sedimentation "$case"
    runAllrun "$case" "$model" -sizeDistribution || exit 1
    (cd "$case" && /usr/bin/python3 sizeDistributionResults.py --check) \
        | tee "$case/results.txt" || status=1
    /usr/bin/python3 - "$case" <<'PY' || status=1
import re, sys
import checks
case = sys.argv[1]
d = float(re.search(r"^diameter\s+([^;]+);", open(case + "/system/mppicSeedParcelsDict").read(), re.M).group(1))
hand = 1e-4*(1 + 3*(0.25/2**0.5)**2)**(1/3)
checks.report(abs(d/hand - 1) < 1e-5, "seeded diameter %.6g m = the volume mean %.6g m" % (d, hand))
rows = [l.split("|") for l in open(case + "/results.txt") if re.match(r"^\s*\d+-\s*\d+ \|", l)]
parcels = [int(r[1]) for r in rows]
middle = (parcels[1] + parcels[2])/sum(parcels)
checks.report(len(rows) == 4 and middle >= 0.95, "%.3f of the parcels in 60-140 um (>= 0.95)" % middle)
sys.exit(checks.status())
PY
done
exit $status
