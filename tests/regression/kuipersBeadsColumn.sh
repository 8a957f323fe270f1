#!/bin/bash
#------------------------------------------------------------------------------
# kuipersBeadsColumn <runDir>
# tutorials/validation/minimumFluidization/kuipersBeads with a short ramp,
# 0 -> 0.1 m/s over 0.4 s (the bed stays fixed: Ergun's Umf is 0.225 m/s):
# a fixed bed of the Kuipers jet's beads at the jet's parcel size (5 parcels
# per cell, close pack 0.62, seeded at 0.60). checks: kuipersBeadsColumn.py
# (its pressure drop over 0.08-0.10 m/s within 5 % of Ergun's for voidage
# 0.40).
#------------------------------------------------------------------------------
runDir="${1:?usage: kuipersBeadsColumn.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

script="$MPPIC_PROJECT_DIR/tutorials/validation/minimumFluidization/kuipersBeads"
"$script" "$runDir/case" -ramp 0.4 0.1 > "$runDir/log.kuipersBeads" 2>&1 \
    || { cat "$runDir/log.kuipersBeads"; exit 1; }

cd "$runDir/case" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/kuipersBeadsColumn.py"
