#!/bin/bash
#------------------------------------------------------------------------------
# parallelCornerNodes <runDir>
# processes: 16 (MPI ranks at most; tests/Alltest runs it alone)
# parallelLinearHat.sh's serial / 2 / 16-process comparison (20 steps of
# uniformFluidization, gas solved to 1e-13) with the default coloringFunction
# and the gas fraction deposited with averagingMethod cornerNodes: alpha.air
# and U.air within 1e-9 of the serial run, the same parcel count and cloud
# mass.
#------------------------------------------------------------------------------
exec "${0%/*}/parallelLinearHat.sh" "${1:?usage: parallelCornerNodes.sh <runDir>}" cornerNodes
