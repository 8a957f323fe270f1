#!/bin/bash
#------------------------------------------------------------------------------
# bubbleStatistics <runDir>: tutorials/lib/mppicBubbles.py on gas fractions
# written by hand in the raw format of a `surfaces` function object (a
# square void of known area rising at a known speed, a noise cell, a bed
# surface at a known height) and on a known pressure signal; checks in
# bubbleStatistics.py against the values derived there.
#------------------------------------------------------------------------------
runDir="${1:?usage: bubbleStatistics.sh <runDir>}"
mkdir -p "$runDir" && cd "$runDir" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/bubbleStatistics.py"
