#!/bin/bash
#------------------------------------------------------------------------------
# parallelFaceForms <runDir>
# processes: 2 (MPI ranks at most; tests/Alltest runs it alone)
# mppicPimpleFoam's two interpolated face forms, PIMPLE faceInterpolatedDrag
# true and superficialFluxCoupling true, give the serial answer on 2 ranks:
# tutorials/validation/uniformFluidization (a bubbling bed) from the seeded
# bed to 0.02 s (40 steps), serially and decomposed into 2 subdomains (the
# case's decomposeParDict, simple (2 1 1): a vertical cut through the bed),
# with the gas solved to 1e-13 (p and pFinal PCG/DIC, U PBiCGStab/DILU,
# relTol 0), then reconstructed. Both forms interpolate the momentum
# matrix's diagonal, H and the explicit forces to the faces and reconstruct
# the cell velocity from face fluxes, across the processor faces too.
# Checks at 0.02 s, each form: alpha.air, U.air, p and phi.air within 1e-8
# of the serial run's, each column scaled by its largest magnitude (measured
# when written: faceInterpolatedDrag U.air 5.6e-10, phi.air 1.7e-10;
# superficialFluxCoupling 3.3e-10, 2.7e-11. With the final pressure solve
# left at the case's GAMG to 1e-7 the same runs differ by 1 % in U.air: the
# check can fail), and the same cloud (parcel count and mass).
#------------------------------------------------------------------------------
runDir="${1:?usage: parallelFaceForms.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
for form in faceInterpolatedDrag superficialFluxCoupling
do
    mkdir -p "$runDir/$form"
    for mode in serial parallel
    do
        dir="$runDir/$form/$mode"
        copyTutorial validation/uniformFluidization "$dir"
        tightGasSolvers "$dir" || exit 1
        setEntry "$dir" system/fvSolution PIMPLE/$form true
        setEntry "$dir" system/controlDict writeInterval 0.02
    done
    runAllrun "$runDir/$form/serial" 0.02 || exit 1
    runAllrun "$runDir/$form/parallel" 0.02 -parallel || exit 1
    [ -d "$runDir/$form/parallel/processor1/0.02" ] \
        || { echo "no parallel run with $form"; exit 1; }
    echo "$form:"
    check sameState "$runDir/$form/serial" "$runDir/$form/parallel" 0.02 \
        1e-8 alpha.air U.air p phi.air || status=1
    check serialParallel "$runDir/$form/serial" "$runDir/$form/parallel" \
        0.02 || status=1
done
exit $status
