#!/bin/bash
#------------------------------------------------------------------------------
# restartContinuity <runDir>
# A run stopped at a written time and continued gives the run that did not
# stop, gas included:
#   - mppicPimpleFoam on tutorials/validation/uniformFluidization (a
#     bubbling bed, gas solved), with coloringFunction, with it and
#     capacityLimit push (which must have pushed after the restart), with
#     conserveMomentum gas (-packsToGas), with PIMPLE
#     superficialFluxCoupling true, and with mfixSnider:
#     0 -> 0.05 s at once, and 0 -> 0.025 s then continued (startFrom
#     latestTime) to 0.05 s; both write ascii at 17 digits;
#   - mppicReactingPimpleFoam on tutorials/verification/wetBulb (a droplet
#     evaporating in a gas cell, temperature and vapour solved): 0 -> 1 s,
#     and 0 -> 0.5 s continued to 1 s.
# Checks at the end: every parcel's velocity and position (barycentric
# coordinates) and the gas fields equal to 1e-8 of each column's largest
# magnitude (the log says where they are bitwise equal); parcel counts equal.
# That the comparison can fail: the bed continued from a time written at 6
# digits differs by more than 1e-8.
#------------------------------------------------------------------------------
runDir="${1:?usage: restartContinuity.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

# wholeAndContinued <tutorial> <name> <precision> <T1> <T2> <endArg> [args]
# (cloudEntry: an entry added to the packing models' coefficients)
wholeAndContinued()
{
    local tutorial="$1" name="$2" precision="$3" t1="$4" t2="$5" endArg="$6"
    shift 6
    for piece in whole continued
    do
        copyTutorial "$tutorial" "$runDir/$name.$piece"
        setEntry "$runDir/$name.$piece" system/controlDict writePrecision "$precision"
        setEntry "$runDir/$name.$piece" system/controlDict writeFormat ascii
        # (wetBulb writes every second: write the stop time; in both, as
        # its adjustable time step lands on write times)
        setEntry "$runDir/$name.$piece" system/controlDict writeInterval "$t1"
        if [ -n "$cloudEntry" ]
        then
            local props="$runDir/$name.$piece/constant/kinematicCloudProperties"
            sed -i "/\(coloringFunction\|mfixSnider\)Coeffs/,/}/s/^\( *\)closePackFraction .*/&\n\1$cloudEntry/" "$props"
            grep -q "$cloudEntry" "$props" \
                || { echo "$name: $cloudEntry not set"; exit 1; }
        fi
        if [ -n "$pimpleSwitch" ]
        then
            setEntry "$runDir/$name.$piece" system/fvSolution \
                "PIMPLE/$pimpleSwitch" true
        fi
    done

    runAllrun "$runDir/$name.whole" $endArg "$t2" "$@" || exit 1
    runAllrun "$runDir/$name.continued" $endArg "$t1" "$@" || exit 1

    local case="$runDir/$name.continued"
    setEntry "$case" system/controlDict endTime "$t2"
    setEntry "$case" system/controlDict startFrom latestTime
    (cd "$case" && $(foamDictionary system/controlDict -entry application \
        -value) > log.continue 2>&1) || exit 1
    local first
    first=$(awk '/^Time = /{print $3; exit}' "$case/log.continue")
    awk -v f="$first" -v t="$t1" 'BEGIN { exit !(f > t && f < 1.5*t) }' \
        || { echo "$name: the continued run's first step is $first, not just after $t1"; exit 1; }
    [ -d "$case/$t2" ] || { echo "$name: no $t2 written"; exit 1; }
}

bedFields="lagrangian/kinematicCloud/U lagrangian/kinematicCloud/coordinates
    lagrangian/kinematicCloud/origId U.air p alpha.air phi.air"

status=0
for packing in coloringFunction mfixSnider
do
    wholeAndContinued validation/uniformFluidization "bed.$packing" 17 \
        0.025 0.05 "" -packing $packing
    check sameState "$runDir/bed.$packing.whole" \
        "$runDir/bed.$packing.continued" 0.05 1e-8 $bedFields || status=1
done

# coloringFunction with capacityLimit push: refused entrants out of full
# cells are pushed on after the restart at 0.025 s (419 in the 50 steps,
# measured)
cloudEntry="capacityLimit push;"
wholeAndContinued validation/uniformFluidization bed.push 17 \
    0.025 0.05 "" -packing coloringFunction
cloudEntry=""
check sameState "$runDir/bed.push.whole" "$runDir/bed.push.continued" \
    0.05 1e-8 $bedFields || status=1
pushes=$(awk '/^ *pushThrough: [0-9]+ refused/ {n += $2} END {print n + 0}' \
    "$runDir/bed.push.continued/log.continue")
if [ "$pushes" -gt 0 ]
then
    echo "PASS push-through: $pushes refused entrants pushed on after the restart (> 0)"
else
    echo "FAIL push-through: no entrant pushed on after the restart"
    status=1
fi

# conserveMomentum gas (-packsToGas: conserving packs whose free packs
# hand their reactions to the gas): the rule keeps nothing across steps, so the
# continued run must be the whole one; the gas must take some share after
# the restart (packingMonitor's gasPackingMomentumY, column 16)
wholeAndContinued validation/uniformFluidization bed.packsToGas 17 \
    0.025 0.05 "" -packsToGas
check sameState "$runDir/bed.packsToGas.whole" \
    "$runDir/bed.packsToGas.continued" 0.05 1e-8 $bedFields || status=1
toGasAfter=$(awk '!/^#/ && $1 > 0.025 && $16 != 0 {n++} END {print n + 0}' \
    "$runDir/bed.packsToGas.continued/postProcessing/packingMonitor/0.025/packingMonitor.dat")
if [ "$toGasAfter" -gt 0 ]
then
    echo "PASS conserveMomentum gas: the gas took a share at $toGasAfter steps after the restart (> 0)"
else
    echo "FAIL conserveMomentum gas: the gas took no share after the restart"
    status=1
fi

# PIMPLE superficialFluxCoupling: its time-derivative correction reads the
# old superficial flux and the old cell velocity, which the continued run
# must find as the whole one had them
pimpleSwitch=superficialFluxCoupling
wholeAndContinued validation/uniformFluidization bed.superficialFlux 17 \
    0.025 0.05 "" -packing coloringFunction
pimpleSwitch=""
check sameState "$runDir/bed.superficialFlux.whole" \
    "$runDir/bed.superficialFlux.continued" 0.05 1e-8 $bedFields || status=1

wholeAndContinued validation/uniformFluidization bed.sixDigits 6 \
    0.025 0.05 "" -packing coloringFunction
check differs "$runDir/bed.coloringFunction.whole" \
    "$runDir/bed.sixDigits.continued" 0.05 1e-8 $bedFields || status=1

wholeAndContinued verification/wetBulb wetBulb 17 0.5 1 -endTime
check sameState "$runDir/wetBulb.whole" "$runDir/wetBulb.continued" 1 1e-8 \
    lagrangian/reactingCloud/U lagrangian/reactingCloud/coordinates \
    lagrangian/reactingCloud/d lagrangian/reactingCloud/T \
    U T p H2O rho || status=1

exit $status
