#!/bin/bash
#------------------------------------------------------------------------------
# decomposeByParcels <runDir>
# processes: 2 (MPI ranks at most; tests/Alltest runs it alone)
# mppicDecomposeByParcels on tutorials/validation/uniformFluidization (3200
# cells, 7680 parcels in a bed of 8 a cell), cut in two along y with
# parcelWeight 1 and 0; decomposePar (method manual) then reads the list and
# mppicPimpleFoam runs 10 steps on the two processors. checks:
# decomposeByParcels.py (the cuts against hand counts, the parcels kept).
# Bad input: n whose product is not numberOfSubdomains, and a negative
# parcelWeight -> FatalIOError naming the keyword and value, exit status 1.
#------------------------------------------------------------------------------
runDir="${1:?usage: decomposeByParcels.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

case="$runDir/case"
copyTutorial validation/uniformFluidization "$case"
cd "$case" || exit 1
runApplication gmsh -3 -format msh2 -o bed.msh bed.geo
runApplication gmshToFoam bed.msh
runApplication changeDictionary
restore0Dir
runApplication mppicSeedParcels

setCoeffs()   # setCoeffs <n> <parcelWeight>
{
    sed -i '/^mppicDecomposeByParcelsCoeffs/,$d' system/decomposeParDict
    sed -i 's/^method .*/method          manual;/' system/decomposeParDict
    cat >> system/decomposeParDict <<DICT
coeffs
{
    dataFile        "cellDecomposition";
}
mppicDecomposeByParcelsCoeffs
{
    n               $1;
    parcelWeight    $2;
}
DICT
}

setCoeffs "(1 2 1)" 1
mppicDecomposeByParcels > log.weighted 2>&1 || { cat log.weighted; exit 1; }
setCoeffs "(1 2 1)" 0
mppicDecomposeByParcels > log.unweighted 2>&1 || { cat log.unweighted; exit 1; }
setCoeffs "(1 3 1)" 1
mppicDecomposeByParcels > log.badN 2>&1
rcN=$?
setCoeffs "(1 2 1)" -1
mppicDecomposeByParcels > log.badWeight 2>&1
rcWeight=$?
setCoeffs "(1 2 1)" 1
mppicDecomposeByParcels > log.final 2>&1 || exit 1
runApplication decomposePar -force
foamDictionary system/controlDict -entry endTime -set 0.005 > /dev/null
runParallel mppicPimpleFoam || exit 1

cat log.weighted
status=0
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/decomposeByParcels.py" || status=1
check fatal log.badN $rcN "n (1 3 1)" "numberOfSubdomains 2" || status=1
check fatal log.badWeight $rcWeight "parcelWeight -1" "[0, inf)" || status=1
exit $status
