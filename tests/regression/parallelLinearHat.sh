#!/bin/bash
#------------------------------------------------------------------------------
# parallelLinearHat <runDir>
# tutorials/validation/uniformFluidization with mfixSnider (-packing
# mfixSnider: the linear-hat deposit for its stress, its mean solids velocity
# and the gas fraction) for 0.01 s (20 steps), serial and decomposed into 2
# (simple, a cut through the bed), with the gas solved to 1e-13 (PCG/DIC,
# PBiCGStab/DILU, relTol 0) so that the two differ by round-off only where
# the kernel is the serial one. Checks at 0.01 s:
#   - alpha.air (the deposited gas fraction), U.air and the mean solids
#     velocity kinematicCloud:UMean within 1e-9 of the serial run, each
#     column scaled by its largest magnitude (measured when written: 2e-14,
#     8e-12, 1.5e-12; with the kernel stopping at processor faces, as
#     before, 0.058, 0.49 and 0.58: the check can fail);
#   - the same parcel count and cloud mass (to 1e-12).
#------------------------------------------------------------------------------
runDir="${1:?usage: parallelLinearHat.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

for mode in serial parallel
do
    dir="$runDir/$mode"
    copyTutorial validation/uniformFluidization "$dir"
    setEntry "$dir" system/controlDict writePrecision 15
    # (foamDictionary cannot address the regular-expression key "U.air.*"
    # and would expand pFinal's $p)
    sed -i -e '/^    p$/,/}/{' \
        -e 's/GAMG;/PCG;/' \
        -e 's/smoother .*;/preconditioner  DIC;/' \
        -e 's/tolerance .*;/tolerance       1e-13;/' \
        -e 's/relTol .*;/relTol          0;/' -e '}' \
        -e '/"U.air\.\*"/,/}/{' \
        -e 's/smoothSolver;/PBiCGStab;/' \
        -e 's/smoother .*;/preconditioner  DILU;/' \
        -e 's/tolerance .*;/tolerance       1e-13;/' -e '}' \
        "$dir/system/fvSolution"
done

runAllrun "$runDir/serial" 0.01 -packing mfixSnider || exit 1
runAllrun "$runDir/parallel" 0.01 -packing mfixSnider -parallel || exit 1
[ -d "$runDir/parallel/processor1/0.01" ] || { echo "no parallel run"; exit 1; }

status=0
check sameState "$runDir/serial" "$runDir/parallel" 0.01 1e-9 \
    alpha.air U.air kinematicCloud:UMean || status=1
check serialParallel "$runDir/serial" "$runDir/parallel" 0.01 || status=1
exit $status
