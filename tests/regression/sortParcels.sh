#!/bin/bash
#------------------------------------------------------------------------------
# sortParcels <runDir>
# sortParcelsEvery (LeanMPPICCloud) puts the parcel list in cell order and
# copies each parcel to a new allocation, and changes nothing else. The
# Kuipers jet's seeded parcels (tutorials/kuipersJet) are injected in a
# shuffled order (the positions file permuted with a fixed seed) and run for
# 3 steps (5e-4 s each) with sortParcelsEvery 0 and 1 (a sort at the start of
# every step). The bed is seeded full (5 parcels in every cell), so no
# capacity decision depends on the order in which parcels come, and the
# two runs must agree to round-off: every parcel, matched by its origId, in
# position and velocity, and the gas velocity, pressure and fraction, to
# 1e-9 of each column's largest value (written with 17 digits). The sorted
# run's written list must be in cell order but for the parcels that changed
# cell in the last step (fewer than 1 % of neighbouring pairs out of order);
# the unsorted one must not be (more than 30 %: the check can fail).
#------------------------------------------------------------------------------
runDir="${1:?usage: sortParcels.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

base="$runDir/base"
copyTutorial kuipersJet "$base"
sed -i "s/^writePrecision .*/writePrecision  17;/" "$base/system/controlDict"
runAllrun "$base" 0.0005 || exit 1
rm -rf "$base"/0.0005 "$base"/postProcessing "$base"/log.mppicPimpleFoam

/usr/bin/python3 - "$base/constant/kinematicCloudPositions" <<'PY' || exit 1
import sys
import numpy as np
path = sys.argv[1]
lines = open(path).read().split("\n")
start = next(i for i, l in enumerate(lines)
             if l.strip().isdigit() and lines[i + 1].strip() == "(")
n = int(lines[start])
rows = lines[start + 2:start + 2 + n]
assert lines[start + 2 + n].strip() == ")" and all(r.startswith("(") for r in rows)
order = np.random.default_rng(19).permutation(n)
lines[start + 2:start + 2 + n] = [rows[i] for i in order]
open(path, "w").write("\n".join(lines))
print("shuffled %d parcel positions" % len(rows))
PY

status=0
for every in 0 1
do
    case="$runDir/every$every"
    rm -rf "$case"
    cp -r "$base" "$case"
    sed -i -e "s/^endTime .*/endTime         0.0015;/" \
        -e "s/^writeInterval .*/writeInterval   0.0015;/" "$case/system/controlDict"
    sed -i "s/^solidsFractionFrom .*/&\nsortParcelsEvery $every;/" \
        "$case/constant/kinematicCloudProperties"
    (cd "$case" && mppicPimpleFoam > log.mppicPimpleFoam 2>&1) \
        || { echo "FAIL run $case"; exit 1; }
done

check sameState "$runDir/every0" "$runDir/every1" 0.0015 1e-9 \
    U.air p alpha.air || status=1

/usr/bin/python3 - "$runDir/every0/0.0015" "$runDir/every1/0.0015" <<'PY' || status=1
import os, sys
import numpy as np
import checks
from checks import read_rows, report

def cloud(time):
    d = os.path.join(time, "lagrangian", "kinematicCloud")
    ids = np.array(read_rows(os.path.join(d, "origId")))[:, 0].astype(int)
    pos = np.array(read_rows(os.path.join(d, "positions")))[:, :3]
    U = np.array(read_rows(os.path.join(d, "U")))
    cells = np.array(read_rows(os.path.join(d, "coordinates")))[:, 4].astype(int)
    order = np.argsort(ids)
    return ids[order], pos[order], U[order], cells

def out_of_order(cells):
    return np.count_nonzero(np.diff(cells) < 0)/(len(cells) - 1)

i0, x0, u0, c0 = cloud(sys.argv[1])
i1, x1, u1, c1 = cloud(sys.argv[2])
report(len(i0) == len(i1) == 38000 and (i0 == i1).all(),
       "the same %d parcels (by origId) in both runs" % len(i1))
for name, a, b in (("position", x0, x1), ("velocity", u0, u1)):
    d = np.abs(a - b).max()/np.abs(a).max()
    report(d <= 1e-9, "parcel %s: largest difference %.2e of the largest value"
           " (tolerance 1e-9)" % (name, d))
report(out_of_order(c1) < 0.01, "sorted list in cell order: %.4f of neighbouring"
       " pairs out of order (< 0.01)" % out_of_order(c1))
report(out_of_order(c0) > 0.30, "unsorted (shuffled) list: %.4f of neighbouring"
       " pairs out of order (> 0.30)" % out_of_order(c0))
sys.exit(checks.status())
PY
exit $status
