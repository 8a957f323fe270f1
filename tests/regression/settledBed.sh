#!/bin/bash
#------------------------------------------------------------------------------
# settledBed <runDir>
# tutorials/verification/settlingColumn with coloringFunction (close pack 0.6, e1 0.85,
# e2 0.9; 1 s, about 70 s): 100 um glass beads (2500 kg/m3) settle in air
# (1.2 kg/m3, 1.8e-5 Pa s) onto the closed bottom and are at rest from
# about 0.8 s. A bed at rest on the bottom hands the gas no weight: the
# bottom carries it. checks: settledBed.py (at 1 s the parcels' mean
# vertical velocity within 0.05 of Ergun's slip velocity u_slip = 0.0242 m/s;
# over 0.9-1.0 s deltaP/weight within [0.5 f, f + 0.05], f = 0.095 the share
# of the weight the semi-implicit drag hands the gas in a step).
#------------------------------------------------------------------------------
runDir="${1:?usage: settledBed.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

case="$runDir/case"
copyTutorial verification/settlingColumn "$case"
setEntry "$case" constant/kinematicCloudProperties \
    subModels/packingModel coloringFunction
setEntry "$case" constant/kinematicCloudProperties \
    subModels/coloringFunctionCoeffs \
    "{ closePackFraction 0.6; e1 0.85; e2 0.9; }"
runAllrun "$case" || exit 1

cd "$case" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/settledBed.py"
