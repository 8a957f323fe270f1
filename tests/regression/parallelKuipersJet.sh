#!/bin/bash
#------------------------------------------------------------------------------
# parallelKuipersJet <runDir>
# processes: 3 (MPI ranks at most; tests/Alltest runs it alone)
# tutorials/validation/kuipersJet for 0.05 s (100 steps) decomposed into 3 with simple
# (1 3 1): two processor boundaries across the column, at 1/3 and 2/3 of its
# height, the lower one through the packed bed; 3 processes on the 2 cores.
# Stock MPPICFoam is reported to hang in KinematicParcel::move with a 3-way
# decomposition (OpenFOAM-8 issue 14): the run must end within 10 minutes.
# checks: parallelKuipersJet.py (at every step 38000 parcels, the cloud mass
# and the largest cell solids fraction within the serial run's bound).
#------------------------------------------------------------------------------
runDir="${1:?usage: parallelKuipersJet.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1

case="$runDir/case"
copyTutorial validation/kuipersJet "$case"
setEntry "$case" system/decomposeParDict numberOfSubdomains 3
setEntry "$case" system/decomposeParDict coeffs/n "(1 3 1)"
timeout 600 "$case/Allrun" 0.05 -parallel
rc=$?
[ $rc = 124 ] && { echo "FAIL: not finished within 600 s (a hang?)"; exit 1; }
grep -l -E 'FOAM FATAL|FOAM aborting' "$case"/log.* && exit 1
[ $rc = 0 ] && [ -d "$case/processor2/0.05" ] || { echo "FAIL: no 0.05 s"; exit 1; }

cd "$case" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/parallelKuipersJet.py"
