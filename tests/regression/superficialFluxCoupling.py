#!/usr/bin/python3
"""Checks of tests/regression/superficialFluxCoupling.sh: the fixed bed of
tutorials/validation/minimumFluidization (20 rows of 0.01 m cells at close
pack 0.62 below a freeboard of 20 rows) under an inlet velocity ramping to
U = 0.12 m/s at 0.6 s, with mppicPimpleFoam's superficialFluxCoupling.

The bed does not move, so the gas is steady but for the ramp (dU/dt =
0.2 m/s2 changes the gas's momentum by 0.2/9.81 of its weight: nothing
against the drag). Continuity then gives every horizontal row of cells
the inlet's superficial velocity: the sum over a row's faces of ag_f phi
is U times the row's area, whatever the gas fraction. On this mesh of
cubes the cell velocity's first part, the rebuilt superficial flux over
the cell's gas fraction, U_y = (flux below + flux above)/(2 ag S_f), has
the row mean of ag U_y equal to U:

    mean over row j of alpha.air U.air_y = U = 0.12 m/s   (every row)

Its second part (mppicSuperficialFlux::cellVelocity) restores the cell's
own H where the faces' interpolation smoothed it: zero where H is the
same from cell to cell, as in the bed, but not in the freeboard's first
rows, where the gas leaving the bed slows from its interstitial 0.32 m/s
to 0.12 m/s (measured there 2.4 % below U at 0.6 s, and 2.5 % with the
ramp four times slower: a steady offset, not a growing one).
  - the written time 0.6 s, inlet velocity 0.12 m/s (the ramp's end);
  - every row of the bed (solids fraction above 0.3) within 2 % of U,
    the top bed row named in the output (with MPPICFoam's coupling, HbyA
    + rAU reconstruct(forces), it carries about half: its 1/A is the
    bed's and one of its faces has the freeboard's gradient; measured
    there 0.062, and 0.34 m/s in the freeboard's first row);
  - every row of the freeboard within 4 % of U.

The pressure drop over the fixed bed is then Ergun's for its voidage
0.38 (minimumFluidization.py's formula and hand value, 0.6359 of the
weight at 0.12 m/s):
  - the mean of dP* over 0.115-0.12 m/s within 3 % of 0.6359. (Earlier
    in the ramp dP* lies above Ergun by 0.012-0.023 of the weight, a
    share that falls as the ramp goes on: 1.056 x Ergun at 0.06 m/s;
    MPPICFoam's coupling, which misses half a cell of the bed's
    gradient, 1.029 there and 0.968 at 0.115-0.12 m/s.)

Usage: superficialFluxCoupling.py   (in the case)
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ["MPPIC_PROJECT_DIR"],
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402
import checks  # noqa: E402
from minimumFluidization import ergun  # noqa: E402
from checks import report as check  # noqa: E402

U_INLET, TIME = 0.12, "0.6"


def check_rows_carry_inlet_velocity():
    alpha = np.array(post.internal_field(os.path.join(TIME, "alpha.air")))
    ug = np.array(post.internal_field(os.path.join(TIME, "U.air")))
    centres = post.internal_field(os.path.join(TIME, "C"))
    heights, superficial = post.layer_means(alpha*ug[:, 1], centres)
    _, solids = post.layer_means(1 - alpha, centres)
    bed = [j for j, s in enumerate(solids) if s > 0.3]
    check(len(bed) >= 19, "the bed fills %d rows (20 seeded)" % len(bed))
    top = max(bed)
    check(abs(superficial[top]/U_INLET - 1) <= 0.02,
          "top bed row (y = %.3f m, solids %.3f): mean ag U_y %.4f m/s "
          "within 2 %% of %.2f" % (heights[top], solids[top],
                                   superficial[top], U_INLET))
    freeboard = [j for j in range(len(heights)) if j not in bed]
    for rows, name, bound in ((bed, "bed", 0.02),
                              (freeboard, "freeboard", 0.04)):
        worst = max(rows, key=lambda j: abs(superficial[j]/U_INLET - 1))
        check(abs(superficial[worst]/U_INLET - 1) <= bound,
              "every one of the %s's %d rows within %g %% of %.2f m/s "
              "(farthest: y = %.3f m, %.4f)"
              % (name, len(rows), 100*bound, U_INLET, heights[worst],
                 superficial[worst]))


def check_fixed_bed_follows_ergun():
    sys.path.insert(0, ".")
    import minimumFluidizationResults as m  # the case's copy
    raw = m.curve(".", m.bed("."))
    check(abs(ergun(U_INLET)/0.6359 - 1) < 1e-3,
          "Ergun dP* at 0.12 m/s %.4f (hand value 0.6359)" % ergun(U_INLET))
    near = [p for u, p in raw if abs(u - U_INLET) <= 0.005]
    mean = sum(near)/len(near)
    check(abs(mean/0.6359 - 1) <= 0.03,
          "dP* at 0.115-0.12 m/s %.4f within 3 %% of Ergun 0.6359 (%d steps)"
          % (mean, len(near)))


if __name__ == "__main__":
    check_rows_carry_inlet_velocity()
    check_fixed_bed_follows_ergun()
    sys.exit(checks.status())
