#!/bin/bash
#------------------------------------------------------------------------------
# splitParcels <runDir>
# bin/splitParcels on tutorials/validation/uniformFluidization (hexahedra,
# a prescribed uniform gas flow of 0.8 m/s upward so that only the cloud
# runs), ascii at 17 digits, run to 0.01 s and its cloud split into K = 4.
# checks: splitParcels.py split (the copies' fields, each cell's solids
# volume, each copy between its parcel and its cell's centre), then the
# solver reads it and runs one step (stopAt writeNow): splitParcels.py solver
# (no parcel outside the mesh, 4 N parcels, the cloud's mass kept);
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
bad=$(/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/splitParcels.py" \
    badNParticle "${nP:-1}")
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
    /usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/splitParcels.py" oneShort "$1"
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
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/splitParcels.py" split || status=1

# The solver reads the split cloud: one step, written
setEntry "$case" system/controlDict startFrom latestTime
setEntry "$case" system/controlDict stopAt writeNow
(cd "$case" && mppicPimpleFoam > log.split 2>&1) || { echo "FAIL the solver on the split cloud"; exit 1; }
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/splitParcels.py" solver || status=1
exit $status
