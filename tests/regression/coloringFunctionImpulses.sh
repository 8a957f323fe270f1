#!/bin/bash
#------------------------------------------------------------------------------
# coloringFunctionImpulses <runDir>
# tutorials/verification/sedimentation (1 s, about 50 s a run) with
# coloringFunction's other three impulses, capacityLimit left at its default
# (true, which acts with impulse neighbour only): impulse gradient (seed 1
# eq 19 on the averaging's gradient), impulse faceGradient (MFiX-PIC's
# face gradient from the parcel's own cell) and impulse cornerNodeGradient
# (the same brought through the cell corners, as MFiX's GARG_2012, on the
# averagingMethod cornerNodes field as MFiX pairs them: measured 0.0375 m;
# on the cell counts (basic) the bed settles at 0.48 and 0.0451 m). Before 2026-11-26 faceGradient with the capacity limit
# stopped at its first step (the packing field unallocated): FAIL here.
# Checks for each: the run ends; 2400 parcels and the cloud mass
# (seeded volume * 2500 kg/m3) to 1e-9 at the end; the final bed height
# within 10 % of the inventory height V_solids/(alpha_cp*A) =
# 5.625e-6/(0.6*0.05*0.005) = 0.0375 m (without the limit a bed may pack
# above alpha_cp: measured +6.6 % with gradient, README).
#------------------------------------------------------------------------------
runDir="${1:?usage: coloringFunctionImpulses.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
for impulse in gradient faceGradient cornerNodeGradient
do
    case="$runDir/$impulse"
    copyTutorial verification/sedimentation "$case"
    sed -i "s/^\( *e2 \+0.9; .*\)$/\1\n        impulse         $impulse;/" \
        "$case/constant/kinematicCloudProperties"
    grep -q "^ *impulse *$impulse;" "$case/constant/kinematicCloudProperties" \
        || { echo "FAIL impulse $impulse not set"; exit 1; }
    if [ "$impulse" = cornerNodeGradient ]
    then
        # MFiX-PIC's pairing: the corner gradient of the corner-node field
        sed -i 's/^\( *averagingMethod \+\)basic;/\1cornerNodes;/' \
            "$case/constant/kinematicCloudProperties"
        grep -q "^ *averagingMethod cornerNodes;" \
            "$case/constant/kinematicCloudProperties" \
            || { echo "FAIL averagingMethod not set"; exit 1; }
    fi
    runAllrun "$case" || { echo "FAIL impulse $impulse: the run stopped"; status=1; continue; }
    grep -q "^End" "$case/log.mppicPimpleFoam" \
        || { echo "FAIL impulse $impulse: no End in the log"; status=1; continue; }

    echo "impulse $impulse:"
    (cd "$case" && /usr/bin/python3 - <<'PY'
import sys
sys.path.insert(0, ".")
from sedimentationResults import read_monitor, bed_profile, post, \
    surface_height, seeded_solids_volume
import checks
from checks import report as check
cp, rows = read_monitor(".")
check(rows[-1][1] == 2400, "2400 parcels at the end (%d)" % rows[-1][1])
mass = rows[-1][2]
check(abs(mass/(seeded_solids_volume(".")*2500) - 1) < 1e-9,
      "cloud mass %.10g kg = seeded volume * 2500" % mass)
ys, prof, dy, _, _ = bed_profile(".", post.latest_time("."))
h = surface_height(ys, prof, 0.5*cp, dy)
check(abs(h/0.0375 - 1) <= 0.10, "bed height %.4f m within 10 %% of 0.0375 m" % h)
sys.exit(checks.status())
PY
) || status=1
done
exit $status
