#!/bin/bash
#------------------------------------------------------------------------------
# vortexAdvection <runDir>
# tutorials/verification/vortexAdvection shortened to 3 periods (0.75 s,
# about 20 s): 512 tracer parcels in the prescribed, time-reversing vortex
# (prescribedGasFlow vortex, gas not solved). All parcels present and the
# largest L1 displacement from the start at t = 3T below 1e-3 m (full run:
# 2.9e-4 m at 3T; MFiX-PIC 2.59e-3 m). An odd number of periods, because
# there an evaluation of the field at the start or the end of the step
# instead of its middle leaves dt*|u| ~ 5e-3 m.
# What this short window cannot show (the 16 periods) is the validation
# matrix's: bin/validate vortexAdvection (docs/VALIDATION.md).
#------------------------------------------------------------------------------
runDir="${1:?usage: vortexAdvection.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial verification/vortexAdvection "$runDir/case"
setEntry "$runDir/case" system/controlDict endTime 0.75
runAllrun "$runDir/case" || exit 1
cd "$runDir/case" && /usr/bin/python3 vortexAdvectionResults.py --check \
    --limit 1e-3
