#!/bin/bash
#------------------------------------------------------------------------------
# parallelSedimentation <runDir>
# processes: 4 (MPI ranks at most; tests/Alltest runs it alone)
# tutorials/verification/sedimentation with coloringFunction decomposed with
# simple into 2 halves side by side (2 1 1), so that the processor boundary
# runs vertically through the settled bed (1 s, the full case), and into 4
# quarters (2 2 1), a second boundary across the column at mid-height (0.5 s:
# the bed has formed; 4 processes on the 2 cores: oversubscribed, for
# correctness only).
# The serial run keeps every cell at 0.6 = close pack (tests/regression/
# sedimentation.sh); before the parcel records were exchanged between
# processors the 2-way split reached 2.36 (issue 20). checks of each:
# parallelSedimentation.py (the largest cell solids fraction at every step
# within the serial run's 0.6; 2400 parcels and the cloud mass; at 1 s the
# bed height within 3 % of 0.0375 m, as serial).
#------------------------------------------------------------------------------
runDir="${1:?usage: parallelSedimentation.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"
# (ranks yield the core when they wait: without it, oversubscribed ranks
# spin against each other and against any other load)
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1

status=0
for split in "2 1 (2 1 1)" "4 0.5 (2 2 1)"
do
    n="${split%% *}"
    endTime=$(echo "$split" | cut -d' ' -f2)
    case="$runDir/ranks$n"
    copyTutorial verification/sedimentation "$case"
    setEntry "$case" system/controlDict endTime "$endTime"
    setEntry "$case" system/decomposeParDict numberOfSubdomains "$n"
    setEntry "$case" system/decomposeParDict coeffs/n "${split#* * }"
    runAllrun "$case" coloringFunction -parallel || exit 1

    (cd "$case" && /usr/bin/python3 \
        "$MPPIC_PROJECT_DIR/tests/regression/parallelSedimentation.py" "$n" "$endTime") \
        || status=1
done
exit $status
