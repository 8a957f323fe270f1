#!/bin/bash
#------------------------------------------------------------------------------
# circulatingFluidizedBed <runDir>
# tutorials/validation/circulatingFluidizedBed as its Allrun runs it by default (coarse
# mesh, cellSize 0.014 m, statistical weight 64, coloringFunction, Case 1)
# for 0.15 s (about 2-3 minutes with the meshing), with two additions of the
# test: writePrecision 17 (so that masses compare to 1e-10), and 120 tracer
# parcels (a second manualInjection, 4 particles each) on and around the
# axes of the exit tube (y 1.15-1.30) and the crossover pipe, so that
# parcels leave through the outlet within the run and the escape path is
# exercised (the inventory itself does not reach the cyclone in 0.15 s).
# checks: circulatingFluidizedBed.py (parcels and mass in the cloud + escaped
# = injected at every step and write time; every cell's solids fraction
# within one parcel of close pack; no fast parcels; cfbResults.py's numbers
# finite), after cfbResults.py --mesh runs.
# What this short window cannot show (the steady loop: each deltaP within 16
# %, each level within 0.052 m) is the validation matrix's: bin/validate
# cfb-1, cfb-2 and cfb-3 (docs/VALIDATION.md).
#------------------------------------------------------------------------------
runDir="${1:?usage: circulatingFluidizedBed.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

case="$runDir/case"
copyTutorial validation/circulatingFluidizedBed "$case"

sed -i 's/^writePrecision .*/writePrecision  17;/' "$case/system/controlDict"

# Tracer positions (on the case's geometry of record, cfb.geo): on and
# around the axes of the exit tube and the crossover
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/circulatingFluidizedBed.py" \
    tracerPositions "$case"

# the tracer injector, next to the seeded one
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/circulatingFluidizedBed.py" \
    tracerInjector "$case"

runAllrun "$case" -endTime 0.15 || exit 1

cd "$case" || exit 1
/usr/bin/python3 cfbResults.py . --mesh --from 0 || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/circulatingFluidizedBed.py" results
