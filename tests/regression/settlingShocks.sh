#!/bin/bash
#------------------------------------------------------------------------------
# settlingShocks <runDir>
# tutorials/verification/settlingShocks at eps_s0 = 0.20, the full 1 s (about
# 2 minutes): the settling and filling fronts at 1 s against eqs 6 and 8 of
# Vaidheeswaran et al. (2020) with Stokes drag (written out in
# settlingShocksResults.py), and the bed held at close pack.
# Tolerance: see the case's README (measured offsets and why).
#------------------------------------------------------------------------------
runDir="${1:?usage: settlingShocks.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

copyTutorial verification/settlingShocks "$runDir/case"
runAllrun "$runDir/case" 0.20 || exit 1
cd "$runDir/case" && /usr/bin/python3 settlingShocksResults.py --check \
    --tolerance "${SETTLING_SHOCKS_TOLERANCE:-0.035}"
