#!/bin/bash
#------------------------------------------------------------------------------
# restartSnider <runDir>
# tutorials/validation/uniformFluidization with mfixSnider as the case sets
# it (slip factor 0.9, MFiX's collision damping) in a prescribed uniform gas
# flow of 0.8 m/s upward (the gas is not solved, so that only the cloud is
# tested; restartContinuity.sh tests the gas with it),
# binary writes at full precision: one run 0 -> 0.05 s, and the same case
# stopped at 0.025 s and continued from there to 0.05 s. mfixSnider keeps
# the previous step's mean solids velocity (<cloud>:UMean): it is written
# with the time directory and read back, so that the two runs give the same
# parcels. checks: restartSnider.py (at 0.05 s the parcel count, every
# parcel's velocity and position, UMean and alpha.air equal to 1e-12; and
# without the stored mean (the file deleted before the restart) the parcels
# differ: the check can fail).
#------------------------------------------------------------------------------
runDir="${1:?usage: restartSnider.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

prepare()
{
    copyTutorial validation/uniformFluidization "$1"
    setEntry "$1" system/controlDict writeFormat binary
    setEntry "$1" system/controlDict writePrecision 17
    uniformGasFlow "$1" "(0 0.8 0)"
}

prepare "$runDir/whole"
runAllrun "$runDir/whole" 0.05 -packing mfixSnider || exit 1

prepare "$runDir/restarted"
runAllrun "$runDir/restarted" 0.025 -packing mfixSnider || exit 1
setEntry "$runDir/restarted" system/controlDict endTime 0.05
setEntry "$runDir/restarted" system/controlDict startFrom latestTime
rm -rf "$runDir/noMean"
cp -r "$runDir/restarted" "$runDir/noMean"
rm -f "$runDir/noMean/0.025/kinematicCloud:UMean"
for case in restarted noMean
do
    (cd "$runDir/$case" && mppicPimpleFoam > log.restart 2>&1) || exit 1
done

cd "$runDir" || exit 1
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/restartSnider.py"
