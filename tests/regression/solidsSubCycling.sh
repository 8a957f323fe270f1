#!/bin/bash
#------------------------------------------------------------------------------
# solidsSubCycling <runDir>
# tutorials/verification/terminalVelocity with gas steps growing to 0.01 s
# (adjustTimeStep) and solids sub-cycling on (CFL 0.1, relaxationTimeFactor
# 0.01): every gas step limited by the response time takes
#     n = ceil(dt_gas/(0.01*tau_p)),  tau_p = rho_p*d^2/(18*mu_g)
#       = 2000*(1e-4)^2/(18*1.8e-5) = 0.0617284 s,
# so 17 sub-steps per 0.01 s step; and the parcel still meets the 0.5 %
# goals of the case against RK4 (the same run without sub-cycling takes
# one explicit step of 0.01 s, 16 % of tau_p). A second run limited by
# CFL 0.05 alone: the solids step of the gas step after each write time
# equals 0.05*dy/|V_y| (dy = 0.3 m/60 = 0.005 m, V_y the written parcel
# velocity). Then bad input: CFL 0 and
# maxSubCycles 0 stop with a FatalIOError naming the keyword and range.
#------------------------------------------------------------------------------
runDir="${1:?usage: solidsSubCycling.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"

case="$runDir/case"
copyTutorial verification/terminalVelocity "$case"
setEntry "$case" system/controlDict deltaT 1e-4
setEntry "$case" system/controlDict adjustTimeStep yes
setEntry "$case" system/controlDict maxCo 1000
setEntry "$case" system/controlDict maxDeltaT 0.01
setEntry "$case" constant/kinematicCloudProperties solidsSubCycling \
    "{ active true; CFL 0.1; relaxationTimeFactor 0.01; }"
runAllrun "$case" || exit 1

status=0
responseTime=$(/usr/bin/python3 -c 'print(repr(2000*1e-4**2/(18*1.8e-5)))')
check subCycles "$case/log.mppicPimpleFoam" "$responseTime" 0.01 || status=1
(cd "$case" && /usr/bin/python3 terminalVelocityResults.py --check) \
    || status=1

foamListTimes -case "$case" -rm > /dev/null
setEntry "$case" constant/kinematicCloudProperties solidsSubCycling \
    "{ active true; CFL 0.05; relaxationTimeFactor 10; }"
(cd "$case" && mppicPimpleFoam > log.CFL 2>&1) || status=1
check subCyclesCFL "$case" "$case/log.CFL" 0.05 0.005 || status=1

for bad in "CFL 0;:CFL:(0, 1]" "maxSubCycles 0;:maxSubCycles:[1, inf)" \
           "relaxationTimeFactor 0;:relaxationTimeFactor:(0, inf)"
do
    entry="${bad%%:*}"
    rest="${bad#*:}"
    setEntry "$case" constant/kinematicCloudProperties solidsSubCycling \
        "{ active true; $entry }"
    (cd "$case" && mppicPimpleFoam > log.broken 2>&1)
    rc=$?
    check fatal "$case/log.broken" $rc "${rest%%:*}" "${rest#*:}" \
        || status=1
done
exit $status
