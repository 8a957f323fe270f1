#!/bin/bash
#------------------------------------------------------------------------------
# sortParcels <runDir>
# sortParcelsEvery (LeanMPPICCloud) puts the parcel list in cell order and
# copies each parcel to a new allocation, and changes nothing else. The
# Kuipers jet's seeded parcels (tutorials/validation/kuipersJet) are injected in a
# shuffled order (the positions file permuted with a fixed seed) and run for
# 3 steps (5e-4 s each) with sortParcelsEvery 0 and 1 (a sort at the start of
# every step). The bed is seeded full (5 parcels in every cell), so no
# capacity decision depends on the order in which parcels come, and the
# two runs must agree to round-off. checks: checks.py sameState (the gas
# velocity, pressure and fraction to 1e-9) and sortParcels.py (every parcel,
# by origId, in position and velocity to 1e-9; the sorted run's list in cell
# order, the unsorted one not: the check can fail).
#------------------------------------------------------------------------------
runDir="${1:?usage: sortParcels.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

base="$runDir/base"
copyTutorial validation/kuipersJet "$base"
sed -i "s/^writePrecision .*/writePrecision  17;/" "$base/system/controlDict"
runAllrun "$base" 0.0005 || exit 1
rm -rf "$base"/0.0005 "$base"/postProcessing "$base"/log.mppicPimpleFoam

/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/sortParcels.py" \
    shuffle "$base/constant/kinematicCloudPositions" || exit 1

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

/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/sortParcels.py" \
    compare "$runDir/every0/0.0015" "$runDir/every1/0.0015" || status=1
exit $status
