#!/bin/bash
#------------------------------------------------------------------------------
# parallelCornerNodeGradient <runDir>
# processes: 16 (MPI ranks at most; tests/Alltest runs it alone)
# parallelLinearHat.sh's serial / 2 / 16-process comparison (20 steps of
# uniformFluidization, gas solved to 1e-13) with the gas fraction deposited
# with averagingMethod cornerNodes and coloringFunction as MFiX-PIC applies
# it through the cell corners (impulse cornerNodeGradient, reflection
# component, no capacity limit, no held packs): alpha.air and U.air within
# 1e-9 of the serial run, the same parcel count and cloud mass, processor
# crossings in the correction pass.
#------------------------------------------------------------------------------
exec "${0%/*}/parallelLinearHat.sh" "${1:?usage: parallelCornerNodeGradient.sh <runDir>}" cornerNodeGradient
