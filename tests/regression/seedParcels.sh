#!/bin/bash
#------------------------------------------------------------------------------
# seedParcels <runDir>
# mppicSeedParcels on the 1 x 2 x 0.1 m box (4 x 8 x 1 cells of 0.25 x 0.25
# x 0.1 m), region box (0 0 0) (1 1 0.1): the 16 cells of the lower half.
# 10 parcels per cell, solids fraction 0.3, d = 0.01 m. Checks:
#   - the lattice: target 10*16 = 160 points on the 1 x 1 x 0.1 box;
#     spacing (0.1/160)^(1/3) = 0.0855 gives nz = round(0.1/0.0855) = 1, then
#     sqrt(1*1*1/160) = 0.0791 gives ny = round(12.65) = 13 and
#     nx = round(160/13) = 12: 156 parcels, all in the region, 8-12 per cell;
#   - nParticle = 0.3*0.1/(156*pi/6*1e-6) = 367.2806379...
#   - arrangement cell on the same region: exactly 10 parcels in each of the
#     16 cells of 0.25 x 0.25 x 0.1 m; the split of a cell closest to cubes
#     is 2 x 5 x 1 (sides 0.125, 0.05, 0.1: ratio 2.5, tied with 5 x 2 x 1,
#     the first in the search; 10 x 1 x 1 gives 10, 1 x 1 x 10 gives 25), so
#     the parcels of a cell lie within +-0.25 sub-spacing of
#     x = 0.0625 + 0.125 i, y = 0.025 + 0.05 j;
#     nParticle = 0.3*0.1/(160*pi/6*1e-6) = 358.09862195...
#   - statisticalWeight 1000 instead of parcelsPerCell (lattice): the
#     lattice density is 0.3/(1000*pi/6*1e-6) per m3, 57.30 points on the
#     1 x 1 x 0.1 box: nz = round(0.1/(0.1/57.30)^(1/3)) = round(0.83) = 1,
#     ny = round(1/sqrt(1/57.30)) = round(7.57) = 8, nx = round(57.30/8) = 7:
#     56 parcels, nParticle = 0.3*0.1/(56*pi/6*1e-6) = 1023.1786..., within
#     the lattice's rounding (2.3 %) of the weight;
#   - arrangement volume (round(N V_cell/V_mean) random points per cell):
#     10 per cell on the box; on the box graded 3:1 in x 5, 8, 11, 16 per
#     cell by column; statisticalWeight 490: 7 per cell (see below);
#   - bad input: solidsFraction 1.2, jitter 1, parcelsPerCell 0, region
#     sphere, an unknown cellZone, a box with min above max, arrangement
#     spiral, and parcelsPerCell 2.5 with arrangement cell each stop with a
#     FatalIOError naming the keyword; so do statisticalWeight 0.5 (range
#     [1, inf)), statisticalWeight with arrangement cell, and both or
#     neither of parcelsPerCell and statisticalWeight.
#------------------------------------------------------------------------------
runDir="${1:?usage: seedParcels.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

case="$runDir/box"
rm -rf "$case"
cp -r "$MPPIC_PROJECT_DIR/tests/unit/cases/box" "$case"
blockMesh -case "$case" > "$runDir/log.blockMesh" 2>&1 || exit 1

writeDict()
{
    cat > "$case/system/mppicSeedParcelsDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object mppicSeedParcelsDict; }
region          ${1:-box};
box             ${5:-(0 0 0) (1 1 0.1)};
cellZone        noSuchZone;
solidsFraction  ${2:-0.3};
parcelsPerCell  ${3:-10};
diameter        0.01;
jitter          ${4:-0.5};
seed            3;
arrangement     ${6:-lattice};
DICT
}

writeDict
mppicSeedParcels -case "$case" > "$runDir/log.seed" 2>&1 || exit 1
cat "$runDir/log.seed" | tail -4

# checkSeeding <lattice|cell>: the positions and nParticle just written
checkSeeding()
{
    /usr/bin/python3 - "$case" "$1" <<'PY'
import math, re, sys
case, mode = sys.argv[1], sys.argv[2]
from checks import seeded_parcels
pts, nParticle = seeded_parcels(case)
import checks
from checks import report as check
counts = {}
for x, y, z in pts:
    key = (min(int(x/0.25), 3), min(int(y/0.25), 3))
    counts[key] = counts.get(key, 0) + 1
check(all(0 <= x <= 1 and 0 <= y <= 1 and 0 <= z <= 0.1 for x, y, z in pts),
      "all parcels in the region box")
if mode == "lattice":
    n = 156
    check(len(counts) == 16 and all(8 <= c <= 12 for c in counts.values()),
          "16 cells with 8-12 parcels each: %s" % sorted(counts.values()))
else:
    n = 160
    check(len(counts) == 16 and all(c == 10 for c in counts.values()),
          "arrangement cell: 10 parcels in each of the 16 cells: %s"
          % sorted(counts.values()))
    def near(v, h, origin):
        k = round((v - origin)/h)
        return abs(v - origin - k*h) <= 0.25*h + 1e-6
    check(all(near(x, 0.125, 0.0625) and near(y, 0.05, 0.025) for x, y, z in pts),
          "parcels within a quarter sub-spacing of the 2 x 5 x 1 sub-box centres")
check(len(pts) == n, "%d parcels (%d)" % (n, len(pts)))
expected = 0.3*0.1/(n*math.pi/6*1e-6)
check(abs(nParticle/expected - 1) < 1e-12,
      "nParticle %.15g = 0.3*0.1/(%d*pi/6*1e-6) = %.15g" % (nParticle, n, expected))
sys.exit(checks.status())
PY
}

checkSeeding lattice || exit 1

writeDict box 0.3 10 0.5 "(0 0 0) (1 1 0.1)" cell
mppicSeedParcels -case "$case" > "$runDir/log.seedCell" 2>&1 || exit 1
checkSeeding cell || exit 1

# writeWeightDict <entries>: the lattice dictionary with the given count
# entries (statisticalWeight and/or parcelsPerCell) and arrangement
writeWeightDict()
{
    cat > "$case/system/mppicSeedParcelsDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object mppicSeedParcelsDict; }
region          box;
box             (0 0 0) (1 1 0.1);
solidsFraction  0.3;
$1
diameter        0.01;
jitter          0.5;
seed            3;
DICT
}

status=0
writeWeightDict "statisticalWeight 1000;"
mppicSeedParcels -case "$case" > "$runDir/log.seedWeight" 2>&1 || exit 1
/usr/bin/python3 - "$case" <<'PY' || status=1
import math, re, sys
case = sys.argv[1]
from checks import seeded_parcels
pts, nParticle = seeded_parcels(case)
n = len(pts)
expected = 0.3*0.1/(56*math.pi/6*1e-6)
import checks
from checks import report as check
check(n == 56, "statisticalWeight 1000: 56 parcels (%d)" % n)
check(abs(nParticle/expected - 1) < 1e-12,
      "nParticle %.15g = 0.3*0.1/(56*pi/6*1e-6) = %.15g" % (nParticle, expected))
check(abs(nParticle/1000 - 1) < 0.025,
      "nParticle within 2.5 % of the statistical weight 1000")
sys.exit(checks.status())
PY
for bad in "statisticalWeight 0.5;:statisticalWeight:[1, inf)" \
           "statisticalWeight 1000; arrangement cell;:statisticalWeight:arrangement lattice" \
           "statisticalWeight 1000; parcelsPerCell 10;:parcelsPerCell and statisticalWeight:both" \
           "jitter 0.5;:parcelsPerCell and statisticalWeight:neither"
do
    entries="${bad%%:*}"
    rest="${bad#*:}"
    keyword="${rest%%:*}"
    what="${rest#*:}"
    writeWeightDict "$entries"
    log="$runDir/log.bad.weight.$(echo "$entries" | tr -cd 'a-zA-Z0-9')"
    mppicSeedParcels -case "$case" > "$log" 2>&1
    rc=$?
    check fatal "$log" $rc "$keyword" "$what" || status=1
done

# arrangement volume: on the uniform box, 10 parcels in each of the 16
# cells; on the box graded 3:1 in x (blockMesh simpleGrading (3 1 1): cell
# widths 0.13294, 0.19172, 0.27652, 0.39882 m, mean 0.25 m), round(10 w/0.25)
# = 5, 8, 11, 16 parcels in the cells of each column (160 in all);
# statisticalWeight 490 on the uniform box: 0.3*0.1/(490*pi/6*1e-6*16) =
# 7.31 per cell, so 7 in each cell, 112 parcels, nParticle =
# 0.3*0.1/(112*pi/6*1e-6) = 511.5870...
checkVolume()   # <label> <column edges> <expected counts per column> <n>
{
    /usr/bin/python3 - "$case" "$@" <<'PY'
import bisect, math, re, sys
case, label, edges, counts, n = sys.argv[1:6]
edges = [float(e) for e in edges.split()]
counts = [int(c) for c in counts.split()]
n = int(n)
from checks import seeded_parcels
pts, nParticle = seeded_parcels(case)
import checks
from checks import report as check
cells = {}
for x, y, z in pts:
    key = (bisect.bisect_right(edges, x) - 1, int(y/0.25))
    cells[key] = cells.get(key, 0) + 1
check(len(pts) == n, "%s: %d parcels (%d)" % (label, n, len(pts)))
check(all(0 <= x <= 1 and 0 <= y <= 1 and 0 <= z <= 0.1 for x, y, z in pts),
      "%s: all parcels in the region" % label)
check(sorted(cells) == [(i, j) for i in range(4) for j in range(4)]
      and all(cells[(i, j)] == counts[i] for i, j in cells),
      "%s: parcels per cell by column %s: %s" % (label, counts,
      [[cells.get((i, j), 0) for j in range(4)] for i in range(4)]))
expected = 0.3*0.1/(n*math.pi/6*1e-6)
check(abs(nParticle/expected - 1) < 1e-12,
      "%s: nParticle %.15g = 0.3*0.1/(%d*pi/6*1e-6) = %.15g"
      % (label, nParticle, n, expected))
sys.exit(checks.status())
PY
}
writeDict box 0.3 10 0.5 "(0 0 0) (1 1 0.1)" volume
mppicSeedParcels -case "$case" > "$runDir/log.seedVolume" 2>&1 || exit 1
checkVolume "volume, uniform" "0 0.25 0.5 0.75 1" "10 10 10 10" 160 || status=1
writeWeightDict "statisticalWeight 490; arrangement volume;"
mppicSeedParcels -case "$case" > "$runDir/log.seedVolumeWeight" 2>&1 || exit 1
checkVolume "volume, statisticalWeight 490" "0 0.25 0.5 0.75 1" "7 7 7 7" 112 \
    || status=1
graded="$runDir/graded"
rm -rf "$graded"
cp -r "$case" "$graded"
sed -i 's/simpleGrading (1 1 1)/simpleGrading (3 1 1)/' \
    "$graded/system/blockMeshDict"
blockMesh -case "$graded" > "$runDir/log.blockMesh.graded" 2>&1 || exit 1
writeDict box 0.3 10 0.5 "(0 0 0) (1 1 0.1)" volume
cp "$case/system/mppicSeedParcelsDict" "$graded/system/"
mppicSeedParcels -case "$graded" > "$runDir/log.seedVolumeGraded" 2>&1 || exit 1
(
    case="$graded"
    checkVolume "volume, graded 3:1" "0 0.13294 0.32466 0.60118 1" "5 8 11 16" 160
) || status=1

for bad in "box 1.2 10 0.5:solidsFraction" "box 0.3 10 1:jitter" \
           "box 0.3 0 0.5:parcelsPerCell" "sphere 0.3 10 0.5:region" \
           "cellZone 0.3 10 0.5:cellZone"
do
    args="${bad%%:*}"
    keyword="${bad##*:}"
    writeDict $args
    mppicSeedParcels -case "$case" > "$runDir/log.bad.$keyword" 2>&1
    rc=$?
    check fatal "$runDir/log.bad.$keyword" $rc "$keyword" || status=1
done
# box with min above max
writeDict box 0.3 10 0.5 "(1 1 0.1) (0 0 0)"
mppicSeedParcels -case "$case" > "$runDir/log.bad.box" 2>&1
rc=$?
check fatal "$runDir/log.bad.box" $rc "keyword box" "min < max" || status=1
writeDict box 0.3 10 0.5 "(0 0 0) (1 1 0.1)" spiral
mppicSeedParcels -case "$case" > "$runDir/log.bad.arrangement" 2>&1
rc=$?
check fatal "$runDir/log.bad.arrangement" $rc "arrangement" "spiral" || status=1
writeDict box 0.3 2.5 0.5 "(0 0 0) (1 1 0.1)" cell
mppicSeedParcels -case "$case" > "$runDir/log.bad.perCell" 2>&1
rc=$?
check fatal "$runDir/log.bad.perCell" $rc "parcelsPerCell" "integer" || status=1
exit $status
