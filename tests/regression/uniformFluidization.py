#!/usr/bin/python3
"""Checks of tests/regression/uniformFluidization.sh: tutorials/validation/
uniformFluidization (coloringFunction, GidaspowDrag, 7680 parcels) for 2 s,
a bed of 0.5 mm glass fluidized uniformly at 0.5 m/s = 2.35 Umf, read with
the tutorial's uniformFluidizationResults:
  - bedPressureDrop's weight per area at every step (to 1e-9) the bed's
        m g/A = 0.1 x 0.12 x 0.01 x 0.6 x 2500 x 9.81/0.001 = 1765.8 Pa
    (bed 0.1 m wide, 0.12 m high, 0.01 m deep at solids fraction 0.6;
    section A = 0.1 x 0.01 m2);
  - the time-mean of (deltaP - gas head)/(m g/A) over 1.2-2 s, after the
    start-up (the packed bed first lifts, 2.2 x its weight at t = 0), within
    3 % of 1 (measured 0.9869 on 2026-11-27; with fixedFluxPressure on the
    inlet, which leaves out the first row's drag, 0.966, and with cellPoint
    interpolation of the gas velocity 0.78: both fail here);
  - 7680 parcels and the cloud mass 0.18 kg at every step (to 1e-9);
  - the largest cell solids fraction at most
        max(1.05 x 0.6, 0.6 + one parcel 0.6/8) = 0.675
    (cell-based field; 8 parcels in a packed cell).

Usage: uniformFluidization.py   (in the case)
"""
import sys

sys.path.insert(0, ".")
import uniformFluidizationResults as u  # noqa: E402 (the case's copy)
import checks  # noqa: E402
from checks import report as check  # noqa: E402


def check_weight_per_area():
    weight = 0.1*0.12*0.01*0.6*2500*9.81/0.001
    rows = u.post.read_table("postProcessing/bedPressureDrop/0/bedPressureDrop.dat")
    check(all(abs(r[5]/weight - 1) < 1e-9 for r in rows),
          "weight per area %.4f Pa = %.4f Pa at every step" % (rows[-1][5], weight))


def check_pressure_drop_carries_weight():
    res = u.summary(".", 1.2)
    check(abs(res["ratio"] - 1) <= 0.03,
          "(deltaP - gas head)/weight over 1.2-2 s %.4f within 3 %% of 1" % res["ratio"])


def check_parcels_mass_and_packing():
    mon = u.monitor(".")
    check(all(r[1] == 7680 for r in mon), "7680 parcels at every step")
    check(all(abs(r[2]/0.18 - 1) < 1e-9 for r in mon), "cloud mass 0.18 kg at every step")
    bound = max(1.05*0.6, 0.6 + 0.6/8)
    check(max(r[4] for r in mon) <= bound + 1e-12,
          "max cell solids fraction %.4f <= %.4f at every step"
          % (max(r[4] for r in mon), bound))


if __name__ == "__main__":
    check_weight_per_area()
    check_pressure_drop_carries_weight()
    check_parcels_mass_and_packing()
    sys.exit(checks.status())
