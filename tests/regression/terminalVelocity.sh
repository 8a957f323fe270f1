#!/bin/bash
#------------------------------------------------------------------------------
# terminalVelocity <runDir>
# tutorials/verification/terminalVelocity (one parcel, Cd = 1, 0.3 s, about
# 15 s): the parcel's velocity at 0.3 s and its height at every output time
# within 0.5 % of the RK4 solution of eq 1 (computed in
# terminalVelocityResults.py, the formula written out there).
# The validation matrix runs the same case: bin/validate terminalVelocity
# (docs/VALIDATION.md).
#------------------------------------------------------------------------------
runDir="${1:?usage: terminalVelocity.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial verification/terminalVelocity "$runDir/case"
runAllrun "$runDir/case" || exit 1
cd "$runDir/case" && /usr/bin/python3 terminalVelocityResults.py --check
