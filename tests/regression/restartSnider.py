#!/usr/bin/python3
"""Checks of tests/regression/restartSnider.sh: tutorials/validation/
uniformFluidization with mfixSnider in a prescribed uniform gas flow, binary
writes at full precision: one run 0 -> 0.05 s (whole/), and the same case
stopped at 0.025 s and continued from there to 0.05 s (restarted/), and
continued without the stored mean solids velocity (noMean/:
0.025/kinematicCloud:UMean deleted). Each run's 0.05 s is converted to ascii
(foamFormatConvert) first. At 0.05 s:
  - 7680 parcels in whole and restarted ((numbers of U - 1)/3);
  - every parcel's velocity and position (barycentric coordinates) of
    restarted = whole to 1e-12 relative to the largest value,
    max|x - y|/max|x|; the fields kinematicCloud:UMean and alpha.air
    likewise;
  - without the stored mean the parcels' velocities differ by more than
    1e-6: the check can fail.

Usage: restartSnider.py   (in the run folder that holds whole/, restarted/, noMean/)
"""
import re
import subprocess
import sys

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


def convert_to_ascii():
    for case in ("whole", "restarted", "noMean"):
        subprocess.run(["foamDictionary", case + "/system/controlDict",
                        "-entry", "writeFormat", "-set", "ascii"], capture_output=True)
        subprocess.run(["foamFormatConvert", "-case", case, "-time", "0.05"],
                       capture_output=True)


def check_restarted_equals_whole():
    nW = (len(cloud("whole", "U")) - 1)//3
    nR = (len(cloud("restarted", "U")) - 1)//3
    check(nW == nR == 7680, "parcels at 0.05 s: %d whole, %d restarted (7680)" % (nW, nR))
    for prop in ("U", "coordinates"):
        d = difference(cloud("whole", prop), cloud("restarted", prop))
        check(d <= 1e-12, "parcel %s: restarted = whole (largest difference %.3g relative)" % (prop, d))
    for name in ("kinematicCloud:UMean", "alpha.air"):
        d = difference(field("whole", name), field("restarted", name))
        check(d <= 1e-12, "%s: restarted = whole (largest difference %.3g relative)" % (name, d))


def check_without_mean_differs():
    d = difference(cloud("whole", "U"), cloud("noMean", "U"))
    check(d > 1e-6, "without the stored mean the parcels differ (%.3g relative): the check can fail" % d)


if __name__ == "__main__":
    convert_to_ascii()
    check_restarted_equals_whole()
    check_without_mean_differs()
    sys.exit(checks.status())
