#!/usr/bin/python3
"""Checks of tests/regression/rayleighTaylor.sh: tutorials/validation/
rayleighTaylor, particle density 5 kg/m3, the coarse slice (-cellSize 0.005:
20 x 120 cells one cell deep, 9600 parcels), to 0.7 s, read with the
tutorial's rayleighTaylorResults.summary.

A particle-laden gas (solids fraction 0.2) over clear gas (1 kg/m3) mixes
in a layer that grows as h = alpha A g t^2 with alpha between 0.05 and 0.07
(seed 2, section 3.1). The Atwood number of the mixture (not seed 2's
Table 6 for rho_p 7), by hand:
    rho_mix = 0.8 x 1 + 0.2 x 5 = 1.8 kg/m3,  A = (1.8 - 1)/(1.8 + 1) = 0.285714
  - the case's Atwood number is that hand value (to 1e-12), its rows 0.005 m
    apart;
  - the layer grows: alpha, the least-squares slope of h against A g t^2
    through the origin over the self-similar range (from h >= 4 cells on; h
    the half-width of the layer between the rows where the horizontally
    averaged solids fraction crosses 5 % and 95 % of 0.2), fitted over at
    least 3 instants, above 0.03, 0.6 x the band's lower edge (a coupling
    that lets the gas through the mixture, or a mixture that does not fall,
    gives less), and below 0.1, 1.4 x its upper edge (a mixture that falls
    nearly unresisted gives more: 0.3 on the 2.5 mm slice with an earlier
    form of PIMPLE superficialFluxCoupling, whose cell velocity carried
    the face flux's time-derivative correction);
  - 9600 parcels at the end (nothing leaves: the outlet is a wall for the
    parcels).
Printed, not asserted: the fit's RMS residual, and alpha and
h(0.7 s)/(A g t^2) against seed 2's band 0.05-0.07 (GOAL lines). On the
defaults this coarse slice falls short (measured alpha 0.040, h(0.7 s)
0.029 x A g t^2, residual 0.19 of the mean h); the band on the seed's
2.5 mm slice over 1.2 s is the validation matrix's.

The test's second case has PIMPLE superficialFluxCoupling true and the
lower bound 0.02 (--lower): that coupling's cell velocity keeps a fourth-
order part of the faces' smoothing, which weighs more on this coarse
slice (measured alpha 0.026 here, 0.029 on the 2.5 mm slice where the
defaults give 0.032).

Usage: rayleighTaylor.py [--lower L]   (in the case; L default 0.03)
"""
import re
import sys

sys.path.insert(0, ".")
import rayleighTaylorResults as rt  # noqa: E402 (the case's copy)
import checks  # noqa: E402
from checks import report as check  # noqa: E402

A_HAND = (1.8 - 1)/(1.8 + 1)


def check_atwood_number_and_rows(res):
    check(abs(res["A"] - A_HAND) < 1e-12 and abs(A_HAND - 0.285714) < 1e-6,
          "Atwood number %.6f = hand value %.6f" % (res["A"], A_HAND))
    check(abs(res["cell"] - 0.005) < 1e-9, "rows 0.005 m apart")


def check_layer_grows(res, lower):
    """alpha between lower and 0.1; the fit's residual and the GOAL lines
    printed."""
    alpha = res.get("alpha", float("nan"))
    t0, t1 = res.get("range", (0, -1))
    fitted = [(t, h) for t, h, _, _ in res["series"] if t0 - 1e-9 <= t <= t1 + 1e-9]
    residual = (sum((h - alpha*A_HAND*9.81*t*t)**2 for t, h in fitted)/len(fitted))**0.5 \
        if fitted else float("nan")
    mean_h = sum(h for _, h in fitted)/len(fitted) if fitted else float("nan")
    check(len(fitted) >= 3 and lower < alpha < 0.1,
          "%g < alpha %.4f < 0.1 (fit over %g-%g s)" % (lower, alpha, t0, t1))
    print("fit h = alpha A g t^2: RMS residual %.5f m, %.2f of the mean h %.5f m"
          % (residual, residual/mean_h, mean_h))
    print("GOAL alpha %.4f %s seed 2's band [0.05, 0.07]"
          % (alpha, "inside" if 0.05 <= alpha <= 0.07 else "outside"))
    series = {round(t, 6): h for t, h, _, _ in res["series"]}
    h = series.get(0.7)
    if h is not None:
        print("GOAL h(0.7 s)/(A g t^2) = %.4f %s [0.05, 0.07]"
              % (h/(A_HAND*9.81*0.49),
                 "inside" if 0.05 <= h/(A_HAND*9.81*0.49) <= 0.07 else "outside"))


def check_parcels_kept():
    text = open("log.mppicPimpleFoam").read()
    counts = re.findall(r"Current number of parcels\s*=\s*(\d+)", text)
    check(bool(counts) and int(counts[-1]) == 9600,
          "9600 parcels at the end (%s)" % (counts[-1] if counts else "none"))


if __name__ == "__main__":
    res = rt.summary(".")
    check_atwood_number_and_rows(res)
    check_layer_grows(res, float(sys.argv[sys.argv.index("--lower") + 1])
                      if "--lower" in sys.argv else 0.03)
    check_parcels_kept()
    sys.exit(checks.status())
