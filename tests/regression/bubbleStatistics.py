#!/usr/bin/python3
"""Checks of tests/regression/bubbleStatistics.sh: tutorials/lib/
mppicBubbles.py on a case written by hand (./synthetic).

The bed: 20 x 40 cells of 5 mm (x 0-0.1 m, y 0-0.2 m), two layers (z = 0
and 0.01, the front and back walls), sampled at t = 0, 0.05, ..., 0.5 s:
  - rows 0-23 (y < 0.12 m) at gas fraction 0.4 (solids 0.6), rows above
    at 1: the row-mean solids fraction falls through 0.1 between the
    centres of rows 23 (0.1175 m, 0.6) and 24 (0.1225 m, 0): bed height
    0.1175 + (0.5/0.6) x 0.005 = 0.1216667 m at every time, std 0;
  - in the front layer, at times k = 0..8, a void of 3 x 3 cells (gas
    fraction 0.95) whose lowest row is row 2 + 2k: its centroid rises 2
    cells (0.01 m) per 0.05 s, 0.2 m/s (it stays below row 23, so the bed
    height does not move); its equivalent diameter
    sqrt(4 x 9 x 25e-6/pi) = 16.93 mm;
  - in the back layer one void cell (0.9) at row 5, column 15: void but
    smaller than a bubble (3 cells).
Counted below top = 0.8 x 0.1216667 = 0.0973333 m: rows 0-18 (centres
< 0.0973, row 19's 0.0975),
19 x 20 = 380 cells a layer. The void's rows 2+2k..4+2k lie below row 19
for k <= 7 (rows up to 18); at k = 8 (rows 18-20) one row of 3 cells
counts:
  - void cells: front 8 x 9 + 3 = 75, back 11 x 1 = 11: 86 of
    11 x 2 x 380 = 8360: 0.010287;
  - bubble cells (>= 3 cells): 75 (the k = 8 remnant, a 3-cell row, is one);
    bubble fraction 75/8360 = 0.0089713; bubbles per time and layer:
    9/22 = 0.40909;
  - rise velocities: the pairs k -> k+1 for k = 0..6, each 0.2 m/s; k = 7
    to 8: the remnant (row 18, centroid 0.0925 m; its area 3/9 of the
    void's, at the factor-3 limit, is kept) against the void's centroid at
    row 17 (0.0875 m): 0.005 m in 0.05 s = 0.1 m/s.  7 at 0.2, one at 0.1.
Correlations against hand values (U = 0.5, Umf = 0.213 m/s, eps_mf 0.4):
  - Darton at h = 0.06 m: 0.54 x 0.287^0.4 x 0.06^0.8 / 9.81^0.2 =
    0.54 x 0.606950 x 0.105322 / 1.578824 = 0.021864 m;
  - two-phase theory at D = 0.021864: u_b = 0.287 + 0.711 sqrt(9.81 x
    0.021864) = 0.287 + 0.711 x 0.463128 = 0.616284 m/s; u_e = 0.5325,
    u_b/u_e = 1.157 (1 to 3): delta = 0.287/(0.616284 + 0.213) = 0.34608.
The pressure signal: 1000 + 50 sin(2 pi 2.5 t) sampled every 1e-3 s over
4 s: standard deviation 50/sqrt(2) = 35.355, dominant frequency 2.5 Hz.
Tolerances: relative 1e-9 for counts and geometry, 1e-4 for the
correlations (hand values to 5-6 digits), the frequency to its bin (0.25 Hz).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ["MPPIC_PROJECT_DIR"], "tutorials", "lib"))
import mppicBubbles as mb  # noqa: E402
sys.path.insert(0, os.path.join(os.environ["MPPIC_PROJECT_DIR"], "tests", "lib"))
from checks import report as check, status  # noqa: E402

NX, NY, DX = 20, 40, 0.005


def write_case(case):
    for k in range(11):
        t = 0.05*k
        folder = os.path.join(case, "postProcessing", "bubbleSlices", "%g" % t)
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(folder, "alpha.air_walls.raw"), "w") as f:
            f.write("# alpha.air  FACE_DATA %d\n# x  y  z  alpha.air\n"
                    % (2*NX*NY))
            for z in (0.0, 0.01):
                for j in range(NY):
                    for i in range(NX):
                        eps = 0.4 if j < 24 else 1.0
                        if z == 0 and k <= 8 and 2 + 2*k <= j <= 4 + 2*k and 8 <= i <= 10:
                            eps = 0.95
                        if z > 0 and j == 5 and i == 15:
                            eps = 0.9
                        f.write("%g %g %g %g\n" % ((i + 0.5)*DX, (j + 0.5)*DX, z, eps))


def close(value, reference, tol):
    return abs(value - reference) <= tol*abs(reference)


def main():
    write_case("synthetic")
    times, xs, ys, eps = mb.read_slices("synthetic")
    check(eps.shape == (11, 2, NY, NX), "read_slices: shape %s = (11, 2, %d, %d)"
          % (eps.shape, NY, NX))
    s = mb.bubble_statistics(times, xs, ys, eps, 0, 0.5)
    for name, value, ref, tol in (
            ("bed height [m]", s["bedHeight"], 0.1175 + 0.005*0.5/0.6, 1e-9),
            ("top [m]", s["top"], 0.8*(0.1175 + 0.005*0.5/0.6), 1e-9),
            ("void fraction", s["voidFraction"], 86/8360., 1e-9),
            ("bubble fraction", s["bubbleFraction"], 75/8360., 1e-9),
            ("bubbles per time and layer", s["bubblesPerFrame"], 9/22., 1e-9),
            ("largest diameter [m]", s["largest"],
             math.sqrt(4*9*DX*DX/math.pi), 1e-9)):
        check(close(value, ref, tol), "%s %.8g against %.8g (rel. %g)"
              % (name, value, ref, tol))
    check(s["bedHeightStd"] < 1e-12, "bed height std %.3g = 0" % s["bedHeightStd"])
    rise = sorted(v for d, v in s["rise"])
    check(len(rise) == 8 and close(rise[0], 0.1, 1e-9)
          and all(close(v, 0.2, 1e-9) for v in rise[1:]),
          "rise velocities %s: one at 0.1 m/s and 7 at 0.2 m/s"
          % ", ".join("%.4g" % v for v in rise))

    d = float(mb.darton_diameter(0.5, 0.213, 0.06))
    check(close(d, 0.021864, 1e-4), "Darton D(0.06 m) %.6g against 0.021864 m" % d)
    delta, ub = mb.two_phase_bubble_fraction(0.5, 0.213, 0.4, d)
    check(close(ub, 0.616284, 1e-4) and close(delta, 0.34608, 1e-4),
          "two-phase u_b %.6g against 0.616284 m/s, delta %.6g against 0.34608"
          % (ub, delta))

    t = np.arange(4000)*1e-3
    std, f, psd, peak = mb.pressure_signal(t, 1000 + 50*np.sin(2*math.pi*2.5*t))
    check(close(std, 50/math.sqrt(2), 1e-3), "signal std %.5g against 35.355" % std)
    check(abs(peak - 2.5) <= 0.25, "dominant frequency %.4g Hz against 2.5 Hz" % peak)
    return status()


if __name__ == "__main__":
    sys.exit(main())
