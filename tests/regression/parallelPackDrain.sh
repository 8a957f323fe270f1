#!/bin/bash
#------------------------------------------------------------------------------
# parallelPackDrain <runDir>
# processes: 2 (MPI ranks at most; tests/Alltest runs it alone)
# The held packs' drain (PackDrain) across a processor face:
# tutorials/settlingColumn with coloringFunction (close pack 0.6, e1 0.85,
# e2 0.9, capacityLimit refuse: push-through's chains would stop at the
# cut) for 0.2 s, serial and on 2 processes (the tutorial's simple (1 2 1): a
# horizontal cut at 0.2 m, through the falling suspension of 0.10-0.35 m),
# with the gas solved to 1e-13 (PCG/DIC, PBiCGStab/DILU, relTol 0).
# PackDrain books each parcel's move from cell to cell along gravity to the
# cell it ends in; a parcel that crossed the cut came from a cell on the
# other processor, whose centre its old processor sends (ParcelEntries).
# Checks at 0.2 s:
#   - the serial drain is the falling suspension's: above 0.1 m/s in the
#     cells on both sides of the cut (centres 0.1975 and 0.2025 m), so the
#     comparison below covers moves across it;
#   - packDrain on 2 processes within 1e-9 of the serial field's largest
#     value (measured when written: 1.1e-14; with a move from another
#     processor not booked: 0.99, the cells below the cut, on processor 0,
#     without drain: 0 against 0.361 m/s);
#   - the same parcel count and cloud mass.
#------------------------------------------------------------------------------
runDir="${1:?usage: parallelPackDrain.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

for mode in serial parallel
do
    dir="$runDir/$mode"
    copyTutorial settlingColumn "$dir"
    setEntry "$dir" system/controlDict endTime 0.2
    setEntry "$dir" system/controlDict writeInterval 0.1
    setEntry "$dir" system/controlDict writePrecision 15
    setEntry "$dir" constant/kinematicCloudProperties \
        subModels/packingModel coloringFunction
    setEntry "$dir" constant/kinematicCloudProperties \
        subModels/coloringFunctionCoeffs \
        "{ closePackFraction 0.6; e1 0.85; e2 0.9; capacityLimit refuse; }"
    tightGasSolvers "$dir" || exit 1
done
grep -q '(1 2 1)' "$runDir/parallel/system/decomposeParDict" \
    || { echo "the tutorial's decomposition is not (1 2 1)"; exit 1; }

runAllrun "$runDir/serial" || exit 1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1
runAllrun "$runDir/parallel" -parallel || exit 1
[ -f "$runDir/parallel/0.2/packDrain" ] || { echo "no reconstructed packDrain"; exit 1; }

(cd "$runDir/serial" && postProcess -func writeCellCentres -time 0.2 \
    > log.writeCellCentres 2>&1) || { echo "writeCellCentres failed"; exit 1; }

status=0
/usr/bin/python3 - "$runDir/serial/0.2" <<'PY' || status=1
import re, sys
from checks import report as check, status

def cells(path):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", text)
    return [float(x) for x in text[m.end():].split()[:int(m.group(1))]]

drain, y = cells(sys.argv[1] + "/packDrain"), cells(sys.argv[1] + "/Cy")
for centre in (0.1975, 0.2025):
    near = [d for d, h in zip(drain, y) if abs(h - centre) < 1e-6]
    check(len(near) == 16 and min(near) > 0.1,
          "serial drain at %.4f m (%s the cut): %d cells, %.4f-%.4f m/s > 0.1"
          % (centre, "below" if centre < 0.2 else "above", len(near),
             min(near or [0]), max(near or [0])))
sys.exit(status())
PY
check sameState "$runDir/serial" "$runDir/parallel" 0.2 1e-9 packDrain || status=1
check serialParallel "$runDir/serial" "$runDir/parallel" 0.2 || status=1
exit $status
