#!/usr/bin/python3
"""Checks of tests/regression/kuipersBeadsColumn.sh: tutorials/validation/
minimumFluidization/kuipersBeads with a short ramp, 0 -> 0.1 m/s over 0.4 s
(the bed stays fixed: Ergun's Umf is 0.225 m/s): a fixed bed of the Kuipers
jet's beads at the jet's parcel size (5 parcels per cell, close pack 0.62,
seeded at 0.60) gets Ergun's pressure drop for voidage eps = 0.40 (glass
d = 0.5 mm, rho_p = 2660 kg/m3; air rho_g = 1.2 kg/m3, mu = 1.2 x 1.5e-5 =
1.8e-5 Pa s; g = 9.81):
    dP*_Ergun(U) = [150 mu (1-eps)^2 U/(eps^3 d^2)
                    + 1.75 rho_g (1-eps) U^2/(eps^3 d)] / (rho_p (1-eps) g)
    at 0.1 m/s: (6075.0 + 393.8 Pa/m)/15656.8 Pa/m = 0.4132
  - the formula gives the hand value 0.4132 at 0.1 m/s (to 1e-3);
  - the ratio sum(dP*)/sum(dP*_Ergun) over the steps at 0.08-0.10 m/s (at
    least 30), U = 0.1 t/0.4, dP* = (deltaP - gas head)/weight per area from
    bedPressureDrop, within 5 % of 1 (measured 1.004 on 2026-11-26; with the
    tutorial's rhoInf 1.0 beside this gas the function object now stops;
    before it read 1/1.2 of it, 0.84).

Usage: kuipersBeadsColumn.py   (in the case)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.environ["MPPIC_PROJECT_DIR"], "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import checks  # noqa: E402
from checks import report as check  # noqa: E402

mu, rho_g, rho_p, d, eps, g = 1.2*1.5e-5, 1.2, 2660.0, 5e-4, 0.40, 9.81


def ergun(U):
    """Ergun's pressure drop over the bed's weight per area at U."""
    grad = (150*mu*(1 - eps)**2*U/(eps**3*d**2)
            + 1.75*rho_g*(1 - eps)*U**2/(eps**3*d))
    return grad/(rho_p*(1 - eps)*g)


def check_fixed_bed_follows_ergun():
    check(abs(ergun(0.1)/0.4132 - 1) < 1e-3,
          "Ergun dP* at 0.1 m/s %.4f (hand value 0.4132)" % ergun(0.1))
    rows = post.function_object_table(".", "bedPressureDrop")
    pairs = [((r[3] - r[4])/r[5], 0.1*r[0]/0.4) for r in rows]
    window = [(p, U) for p, U in pairs if 0.08 - 1e-9 <= U <= 0.1 + 1e-9]
    ratio = sum(p for p, _ in window)/sum(ergun(U) for _, U in window)
    check(len(window) >= 30 and abs(ratio - 1) <= 0.05,
          "fixed bed, 0.08-0.10 m/s: dP*/Ergun %.4f within 5 %% of 1 (%d steps)"
          % (ratio, len(window)))


if __name__ == "__main__":
    check_fixed_bed_follows_ergun()
    sys.exit(checks.status())
