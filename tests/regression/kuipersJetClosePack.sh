#!/bin/bash
#------------------------------------------------------------------------------
# kuipersJetClosePack <runDir>
# tutorials/kuipersJet with -seedAtClosePack: the bed seeded at the
# coloring function's close pack, 0.62, with 5 parcels per cell, so that
# one parcel is 0.124 of a cell and a full cell is at close pack (the
# tutorial's 0.6 seeding makes a full cell 5 x 0.12 = 0.600, and the gas of
# such a cell needs 0.225 m/s to carry it, where the annulus gets about
# 0.2), 0.2 s (about 2 minutes). Checks, every step (packing monitor):
#   - 48 rows x 76 x 2 cells x 5 = 36 480 parcels and the cloud mass
#     0.62*0.57*0.48*0.015*2660 = 6.76832 kg;
#   - one parcel 0.62/5 = 0.124 of a cell;
#   - the largest cell solids fraction is exactly close pack, 0.62 (1e-9),
#     at every step: a cell takes its fifth parcel and refuses a sixth
#     (0.744 > 0.62 + 0.5 x 0.124, the overfill), where the tutorial's full
#     cell stays at 0.600;
#   - the bed pressure drop over 0.1-0.2 s within 15 % of the bed weight
#     per area, 6.76832*9.81/(0.57*0.015) = 7765.8 Pa (-seedAtClosePack
#     sets packAtClosePack false; with every full cell a pack, eq 18's >=,
#     measured 2.505 x the weight: the bed froze);
#   - the gas budget's minimum fluidization of a full cell, now at 0.62,
#     equals Ergun's quadratic at e = 0.38 (the same Archimedes number
#     12080.8 as at 0.4): 1.75/e^3 Re^2 + 150(1-e)/e^3 Re = 12080.8 gives
#     Re 6.36547, so U_mf = 0.22493*6.36547/7.49771 = 0.19096 m/s (1e-3).
#   - the log's capacity report at the first step: a full cell holds 5
#     parcels, 0.62 of the cell, and no warning of a full cell below close
#     pack (which the tutorial's seeding gets);
#   - pushThrough prefers no direction the mesh's numbering gives: the bed
#     and its mesh are mirror-symmetric in x and in z, so over the run the
#     refused entrants pushed on toward -x and +x are as many within 2 %
#     of their sum, and those toward -z and +z within 5 % (fewer: a fifth
#     of the x pushes). Measured when written, with the choice before (the
#     first cell with room found, the lowest-numbered): -x 55 297, +x
#     44 466 (10.9 %), -z 10 916, +z 9 691 (5.9 %); with pushOrderKey's
#     choice: -x 72 046, +x 71 576 (0.3 %), -z 13 324, +z 13 959 (2.3 %).
#------------------------------------------------------------------------------
runDir="${1:?usage: kuipersJetClosePack.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial kuipersJet "$runDir/case"
runAllrun "$runDir/case" 0.2 -seedAtClosePack || exit 1

cd "$runDir/case" || exit 1
/usr/bin/python3 kuipersJetResults.py --from 0.1
/usr/bin/python3 - <<'PY'
import sys
sys.path.insert(0, ".")
import kuipersJetResults as k
import kuipersJetGasBudget as gb
import checks
from checks import report as check
res = k.summary(".", 0.1)
mon = res["monitor"]
check(all(r[1] == 36480 for r in mon), "36480 parcels at every step")
mass = 0.62*0.57*0.48*0.015*2660
check(all(abs(r[2]/mass - 1) < 1e-9 for r in mon),
      "cloud mass %.6g kg = %.6g kg at every step" % (mon[-1][2], mass))
check(abs(res["parcelFraction"] - 0.124) < 1e-3,
      "one parcel = %.4f of a cell" % res["parcelFraction"])
largest = [r[4] for r in mon]
check(all(abs(a - 0.62) < 1e-9 for a in largest),
      "largest cell solids fraction 0.62 at every step (%.10f to %.10f)"
      % (min(largest), max(largest)))
check(abs(res["dpRatio"] - 1) <= 0.15,
      "mean deltaP over 0.1-0.2 s %.3f x bed weight within 15 %%"
      % res["dpRatio"])
check(abs(gb.minimum_fluidization(0.62)/0.19096 - 1) < 1e-3,
      "minimum fluidization of a full cell at 0.62: %.5f m/s = Ergun's 0.19096"
      % gb.minimum_fluidization(0.62))
sys.exit(checks.status())
PY
status=$?
# the capacity report at the first step (CapacityLimit::reportFullCell):
# 5 parcels of 0.124 make a full cell at close pack: no warning
fullCellReport log.mppicPimpleFoam "5 parcels, 0.62 of the cell" false || status=1
# the rooms' directions of the pushes (CapacityLimit's log line)
awk '
    /^ *pushThrough: [0-9]+ refused/ { for (i = 1; i < NF; ++i) n[$i] += $(i + 1) }
    function balance(a, b, tol, axis) {
        d = (n[a] - n[b])/(n[a] + n[b]); if (d < 0) d = -d
        ok = n[a] + n[b] > 0 && d <= tol
        printf "%s pushes toward %s %d and %s %d: %.4f of their sum apart (<= %g)\n",
            ok ? "PASS" : "FAIL", a, n[a], b, n[b], d, tol
        return ok
    }
    END { ok = balance("-x", "+x", 0.02) ; ok = balance("-z", "+z", 0.05) && ok; exit !ok }
' log.mppicPimpleFoam || status=1
exit $status
