#!/bin/bash
#------------------------------------------------------------------------------
# cfbEqualArea <runDir>
# tutorials/validation/circulatingFluidizedBed's coarse mesh as its Allrun makes it, with
# and without -equalArea (a few steps each, -endTime 0.002); checks:
# cfbEqualArea.py (the meshed cross-sections of the standpipe and the riser
# against the pipes' areas).
#------------------------------------------------------------------------------
runDir="${1:?usage: cfbEqualArea.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

for variant in nominal equalArea
do
    copyTutorial validation/circulatingFluidizedBed "$runDir/$variant"
    args="-endTime 0.002"
    [ "$variant" = equalArea ] && args="$args -equalArea"
    PROGRESS_EVERY=0 runAllrun "$runDir/$variant" $args || exit 1
done

cd "$runDir" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/cfbEqualArea.py"
