#!/bin/bash
#------------------------------------------------------------------------------
# parallelPushThrough <runDir>
# processes: 16 (MPI ranks at most; tests/Alltest runs it alone)
# tutorials/validation/uniformFluidization with coloringFunction's
# capacityLimit push for 0.02 s, serial, on 2 and on 16 processes
# (parallelLinearHat.sh pushThrough): chains on every decomposition, the
# serial run's parcels and mass, no cell above close pack.
#------------------------------------------------------------------------------
exec "${0%/*}/parallelLinearHat.sh" "${1:?usage: parallelPushThrough.sh <runDir>}" pushThrough
