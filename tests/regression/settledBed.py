#!/usr/bin/python3
"""Checks of tests/regression/settledBed.sh: tutorials/verification/settlingColumn with
coloringFunction (close pack 0.6, e1 0.85, e2 0.9; 1 s): 100 um glass beads
(rho_p = 2500 kg/m3) settle in air (rho_g = 1.2 kg/m3, mu = 1.8e-5 Pa s)
onto the closed bottom and are at rest from about 0.8 s. A bed at rest on
the bottom hands the gas no weight: the bottom carries it.

The slip velocity u_slip at which Ergun's drag carries the buoyant weight
of a bed at solids fraction 0.6 (eps = 0.4, d = 1e-4 m, U = eps u_slip
superficial, g = 9.81):
    150 mu (1-eps)^2 U/(eps^3 d^2) + 1.75 rho_g (1-eps) U^2/(eps^3 d)
        = (rho_p - rho_g)(1 - eps) g                -> u_slip = 0.0242 m/s
(the positive root of a U^2 + b U = rhs). The part f of gravity's impulse
each step that the drag hands the gas while a parcel at rest at the start of
the step accelerates within it (semi-implicit drag, relaxation time
tau = rho_p eps_s/beta, beta = (rho_p - rho_g) eps_s g/u_slip):
    f = 1 - (tau/dt)(1 - exp(-dt/tau)),  dt = 5e-4 s  -> f = 0.095
Checks:
  - 3200 parcels at 1 s, and they keep no velocity they do not move with:
    |mean U_y| at 1 s at most 0.05 u_slip (before the pack-support rule:
    -0.0125 m/s = 0.52 u_slip);
  - the gas pressure drop over the weight per area (bedPressureDrop's
    deltaPByWeight), mean over 0.9-1.0 s, within [0.5 f, f + 0.05]
    (before: 0.39).

Usage: settledBed.py   (in the case)
"""
import glob
import math
import re
import sys

import checks
from checks import read_dat, report as check

rho_p, rho_g, mu, d, g, dt = 2500.0, 1.2, 1.8e-5, 1e-4, 9.81, 5e-4
eps = 0.4


def slip_and_gas_share():
    """u_slip and f as derived above (printed)."""
    rhs = (rho_p - rho_g)*(1 - eps)*g
    a = 1.75*rho_g*(1 - eps)/(eps**3*d)
    b = 150*mu*(1 - eps)**2/(eps**3*d**2)
    U = (-b + math.sqrt(b*b + 4*a*rhs))/(2*a)
    u_slip = U/eps
    beta = (rho_p - rho_g)*(1 - eps)*g/u_slip
    tau = rho_p*(1 - eps)/beta
    f = 1 - tau/dt*(1 - math.exp(-dt/tau))
    print("u_slip %.5f m/s, tau %.3e s, f %.4f" % (u_slip, tau, f))
    return u_slip, f


def check_parcels_at_rest(u_slip):
    text = open("1/lagrangian/kinematicCloud/U").read()
    uy = [float(m.group(2)) for m in re.finditer(
        r"\(([-\d.eE+]+) ([-\d.eE+]+) ([-\d.eE+]+)\)", text)]
    mean_uy = sum(uy)/len(uy)
    check(len(uy) == 3200, "3200 parcels at 1 s (%d)" % len(uy))
    check(abs(mean_uy) <= 0.05*u_slip,
          "|mean U_y| %.3e m/s <= 0.05 u_slip = %.3e m/s" % (abs(mean_uy), 0.05*u_slip))


def check_gas_carries_little_weight(f):
    ratios = []
    for path in glob.glob("postProcessing/bedPressureDrop/0/*.dat"):
        for cols in read_dat(path):
            if 0.9 <= cols[0] <= 1.0:
                ratios.append(cols[6])
    ratio = sum(ratios)/len(ratios)
    check(0.5*f <= ratio <= f + 0.05,
          "deltaP/weight %.4f over 0.9-1.0 s in [0.5 f, f + 0.05] = [%.4f, %.4f]"
          % (ratio, 0.5*f, f + 0.05))


if __name__ == "__main__":
    u_slip, f = slip_and_gas_share()
    check_parcels_at_rest(u_slip)
    check_gas_carries_little_weight(f)
    sys.exit(checks.status())
