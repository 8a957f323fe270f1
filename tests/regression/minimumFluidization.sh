#!/bin/bash
#------------------------------------------------------------------------------
# minimumFluidization <runDir>
# The fixed-bed branch of tutorials/validation/minimumFluidization
# (coloringFunction, Gidaspow's law, close pack 0.62 by -closePack instead
# of the case's 0.56, a bed 0.2 m = 20 cells high, 10 parcels per cell
# instead of 20 to keep it short): the inlet
# velocity ramps from 0 to 0.12 m/s (2/3 of the measured Umf 0.182 m/s)
# over 0.6 s, about 1 minute.
# checks: minimumFluidization.py (the bed does not move, so its pressure
# drop at 0.06 and 0.12 m/s is Ergun's for its voidage 0.38, within 5 %).
# The same with coloringFunction's conserveMomentum packs: a held pack hands
# the reactions' part down along gravity to its support, so the bed at rest
# keeps Ergun's drop (had its parcels kept that velocity, the drag of their
# fall would raise dP*: measured 1.6-1.9 x Ergun on Kuipers' beads).
# And mfixSnider with conserveMomentum packs, which shares that rule
# (without it: 1.97 x Ergun at 0.06 m/s).
# What this short window cannot show (the 12 s ramp: Umf within 10 % of 0.182
# m/s, plateau 1 +- 0.03) is the validation matrix's: bin/validate
# minimumFluidization (docs/VALIDATION.md).
#------------------------------------------------------------------------------
runDir="${1:?usage: minimumFluidization.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
for run in coloringFunction:none coloringFunction:packs mfixSnider:packs
do
    packing=${run%:*}
    conserve=${run#*:}
    case="$runDir/$packing-conserveMomentum-$conserve"
    copyTutorial validation/minimumFluidization "$case"
    # both models' entries
    sed -i "/\(coloringFunction\|mfixSnider\)Coeffs/,/}/s/^\( *\)closePackFraction .*/&\n\1conserveMomentum $conserve;/" \
        "$case/constant/kinematicCloudProperties"
    [ "$(grep -c "^ *conserveMomentum $conserve;" \
        "$case/constant/kinematicCloudProperties")" = 2 ] \
        || { echo "FAIL conserveMomentum $conserve not set"; exit 1; }
    runAllrun "$case" -packing $packing -ramp 0.6 0.12 -parcelsPerCell 10 -closePack 0.62 \
        || exit 1

    echo "$packing, conserveMomentum $conserve:"
    (cd "$case" && /usr/bin/python3 \
        "$MPPIC_PROJECT_DIR/tests/regression/minimumFluidization.py") || status=1
done
exit $status
