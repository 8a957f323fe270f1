#!/bin/bash
#------------------------------------------------------------------------------
# decomposeByParcels <runDir>
# processes: 2 (MPI ranks at most; tests/Alltest runs it alone)
# mppicDecomposeByParcels on tutorials/validation/uniformFluidization: 20 x 80
# x 2 cubic cells (3200, rows of 40), a bed 24 rows high of exactly 8
# parcels per cell (960 cells, 7680 parcels). Cut in two along y with
# parcelWeight 1, each bed cell weighs 9 and each gas cell 1: the total is
# 960*9 + 2240 = 10880, so processor 0 takes the lowest 5440/9 = 604.4 bed
# cells (604 or 605, 4832 or 4840 parcels) and processor 1 the rest, both
# within half a bed cell (4.5) of 5440; with parcelWeight 0 it is simple's
# cut, 1600 cells each. decomposePar (method manual) then reads the list and
# mppicPimpleFoam runs 10 steps on the two processors keeping 7680 parcels.
# Bad input: n whose product is not numberOfSubdomains, and a negative
# parcelWeight -> FatalIOError naming the keyword and value, exit status 1.
#------------------------------------------------------------------------------
runDir="${1:?usage: decomposeByParcels.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

case="$runDir/case"
copyTutorial validation/uniformFluidization "$case"
cd "$case" || exit 1
runApplication gmsh -3 -format msh2 -o bed.msh bed.geo
runApplication gmshToFoam bed.msh
runApplication changeDictionary
restore0Dir
runApplication mppicSeedParcels

setCoeffs()   # setCoeffs <n> <parcelWeight>
{
    sed -i '/^mppicDecomposeByParcelsCoeffs/,$d' system/decomposeParDict
    sed -i 's/^method .*/method          manual;/' system/decomposeParDict
    cat >> system/decomposeParDict <<DICT
coeffs
{
    dataFile        "cellDecomposition";
}
mppicDecomposeByParcelsCoeffs
{
    n               $1;
    parcelWeight    $2;
}
DICT
}

setCoeffs "(1 2 1)" 1
mppicDecomposeByParcels > log.weighted 2>&1 || { cat log.weighted; exit 1; }
setCoeffs "(1 2 1)" 0
mppicDecomposeByParcels > log.unweighted 2>&1 || { cat log.unweighted; exit 1; }
setCoeffs "(1 3 1)" 1
mppicDecomposeByParcels > log.badN 2>&1
rcN=$?
setCoeffs "(1 2 1)" -1
mppicDecomposeByParcels > log.badWeight 2>&1
rcWeight=$?
setCoeffs "(1 2 1)" 1
mppicDecomposeByParcels > log.final 2>&1 || exit 1
runApplication decomposePar -force
foamDictionary system/controlDict -entry endTime -set 0.005 > /dev/null
runParallel mppicPimpleFoam || exit 1

cat log.weighted
status=0
/usr/bin/python3 - <<'PY' || status=1
import re
import checks
from checks import report as check
def table(log):
    rows = re.findall(r"^(\d+)  (\d+)  (\d+)  ([0-9.e+]+)$", open(log).read(), re.M)
    return [(int(a), int(b), int(c), float(d)) for a, b, c, d in rows]
w = table("log.weighted")
check(len(w) == 2 and sum(r[1] for r in w) == 3200 and sum(r[2] for r in w) == 7680,
      "two processors with 3200 cells and 7680 parcels in all: %s" % w)
check(w[0][1] in (604, 605) and w[0][2] in (4832, 4840),
      "processor 0: %d cells (604 or 605), %d parcels (4832 or 4840)" % w[0][1:3])
check(all(abs(r[3] - 5440) <= 4.5 for r in w),
      "weights %s within 4.5 of 5440" % [r[3] for r in w])
u = table("log.unweighted")
check([r[1] for r in u] == [1600, 1600], "parcelWeight 0: cells %s = simple's 1600, 1600"
      % [r[1] for r in u])
log = open("log.mppicPimpleFoam").read()
counts = re.findall(r"Cloud: parcels = (\d+)", log)
check(len(counts) == 10 and all(int(c) == 7680 for c in counts),
      "2 ranks on the manual decomposition: 7680 parcels at each of %d steps" % len(counts))
raise SystemExit(checks.status())
PY
check fatal log.badN $rcN "n (1 3 1)" "numberOfSubdomains 2" || status=1
check fatal log.badWeight $rcWeight "parcelWeight -1" "[0, inf)" || status=1
exit $status
