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
# parcels. Checks at 0.05 s: parcel count, and every parcel's velocity and
# position (barycentric coordinates) equal to 1e-12 relative to the largest
# value; the fields kinematicCloud:UMean and alpha.air likewise. Without
# the stored mean (the file deleted before the restart) the parcels differ:
# the check can fail.
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
/usr/bin/python3 - <<'PY'
import re, subprocess, sys
import checks
from checks import report as check

NUMBER = r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?"

def body(path):
    """The text of an OpenFOAM file after its FoamFile header."""
    text = open(path).read()
    return text[text.index("}", text.index("FoamFile")) + 1:]

def cloud(case, prop):
    return [float(x) for x in re.findall(NUMBER, body(
        "%s/0.05/lagrangian/kinematicCloud/%s" % (case, prop)))]

def field(case, name):
    text = body("%s/0.05/%s" % (case, name))
    inner = text[text.index("internalField"):text.index("boundaryField")]
    return [float(x) for x in re.findall(NUMBER, inner.split("(", 1)[1])]

def difference(a, b):
    if len(a) != len(b) or not a:
        return float("inf")
    scale = max(max(abs(x) for x in a), 1e-300)
    return max(abs(x - y) for x, y in zip(a, b))/scale

for case in ("whole", "restarted", "noMean"):
    subprocess.run(["foamDictionary", case + "/system/controlDict",
                    "-entry", "writeFormat", "-set", "ascii"], capture_output=True)
    subprocess.run(["foamFormatConvert", "-case", case, "-time", "0.05"],
                   capture_output=True)

nW = (len(cloud("whole", "U")) - 1)//3
nR = (len(cloud("restarted", "U")) - 1)//3
check(nW == nR == 7680, "parcels at 0.05 s: %d whole, %d restarted (7680)" % (nW, nR))
for prop in ("U", "coordinates"):
    d = difference(cloud("whole", prop), cloud("restarted", prop))
    check(d <= 1e-12, "parcel %s: restarted = whole (largest difference %.3g relative)" % (prop, d))
for name in ("kinematicCloud:UMean", "alpha.air"):
    d = difference(field("whole", name), field("restarted", name))
    check(d <= 1e-12, "%s: restarted = whole (largest difference %.3g relative)" % (name, d))
d = difference(cloud("whole", "U"), cloud("noMean", "U"))
check(d > 1e-6, "without the stored mean the parcels differ (%.3g relative): the check can fail" % d)
sys.exit(checks.status())
PY
