#!/bin/bash
#------------------------------------------------------------------------------
# solverParity <runDir>
# mppicPimpleFoam against stock MPPICFoam on the settling column, 0.2 s, same
# models and time step: parcel count and cloud mass identical at 0.2 s, mean
# bed pressure drop over 0.1-0.2 s within 2 %, and the cloud mass equal to
# the hand value of the injected lattice:
#     3200 parcels * 2984 particles * 2500 kg/m3 * pi/6 * (1e-4 m)^3
# The bedPressureDrop function object of libmppicModels (loaded with libs)
# writes the pressure drop for both solvers.
#------------------------------------------------------------------------------
runDir="${1:?usage: solverParity.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

for solver in mppicPimpleFoam MPPICFoam
do
    copyTutorial verification/settlingColumn "$runDir/$solver"
    setEntry "$runDir/$solver" system/controlDict application $solver
    setEntry "$runDir/$solver" system/controlDict endTime 0.2
    runAllrun "$runDir/$solver" || exit 1
done

expectedMass=$(/usr/bin/python3 -c 'import math; print(repr(3200*2984*2500*math.pi/6*1e-4**3))')

check parity "$runDir/mppicPimpleFoam" "$runDir/MPPICFoam" 0.2 0.1 0.2 0.02 \
 && check cloudMass "$runDir/mppicPimpleFoam" 0.2 "$expectedMass" 1e-12
