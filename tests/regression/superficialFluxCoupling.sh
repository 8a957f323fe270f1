#!/bin/bash
#------------------------------------------------------------------------------
# superficialFluxCoupling <runDir>
# The fixed-bed branch of tutorials/validation/minimumFluidization as
# minimumFluidization.sh runs it (coloringFunction, close pack 0.62, a bed
# 0.2 m = 20 cells high, 10 parcels per cell, the inlet velocity ramping
# from 0 to 0.12 m/s over 0.6 s, about 1 minute), with mppicPimpleFoam's
# PIMPLE superficialFluxCoupling true.
# checks: superficialFluxCoupling.py (at 0.6 s every row of cells carries
# the inlet's superficial velocity in the velocity the parcels see, mean
# of ag U_y over the row = 0.12 m/s, within 2 % in the bed, the top bed
# row included, and within 4 % in the freeboard, measured 2.4 % below in
# its first rows; MPPICFoam's coupling gives the top bed row about half,
# 0.062, and the freeboard's first row 0.34), and the fixed bed's pressure
# drop at 0.12 m/s Ergun's for its voidage within 3 % (measured 0.993 x
# Ergun).
#------------------------------------------------------------------------------
runDir="${1:?usage: superficialFluxCoupling.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

case="$runDir/case"
copyTutorial validation/minimumFluidization "$case"
setEntry "$case" system/fvSolution PIMPLE/superficialFluxCoupling true
runAllrun "$case" -ramp 0.6 0.12 -parcelsPerCell 10 -closePack 0.62 \
    || exit 1
(cd "$case" && postProcess -func writeCellCentres -time 0.6 \
    > log.writeCellCentres 2>&1) || exit 1

cd "$case" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/superficialFluxCoupling.py"
