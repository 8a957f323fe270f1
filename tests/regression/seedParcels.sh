#!/bin/bash
#------------------------------------------------------------------------------
# seedParcels <runDir>
# mppicSeedParcels on the 1 x 2 x 0.1 m box (4 x 8 x 1 cells of 0.25 x 0.25
# x 0.1 m), region box (0 0 0) (1 1 0.1): the 16 cells of the lower half.
# 10 parcels per cell, solids fraction 0.3, d = 0.01 m; then arrangement
# cell, statisticalWeight 1000 instead of parcelsPerCell, and arrangement
# volume (on the uniform box, with statisticalWeight 490, and on the box
# graded 3:1 in x). checks: seedParcels.py (the parcels' number, places and
# counts per cell, and nParticle, against hand values); here, in bash:
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
    /usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/seedParcels.py" \
        seeding "$case" "$1"
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
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/seedParcels.py" \
    weight "$case" || status=1
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

# arrangement volume (seedParcels.py volume: hand counts per column of cells)
checkVolume()   # <label> <column edges> <expected counts per column> <n>
{
    /usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/seedParcels.py" \
        volume "$case" "$@"
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
