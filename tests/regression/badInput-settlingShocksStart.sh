#!/bin/bash
#------------------------------------------------------------------------------
# badInput-settlingShocksStart <runDir>
# tutorials/verification/settlingShocks' start argument and the hindered
# settling velocity it sets (no solver run, a few seconds):
#   - ./Allrun 0.15 diffusion averaging coloringFunction sideways: exit
#     status 1 before any meshing, the message naming 'sideways' and the
#     allowed 'rest or moving';
#   - settlingShocksResults.py --hindered-velocity 0.7 (above close pack
#     0.6): exit status 2, the message naming 0.7 and (0, 0.6);
#   - --hindered-velocity 0.15 prints eg0*u_r(eg0), by hand (eq 7, Stokes
#     with the voidage factor, 1 mm beads of 2000 kg/m3 in water, mu 1e-3):
#     0.85 * 9.81*1000*1e-6/(18*1e-3) * 0.85^3.65
#       = 0.85 * 0.545 * exp(3.65*ln 0.85) = 0.85 * 0.545 * 0.552536
#       = 0.255973 m/s, to 1e-5 relative (printed to 6 digits).
#------------------------------------------------------------------------------
runDir="${1:?usage: badInput-settlingShocksStart.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

status=0
check()
{
    if [ "$1" = 0 ]
    then
        echo "PASS $2"
    else
        echo "FAIL $2"
        status=1
    fi
}

case="$runDir/case"
copyTutorial verification/settlingShocks "$case"
cd "$case" || exit 1

./Allrun 0.15 diffusion averaging coloringFunction sideways > log.bad 2>&1
rc=$?
cat log.bad
[ "$rc" = 1 ]; check $? "Allrun start sideways: exit status $rc (1)"
grep -q "sideways" log.bad && grep -q "rest or moving" log.bad
check $? "message names 'sideways' and 'rest or moving'"
[ ! -e log.gmsh ]; check $? "stopped before meshing (no log.gmsh)"

/usr/bin/python3 settlingShocksResults.py --hindered-velocity 0.7 \
    > log.range 2>&1
rc=$?
cat log.range
[ "$rc" = 2 ]; check $? "--hindered-velocity 0.7: exit status $rc (2)"
grep -q "0.7" log.range && grep -q "(0, 0.6)" log.range
check $? "message names 0.7 and (0, 0.6)"

value=$(/usr/bin/python3 settlingShocksResults.py --hindered-velocity 0.15)
/usr/bin/python3 -c "import sys; sys.exit(abs($value/0.255973 - 1) > 1e-5)"
check $? "--hindered-velocity 0.15 = $value m/s (hand: 0.255973)"

exit $status
