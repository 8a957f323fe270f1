#!/bin/bash
#------------------------------------------------------------------------------
# depositionConservation <runDir>
# tutorials/verification/depositionConservation shortened to 2 periods
# (0.5 s; about 6-15 s CPU each), once per conservative averagingMethod
# (basic, linearHat, cornerNodes, diffusion), the gas fraction deposited by it
# (solidsFractionFrom averaging): 480 parcels starting across the cyclic
# faces of the periodic cube. (OpenFOAM's dual is not conservative here:
# 1.7 % of the solids volume missing, see the case's README.)
# At every period all parcels present and
#     |sum eps_g V + sum parcel volumes - V_total|/V_total <= 1e-14.
# What this short window cannot show is the validation matrix's: bin/validate
# depositionConservation (docs/VALIDATION.md).
#------------------------------------------------------------------------------
runDir="${1:?usage: depositionConservation.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
for method in basic linearHat cornerNodes diffusion
do
    copyTutorial verification/depositionConservation "$runDir/$method"
    setEntry "$runDir/$method" system/controlDict endTime 0.5
    runAllrun "$runDir/$method" "$method" || exit 1
    (cd "$runDir/$method" && /usr/bin/python3 \
        depositionConservationResults.py --label "$method" --check) \
        || status=1
done
exit $status
