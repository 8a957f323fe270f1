#!/usr/bin/python3
"""Checks of tests/regression/sedimentation.sh: tutorials/verification/
sedimentation with coloringFunction (1 s, the full case): a suspension at
solids fraction 0.15 settles into a bed at close pack alpha_cp = 0.6, 32
parcels per packed cell. From the packing monitor (every step) and the final
field, read with the tutorial's sedimentationResults helpers:
  - the gas fraction never falls below 0;
  - the final bed height (where the bed profile crosses alpha_cp/2) within
    3 % of the inventory height
        V_solids/(alpha_cp A) = 5.625e-6/(0.6 x 0.05 x 0.005) = 0.0375 m;
  - the cloud mass at the end = the seeded solids volume x 2500 kg/m3 to
    1e-9;
  - at every step, the largest solids fraction of the model's averaging
    (basic: the cell solids fraction, which moves in steps of one parcel,
        V_solids/N_parcels/(5 mm)^3 = 0.01875 of a cell here)
    at most max(1.03 alpha_cp, alpha_cp + one parcel) = max(0.618, 0.61875).

Usage: sedimentation.py   (in the case)
"""
import sys

sys.path.insert(0, ".")
from sedimentationResults import read_monitor, bed_profile, post, \
    surface_height, seeded_solids_volume  # noqa: E402 (the case's copy)
import checks  # noqa: E402
from checks import report as check  # noqa: E402


def check_settled_bed(cp, rows):
    min_gas = min(r[6] for r in rows)
    check(min_gas >= 0, "gas fraction never below 0 (min %.4f)" % min_gas)
    ys, prof, dy, _, _ = bed_profile(".", post.latest_time("."))
    h = surface_height(ys, prof, 0.5*cp, dy)
    check(abs(h/0.0375 - 1) <= 0.03, "bed height %.4f m within 3 %% of 0.0375 m" % h)
    mass = rows[-1][2]
    check(abs(mass/(seeded_solids_volume(".")*2500) - 1) < 1e-9,
          "cloud mass %.10g kg = seeded volume * 2500" % mass)


def check_packing_bound(cp, rows):
    max_avg = max(r[3] for r in rows)
    one_parcel = seeded_solids_volume(".")/rows[-1][1]/0.005**3  # 5 mm cubes
    bound = max(1.03*cp, cp + one_parcel)
    check(abs(one_parcel - 0.01875) < 1e-9, "one parcel = %.6f of a cell" % one_parcel)
    check(max_avg <= bound, "max solids fraction %.6f <= max(1.03*alpha_cp, "
          "alpha_cp + one parcel) = %.6f at every step" % (max_avg, bound))


if __name__ == "__main__":
    cp, rows = read_monitor(".")
    check_settled_bed(cp, rows)
    check_packing_bound(cp, rows)
    sys.exit(checks.status())
