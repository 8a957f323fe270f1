#!/bin/bash
#------------------------------------------------------------------------------
# leanCloudStep <runDir>
# The lean cloud step of mppicPimpleFoam (LeanMPPICCloud: one plain loop for
# the corrections, a correction pass over the parcels with a correction only,
# only the averages the models read) against OpenFOAM's MPPICCloud::motion
# (cloudStep MPPICCloud), on tutorials/validation/kuipersJet for 0.05 s (100 steps),
# with the case's coloringFunction, and for 3 steps with stock's explicit
# packing model (which reads the density and squared-velocity averages too).
# The two steps are the same algorithm: the stock pass tracks the parcels
# without a correction over a zero displacement, which only re-normalises
# their barycentric coordinates (a round-off change), so the states agree to
# round-off: every parcel's position, velocity and statistical weight and the
# gas velocity, pressure and fraction to 1e-9 of each column's largest value
# (written with 17 digits: checks.py sameState). The lean pass must also
# have left parcels out (fewer parcels corrected than in the cloud, from the
# log; checks: leanCloudStep.py).
# Why explicit for 3 steps only: its correction applies where
# (U_p - u_mean).grad(alpha) > 0, and the 5 parcels of a cell start with
# one velocity, so U_p - u_mean is round-off and its sign flips with the
# last bit: at the 4th step 129 parcels (whole cells) differ by 1e-3 of
# their velocity between the two steps (measured), as they would between
# two compilers.
#------------------------------------------------------------------------------
runDir="${1:?usage: leanCloudStep.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
for run in coloringFunction:0.05 explicit:0.0015
do
    packing=${run%:*}
    endTime=${run#*:}
    lean="$runDir/$packing-lean"
    stock="$runDir/$packing-MPPICCloud"
    copyTutorial validation/kuipersJet "$lean"
    # (sed: foamDictionary would write the included parcel weight rounded)
    sed -i "s/^\( *packingModel \+\)[A-Za-z]\+;/\1$packing;/" \
        "$lean/constant/kinematicCloudProperties"
    sed -i "s/^writePrecision .*/writePrecision  17;/" "$lean/system/controlDict"
    runAllrun "$lean" $endTime || exit 1
    rm -rf "$stock"
    cp -r "$lean" "$stock"
    (cd "$stock" && rm -rf 0.0[1-9]* postProcessing log.mppicPimpleFoam)
    sed -i "s/^solidsFractionFrom .*/&\ncloudStep MPPICCloud;/" \
        "$stock/constant/kinematicCloudProperties"
    grep -q "^cloudStep MPPICCloud;" "$stock/constant/kinematicCloudProperties" \
        || { echo "FAIL cloudStep not set"; exit 1; }
    (cd "$stock" && mppicPimpleFoam > log.mppicPimpleFoam 2>&1) \
        || { echo "FAIL run $stock"; exit 1; }
    check sameState "$lean" "$stock" $endTime 1e-9 \
        lagrangian/kinematicCloud/positions lagrangian/kinematicCloud/U \
        lagrangian/kinematicCloud/nParticle U.air p alpha.air || status=1
    /usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/leanCloudStep.py" \
        "$lean/log.mppicPimpleFoam" $endTime || status=1
done
exit $status
