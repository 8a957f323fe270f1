#!/bin/bash
#------------------------------------------------------------------------------
# splitParcels <runDir>
# bin/splitParcels on tutorials/validation/uniformFluidization (hexahedra,
# a prescribed uniform gas flow of 0.8 m/s upward so that only the cloud
# runs), ascii at 17 digits, run to 0.01 s and its cloud split into K = 4.
# Checks on the written split (against the 0.01 s cloud kept aside):
#   - 4 N parcels; copy k of parcel i has parcel i's velocity, diameter and
#     density, nParticle/4 to 1e-15, and origId 4 origId_i + k (all unique);
#   - every cell holds the solids volume it held, to 1e-12 relative;
#   - every copy lies between the parcel and its cell's centre, 1-50 % of
#     the way (the geometry that keeps it in a convex cell);
# then the solver reads it and runs one step (stopAt writeNow):
#   - no parcel initialised outside the mesh (the solver's warning), 4 N
#     parcels, and the cloud's mass that of the 0.01 s cloud to 1e-12
#     (from the parcels' own fields);
# and the bad inputs stop with their message, exit status 1 and no file
# changed: K = 1, --nParticle 1 % off nParticle/K, a decomposed case, a
# binary field, a field one entry short, no cloud at the time, no geometry
# entry in the cloud's uniform properties.
#------------------------------------------------------------------------------
runDir="${1:?usage: splitParcels.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

case="$runDir/case"
copyTutorial validation/uniformFluidization "$case"
setEntry "$case" system/controlDict writePrecision 17
uniformGasFlow "$case" "(0 0.8 0)"
runAllrun "$case" 0.01 || exit 1
rm -rf "$runDir/before"
cp -r "$case/0.01" "$runDir/before"

status=0
nP=$(sed -n 's/^\([0-9]*\){\(.*\)}$/\2/p' "$case/0.01/lagrangian/kinematicCloud/nParticle")
bad=$(/usr/bin/python3 -c "print(repr(1.01*float('${nP:-1}')/4))")
lag=0.01/lagrangian/kinematicCloud
# refused LABEL 'EDIT' 'ARGS' 'MESSAGE': on a copy of the case changed by EDIT
# (run in the copy), splitParcels ARGS stops with exit status 1 and a message
# containing MESSAGE, and the copy's 0.01 is as it was after EDIT
refused()
{
    local copy="$runDir/refused" out rc
    rm -rf "$copy"; cp -r "$case" "$copy"
    (cd "$copy" && eval "$2")
    cp -r "$copy/0.01" "$runDir/refusedBefore"
    out=$("$MPPIC_PROJECT_DIR/bin/splitParcels" "$copy" $3 2>&1)
    rc=$?
    if [ $rc = 1 ] && [[ "$out" == *"$4"* ]] \
    && diff -r -q "$runDir/refusedBefore" "$copy/0.01" > /dev/null
    then
        echo "PASS splitParcels $1: exit 1, nothing changed: $out"
    else
        echo "FAIL splitParcels $1: exit $rc, expected \"$4\" (or files changed): $out"; status=1
    fi
    rm -rf "$copy" "$runDir/refusedBefore"
}
# oneShort FILE: a uniform list N{v} becomes (N - 1){v}
oneShort()
{
    /usr/bin/python3 -c 'import re, sys; s = open(sys.argv[1]).read()
open(sys.argv[1], "w").write(re.sub(r"(?m)^(\d+)\{", lambda m: "%d{" % (int(m.group(1)) - 1), s))' "$1"
}
refused "K = 1" ':' '0.01 1' 'split into 2 or more'
refused "--nParticle 1 % off" ':' "0.01 4 --nParticle $bad" 'off a parcel'
refused "decomposed case" 'mkdir processor0' '0.01 4' 'is decomposed'
refused "binary field" "sed -i 's/format *ascii;/format      binary;/' $lag/d" \
    '0.01 4' 'format binary'
refused "a field one entry short" "oneShort $lag/nParticle" '0.01 4' 'entries for'
refused "no cloud at the time" ':' '0.5 4' 'no positions file'
refused "no geometry entry" \
    "sed -i '/geometry/d' 0.01/uniform/lagrangian/kinematicCloud/cloudProperties" \
    '0.01 4' 'no geometry entry'
[ -n "$nP" ] || { echo "FAIL the 0.01 s cloud has no uniform nParticle"; status=1; }

"$MPPIC_PROJECT_DIR/bin/splitParcels" "$case" 0.01 4 || exit 1

cd "$runDir" || exit 1
/usr/bin/python3 - <<'PY' || status=1
import math, os, re, sys
import checks
from checks import report as check

def items(path):
    text = open(path).read()
    body = re.sub(r"//[^\n]*", "", text[text.index("}", text.index("FoamFile")) + 1:])
    if "internalField" in body:
        body = body[body.index("internalField"):body.index("boundaryField")]
        body = body[body.index(">") + 1:body.rindex(";")]
    m = re.match(r"\s*(\d+)\s*\{(.*?)\}", body, re.S)
    if m:
        return [m.group(2).strip()]*int(m.group(1))
    inner = body[body.index("(") + 1:body.rindex(")")]
    return re.findall(r"\([^()]*\)(?:[ \t]+\d+)?", inner) if "(" in inner else inner.split()

def vec(s):
    return [float(v) for v in s[s.index("(") + 1:s.index(")")].split()]

old, new = "before/lagrangian/kinematicCloud", "case/0.01/lagrangian/kinematicCloud"
K = 4
n = len(items(old + "/U"))
pos0 = items(old + "/positions")
pos1 = items(new + "/positions")
check(len(pos1) == K*n and len(items(new + "/U")) == K*n,
      "%d parcels split into %d (K = %d)" % (n, len(pos1), K))
same = True
for f in ("U", "d", "rho"):
    a, b = items(old + "/" + f), items(new + "/" + f)
    same = same and all(b[K*i + k] == a[i] for i in range(n) for k in range(K))
check(same, "every copy has its parcel's U, d and rho as written")
n0 = [float(v) for v in items(old + "/nParticle")]
n1 = [float(v) for v in items(new + "/nParticle")]
worst = max(abs(K*n1[K*i + k]/n0[i] - 1) for i in range(n) for k in range(K))
check(worst <= 1e-15, "nParticle of a copy = the parcel's / %d (largest difference %.2e <= 1e-15)"
      % (K, worst))
ids0 = [int(v) for v in items(old + "/origId")]
ids1 = [int(v) for v in items(new + "/origId")]
check(ids1 == [K*v + k for v in ids0 for k in range(K)] and len(set(ids1)) == K*n,
      "origId of copy k = %d origId + k, all %d unique" % (K, len(set(ids1))))

d0 = [float(v) for v in items(old + "/d")]
d1 = [float(v) for v in items(new + "/d")]
def cell_volumes(pos, nP, d):
    out = {}
    for p, a, b in zip(pos, nP, d):
        c = int(p.split(")")[1])
        out[c] = out.get(c, 0.0) + a*math.pi/6*b**3
    return out
v0, v1 = cell_volumes(pos0, n0, d0), cell_volumes(pos1, n1, d1)
worst = max(abs(v1.get(c, 0.0)/v - 1) for c, v in v0.items())
check(set(v0) == set(v1) and worst <= 1e-12,
      "%d cells hold the solids volume they held (largest difference %.2e <= 1e-12)"
      % (len(v0), worst))

C = [vec(c) for c in items("case/0.01/C" if os.path.isfile("case/0.01/C") else "case/0/C")]
worstF = (1.0, 0.0)
for i, p in enumerate(pos0):
    x, c = vec(p), int(p.split(")")[1])
    for k in range(K):
        q = vec(pos1[K*i + k])
        to = [C[c][j] - x[j] for j in range(3)]
        f = sum((q[j] - x[j])*to[j] for j in range(3))/max(sum(t*t for t in to), 1e-300)
        off = math.sqrt(sum((q[j] - x[j] - f*to[j])**2 for j in range(3)))
        worstF = (min(worstF[0], f), max(worstF[1], f + off/math.sqrt(sum(t*t for t in to))))
check(0.01 - 1e-9 <= worstF[0] and worstF[1] <= 0.5 + 1e-9,
      "every copy on the segment to its cell's centre, fraction %.4f to %.4f (within 0.01-0.5)"
      % worstF)
sys.exit(checks.status())
PY

# The solver reads the split cloud: one step, written
setEntry "$case" system/controlDict startFrom latestTime
setEntry "$case" system/controlDict stopAt writeNow
(cd "$case" && mppicPimpleFoam > log.split 2>&1) || { echo "FAIL the solver on the split cloud"; exit 1; }
/usr/bin/python3 - <<'PY' || status=1
import glob, math, os, sys
import checks
from checks import read_list, report as check
log = open("case/log.split").read()
check("outside of the mesh" not in log and "FOAM FATAL" not in log,
      "the solver read the split cloud: no parcel outside the mesh")
def mass(lag):
    nP, d, rho = (read_list(os.path.join(lag, f)) for f in ("nParticle", "d", "rho"))
    return len(nP), math.fsum(a*r*math.pi/6*b**3 for a, b, r in zip(nP, d, rho))
t = max((x for x in glob.glob("case/0.01*") if x != "case/0.01"),
        key=lambda x: float(os.path.basename(x)))
n0, m0 = mass("before/lagrangian/kinematicCloud")
n1, m1 = mass(os.path.join(t, "lagrangian", "kinematicCloud"))
check(n1 == 4*n0, "after one step at %s s: %d parcels (4 x %d)" % (os.path.basename(t), n1, n0))
check(abs(m1/m0 - 1) <= 1e-12, "cloud mass %.15g kg = before the split %.15g (%.2e <= 1e-12)"
      % (m1, m0, abs(m1/m0 - 1)))
sys.exit(checks.status())
PY
exit $status
