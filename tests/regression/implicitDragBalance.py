#!/usr/bin/python3
"""Checks of tests/regression/implicitDragBalance.sh: tutorials/validation/
uniformFluidization at 3 parcels per packed cell (2880 parcels), 40 steps of
dt = 5e-4 s from the seeded bed with the fields written at every step, PIMPLE
balanceImplicitDrag off and on (runs off/ and on/).

Per step, the cloud's vertical momentum budget over the weight W,
    R = (P_y(t) - P_y(t - dt))/(dt W) + 1 - J_pack/(dt W)
        - (deltaP - gas head)/(W/A)
(P_y the parcels' momentum from the written U, nParticle, d, rho
(mppicPost.cloud_momentum); J_pack the packing monitor's impulse of the
step (packingMomentumY); (deltaP - gas head)/(W/A) from bedPressureDrop) is
what neither the gas's pressure drop nor the packing step gave the parcels:
the walls' share. The side walls rebound without friction and no parcel
reaches the distributor here (checked: every parcel at least d/2 above it
at every written step), so R is what the parcels got from the gas beyond
the gas's pressure drop. Steps 2-40 (the first step starts from a bed at
rest on the inlet):
  - on: |mean R| <= 5e-4 of the weight (measured -0.00024 against 0.0008
    without the balance, 2026-11-27);
  - off - on: the mean R of the run without the balance less the run with
    it equals the mean momentum the balance gave the parcels per step over
    dt W (its log line, "Implicit drag balance: parcels given (x y z)"),
    with the opposite sign, to 30 % (measured 0.0010 and -0.00101), over
    its 40 log lines: the switch removes exactly the difference it logs;
  - the cells without parcels (the impulse that cannot be passed on) hold
    at most 1e-3 of it;
  - 2880 parcels and the mass 0.18 kg at every step.

Usage: implicitDragBalance.py   (in the run folder that holds off/ and on/)
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ["MPPIC_PROJECT_DIR"], "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import checks  # noqa: E402
from checks import report as check  # noqa: E402

DT = 5e-4


def budget(case):
    """R of each step; the lowest gap between a parcel and the distributor
    over the written steps; the monitor's rows; the weight."""
    dp = {round(r[0], 6): (r[3] - r[4])/r[5] for r in
          post.read_table(os.path.join(case, "postProcessing/bedPressureDrop/0/bedPressureDrop.dat"))}
    mon = post.read_table(os.path.join(case, "postProcessing/packingMonitor/0/packingMonitor.dat"))
    pack = {round(r[0], 6): r[9] for r in mon}
    weight = mon[0][2]*9.81
    momentum, lowest = {}, {}
    for t, d in post.time_dirs(case):
        cloud = os.path.join(case, d, "lagrangian", "kinematicCloud")
        if not os.path.exists(os.path.join(cloud, "U")):
            continue
        y = [p[1] for p in post.lagrangian_field(os.path.join(cloud, "positions"))]
        diameters = [v[0] for v in post.lagrangian_field(os.path.join(cloud, "d"))]
        momentum[round(t, 6)] = post.cloud_momentum(case, d)
        lowest[round(t, 6)] = min(yi - di/2 for yi, di in zip(y, diameters))
    steps = sorted(momentum)
    rest = [(momentum[t] - momentum[s])/(DT*weight) + 1 - pack[t]/(DT*weight) - dp[t]
            for s, t in zip(steps, steps[1:])]
    return rest, min(lowest.values()), mon, weight


def given(case):
    """The momentum the balance gave per step, y, over dt W; and the share
    of it that cells without parcels kept."""
    rows = [re.findall(r"\(([^)]*)\)", line) for line in open(os.path.join(case, "log.steps"))
            if line.startswith("Implicit drag balance")]
    y = [float(r[0].split()[1]) for r in rows]
    kept = [float(r[1].split()[1]) for r in rows]
    return y, sum(abs(k) for k in kept)/max(sum(abs(g) for g in y), 1e-300)


def check_both_runs(results):
    """No parcel on the distributor; parcels and mass kept."""
    for mode, (rest, low, mon, weight) in results.items():
        check(low > 0, "%s: every parcel above the distributor by %.3g m or more" % (mode, low))
        check(all(r[1] == 2880 for r in mon) and all(abs(r[2]/0.18 - 1) < 1e-9 for r in mon),
              "%s: 2880 parcels and 0.18 kg at every step" % mode)


def check_balance_closes_budget(results):
    """The budget's rest with the balance, and the difference the switch
    makes against the impulse it logs."""
    rest_on, rest_off = (sum(results[m][0])/len(results[m][0]) for m in ("on", "off"))
    check(abs(rest_on) <= 5e-4,
          "on: the momentum budget's rest %.2e of the weight per step, within 5e-4" % rest_on)
    impulse, kept = given("on")
    mean_given = sum(impulse[1:])/len(impulse[1:])/(DT*results["on"][3])
    check(len(impulse) == 40 and abs((rest_off - rest_on)/(-mean_given) - 1) <= 0.3,
          "off - on %.5f = -(the balance's mean impulse %.5f) to 30 %% (%d log lines)"
          % (rest_off - rest_on, mean_given, len(impulse)))
    check(kept <= 1e-3, "cells without parcels kept %.2e of the impulse" % kept)


if __name__ == "__main__":
    results = {mode: budget(mode) for mode in ("off", "on")}
    check_both_runs(results)
    check_balance_closes_budget(results)
    sys.exit(checks.status())
