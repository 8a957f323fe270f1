#!/bin/bash
#------------------------------------------------------------------------------
# serialParallel <runDir>
# processes: 2 (MPI ranks at most; tests/Alltest runs it alone)
# The settling column with mppicPimpleFoam for 0.2 s, serial and decomposed
# into 2 subdomains (decomposePar simple, mpirun -np 2, reconstructPar):
# the same parcel count and, parcel by parcel, the same cloud mass, exactly.
#------------------------------------------------------------------------------
runDir="${1:?usage: serialParallel.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

for mode in serial parallel
do
    copyTutorial verification/settlingColumn "$runDir/$mode"
    setEntry "$runDir/$mode" system/controlDict endTime 0.2
done

runAllrun "$runDir/serial" || exit 1
runAllrun "$runDir/parallel" -parallel || exit 1
[ -d "$runDir/parallel/processor1/0.2" ] || { echo "no parallel run"; exit 1; }

check serialParallel "$runDir/serial" "$runDir/parallel" 0.2
