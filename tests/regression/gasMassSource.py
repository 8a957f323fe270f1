#!/usr/bin/python3
"""Checks of tests/regression/gasMassSource.sh: gas added inside the domain
(libmppicModels' gasMassSources, MFiX's point sources) against the 1D
solution.

A channel of length L = 1 m along x, 200 cells, closed at x = 0 (wall),
open at x = L (p = 0), section A = 1e-4 m2, no parcels, no gravity; one
source spread over the whole channel adds S = Q/V = 1 /s of gas volume per
unit volume (Q = 1e-4 m3/s) with the velocity (u_s, 0, 0). Continuity gives
U(x) = S x, whatever the time, so the steady momentum balance
    U dU/dx = S (u_s - U) - dp/dx
holds from the first step and
    p(x) - p(L) = S^2 (L^2 - x^2) - S u_s (L - x)        (kinematic p)
Checks, for u_s = 0 and u_s = 0.5 m/s after 5 steps of 1e-3 s (channel):
  - the outlet's gas flux equals Q to 1e-8 (the continuity's source);
  - the face fluxes equal S x A to 1e-8 relative (face i at x = (i+1) L/n),
    the cell velocities S x within 0.5 % of the outflow's S L;
  - p at the first cell (x = 0.0025 m) within 1 % of the formula
    (0.99999 and 0.49874 m2/s2): a missing momentum source (the gas
    arriving with the cell's velocity) would give 0.5 x and 1.0 x of these,
    a double-counted one 1.5 x.
The continuity error printed by the solver, with the source taken off,
stays below 1e-10 (continuity).
On 2 ranks (u_s = 0.5 m/s, the channel cut at x = 0.5, the sphere spread
over both), p and the face fluxes equal the serial run's to 1e-9 of the
largest value (ranks): the source's cell volume is summed over the ranks.

Usage:
    gasMassSource.py channel <case> <u_s>          (its 0.005 s fields)
    gasMassSource.py continuity <error> <u_s>      (the log's largest sum local)
    gasMassSource.py ranks <serial time dir> <2-rank time dir>
"""
import re
import sys

from checks import report, run_command, status


def internal_field(time_dir, name, vector=False):
    """The internal field of a nonuniform volume or surface field file."""
    text = open(time_dir + "/" + name).read()
    body = text.split("internalField", 1)[1]
    body = body[body.index("(", body.index("\n")) + 1:]
    if vector:
        return [tuple(map(float, v.split()))
                for v in re.findall(r"\(([^()]*)\)", body.split("\n)\n")[0])]
    return [float(v) for v in body.split(")")[0].split()]


def check_channel(case, us):
    """The 1D solution's outflow, fluxes, velocities and first cell's p."""
    t = case + "/0.005"
    x = [c[0] for c in internal_field(t, "C", vector=True)]
    U = [u[0] for u in internal_field(t, "U.air", vector=True)]
    p = internal_field(t, "p")
    S, L, Q = 1.0, 1.0, 1e-4

    phi = open(t + "/phi.air").read()
    top = phi.split("top", 1)[1]
    m = re.search(r"value\s+uniform\s+([-0-9.eE+]+)", top) or \
        re.search(r"value\s+nonuniform\s+List<scalar>\s+1\(([-0-9.eE+]+)\)", top)
    outflow = float(m.group(1))
    report(abs(outflow - Q) <= 1e-8*Q,
           "outlet flux %.12g m3/s, Q %g (1e-8)" % (outflow, Q))

    A, n = 1e-4, len(x)
    faceFlux = internal_field(t, "phi.air")
    worst = max(abs(f - S*(i + 1)/n*L*A)/(S*(i + 1)/n*L*A)
                for i, f in enumerate(faceFlux))
    report(len(faceFlux) == n - 1 and worst <= 1e-8,
           "%d face fluxes, largest |phi - S x A|/(S x A) %.3g (1e-8)"
           % (len(faceFlux), worst))
    worst = max(abs(u - S*xi) for u, xi in zip(U, x))/(S*L)
    report(worst <= 0.005,
           "largest |U - S x|/(S L) at the cells: %.3g (0.5 %%)" % worst)

    x1 = x[0]
    exact = S**2*(L**2 - x1**2) - S*us*(L - x1)
    report(abs(p[0] - exact) <= 0.01*exact,
           "p at x = %.4f m: %.6g m2/s2, formula %.6g (1 %%)" % (x1, p[0], exact))


def check_continuity(errs, us):
    """errs and us as the script has them (printed as given)."""
    report(float(errs) <= 1e-10,
           'largest continuity error (sum local), u_s %s: %s (1e-10)' % (us, errs))


def check_two_ranks(serial_time, ranks2_time):
    for name in ("p", "phi.air"):
        serial, ranks2 = internal_field(serial_time, name), internal_field(ranks2_time, name)
        scale = max(abs(v) for v in serial)
        worst = max(abs(a - b) for a, b in zip(serial, ranks2))/scale
        report(len(serial) == len(ranks2) and worst <= 1e-9,
               "%s on 2 ranks against serial: largest difference %.3g of the "
               "largest value (1e-9)" % (name, worst))


def main(argv):
    return run_command(argv, {
        "channel": lambda case, u: check_channel(case, float(u)),
        "continuity": check_continuity, "ranks": check_two_ranks})


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
