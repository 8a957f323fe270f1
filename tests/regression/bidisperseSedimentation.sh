#!/bin/bash
#------------------------------------------------------------------------------
# bidisperseSedimentation <runDir>
# processes: 2
# tutorials/verification/bidisperseSedimentation with 5 parcels of each
# phase per cell (-perCell 5, a quarter of the default) (1 mm and 0.5 mm beads,
# 0.075 each, settling in water), a mixture of two solids phases:
#   - serial to 1 s (ascii, 17 digits, written every 0.05 s): the three
#     fronts within 2 % or 0.005 m of the exact kinematic-wave fronts from
#     rest, each phase's mass kept to 1e-12, no cell above close pack at any
#     step (bidisperseSedimentationResults.py --check --time 1);
#   - 2 ranks, one above the other, to 0.1 s (17 digits): at every step each
#     phase's parcels and mass equal to the serial run's and its mean height within
#     1e-6 m (the written rows; round-off that the settling amplifies: 2.5e-8 m
#     at 0.1 s, measured);
#   - the serial run continued from its 0.05 s: at 0.1 s every parcel's
#     velocity and position and the liquid's U and p equal to the run that did
#     not stop (bitwise expected, 1e-12 of each column's scale allowed).
#------------------------------------------------------------------------------
runDir="${1:?usage: bidisperseSedimentation.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1

serial="$runDir/serial"
copyTutorial verification/bidisperseSedimentation "$serial"
setEntry "$serial" system/controlDict endTime 1
setEntry "$serial" system/controlDict writeInterval 0.05
setEntry "$serial" system/controlDict writePrecision 17
runAllrun "$serial" -perCell 5 || exit 1

status=0
(cd "$serial" && /usr/bin/python3 bidisperseSedimentationResults.py \
    --time 1 --check) || status=1

parallel="$runDir/parallel"
copyTutorial verification/bidisperseSedimentation "$parallel"
setEntry "$parallel" system/controlDict endTime 0.1
setEntry "$parallel" system/controlDict writePrecision 17
runAllrun "$parallel" coloringFunction -parallel -perCell 5 || exit 1
/usr/bin/python3 - "$serial" "$parallel" <<'PY' || status=1
import sys
import checks
def rows(case):
    path = case + "/postProcessing/packingMonitor/0/phases.dat"
    return {(round(float(r[0]), 9), int(r[1])): [float(v) for v in r[2:]]
            for r in (l.split() for l in open(path) if not l.startswith("#"))}
s, p = rows(sys.argv[1]), rows(sys.argv[2])
keys = sorted(k for k in p if k in s)
checks.report(len(keys) == len(p) and len(keys) >= 400,
              "%d phase rows of the 2 ranks found in the serial run's" % len(keys))
checks.report(all(s[k][0] == p[k][0] for k in keys),
              "each phase's parcel count equal at every step")
mass = max(abs(s[k][1]/p[k][1] - 1) for k in keys)
checks.report(mass <= 1e-12, "each phase's mass equal at every step "
              "(largest relative difference %.2e <= 1e-12)" % mass)
height = max(abs(s[k][2] - p[k][2]) for k in keys)
checks.report(height <= 1e-6, "each phase's mean height within 1e-6 m at "
              "every step (largest difference %.2e m)" % height)
sys.exit(checks.status())
PY

continued="$runDir/continued"
rm -rf "$continued"
mkdir -p "$continued"
cp -r "$serial/constant" "$serial/system" "$serial/0" "$serial/0.05" \
    "$continued/"
setEntry "$continued" system/controlDict startFrom latestTime
setEntry "$continued" system/controlDict endTime 0.1
(cd "$continued" && mppicPimpleFoam > log.continue 2>&1) || exit 1
check sameState "$serial" "$continued" 0.1 1e-12 \
    lagrangian/kinematicCloud/U lagrangian/kinematicCloud/coordinates \
    lagrangian/kinematicCloud/typeId U.water p || status=1

exit $status
