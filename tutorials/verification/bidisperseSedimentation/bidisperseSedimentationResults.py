#!/usr/bin/python3
"""Fronts of the bidisperse sedimentation case against the exact solution.

Usage:
    bidisperseSedimentationResults.py [--case DIR] [--time T] [--check]
                                      [--plot] [--record FILE]

Reads the parcels of <time>/lagrangian/kinematicCloud (each phase's cell
solids fractions, from the parcels' typeId: phase 1 the 1 mm beads, phase 2
the 0.5 mm ones), 0/C and 0/V, and averages each phase's solids fraction
over each horizontal layer of cells. Fronts (linear interpolation between
layer centres):
  - clear top: the highest height where the small phase's profile falls
    through a*/2 (a*: the small-only zone's solids fraction);
  - mixture top: the highest height where the large phase's profile falls
    through alpha_1,0/2 (the top of the zone holding large beads);
  - sediment top: the lowest height where the total profile falls through
    (alpha_max + phi_0)/2 (the top of the packed bed).
Exact fronts: bidisperseFronts.py (the kinematic-wave solution, parcels at
their equilibrium slip from t = 0), corrected for the parcels' start from
rest: in the mixture zone each phase relaxes to its slip by the linear
equations (OpenFOAM's parcel equation with the liquid's return flow)
    dv_i/dt = -g' + (u_f - v_i)/T_i,  u_f = -(alpha_1 v_1 + alpha_2 v_2)/eps,
    T_i = rho_p d_i^2/(18 mu) eps^(n+1),  g' = g (1 - rho_f/rho_p),
solved exactly; the mixture top moves by the large phase's displacement,
the sediment top by the mixture's solids volume arriving over
(alpha_max - phi_0); the clear top relaxes to its speed with the small-only
zone's time T_2(a*)*(1 - a*) (that zone forms as the large beads leave,
within T_2; its lag, about 1 mm, is taken to first order).
Prints the fronts; --check: exit 1 unless every front is within 2 % of its
exact height or 0.005 m, whichever is larger, each phase's mass is kept to
1e-12 (postProcessing/packingMonitor/0/phases.dat) and no cell exceeds
close pack (packingMonitor.dat); --plot: bidisperseSedimentation_<t>.png;
--record FILE: the validation matrix's record (case bidisperseSedimentation):
the fronts at 1 s and at --time, the masses and the bound.
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import validationRecord as record  # noqa: E402 (tutorials/lib)
import bidisperseFronts as exact  # noqa: E402

LARGE, SMALL = 1, 2
FRONTS = ("clear_top", "mixture_top", "sediment_top")


def case_parameters(case):
    """The exact solution's parameters from the case's dictionaries."""
    seed = os.path.join(case, "system", "mppicSeedParcelsDict")
    alpha = post.dict_number(seed, "solidsFraction")
    box = post.dict_entry(seed, "box")
    top = float(box.replace("(", " ").replace(")", " ").split()[4])
    params = dict(H=top, g=post.G)
    for name, key in (("large", "alpha1"), ("small", "alpha2")):
        params[key] = alpha*phase_number(seed, name, "volumeFraction")
    for name, key in (("large", "d1"), ("small", "d2")):
        params[key] = phase_number(seed, name, "diameter")
    return params


def phase_number(path, phase, key):
    """A number of one phase's sub-dictionary of mppicSeedParcelsDict."""
    text = open(path).read()
    block = text[text.index(phase, text.index("phases")):]
    block = block[:block.index("}")]
    for line in block.splitlines():
        words = line.split("//")[0].replace(";", " ").split()
        if len(words) >= 2 and words[0] == key:
            return float(words[1])
    raise KeyError("%s: no %s in phase %s" % (path, key, phase))


def from_rest(t, params):
    """Exact fronts with the parcels starting at rest (module docstring)."""
    st = exact.states(**params)
    p = st["params"]
    a = np.array([p["alpha1"], p["alpha2"]])
    eps = 1 - a.sum()
    d = np.array([p["d1"], p["d2"]])
    T = p["rho_p"]*d**2/(18*p["mu"])*eps**(p["n"] + 1)
    g_reduced = p["g"]*(1 - p["rho_f"]/p["rho_p"])
    # dv/dt = A v + b
    A = -np.diag(1/T) - np.outer(1/T, a/eps)
    b = -g_reduced*np.ones(2)
    v_inf = -np.linalg.solve(A, b)
    lam, R = np.linalg.eig(A)
    R_inv = np.linalg.inv(R)
    # displacement X(t) = v_inf t + A^-1 (e^{At} - I)(0 - v_inf)
    expm = (R @ np.diag(np.exp(lam*t)) @ R_inv).real
    X = v_inf*t + np.linalg.solve(A, (expm - np.eye(2)) @ (-v_inf))
    a_s = st["small"]["alpha2"]
    s_top = st["speeds"]["clear_top"]
    tau = p["rho_p"]*p["d2"]**2/(18*p["mu"])*(1 - a_s)**(p["n"] + 2)
    top = s_top*(t - tau*(1 - math.exp(-t/tau)))
    return dict(clear_top=p["H"] + top,
                mixture_top=p["H"] + X[0],
                sediment_top=-(a @ X)/(p["alpha_max"] - a.sum()),
                v_inf=v_inf, relaxation=-1/lam.real, states=st)


def profiles(case, time):
    """Layer heights and each phase's layer-mean solids fraction."""
    centres = post.internal_field(os.path.join(case, "0", "C"))
    volumes = np.asarray(post.internal_field(os.path.join(case, "0", "V")),
                         dtype=float)
    phases = post.phase_solids_fractions(case, time, volumes)
    if phases is None or LARGE not in phases or SMALL not in phases:
        raise SystemExit("%s/%s: no parcels of phases 1 and 2" % (case, time))
    ys, large = post.layer_means(phases[LARGE], centres)
    _, small = post.layer_means(phases[SMALL], centres)
    return np.array(ys), np.array(large), np.array(small)


def measured_fronts(ys, large, small, params, st):
    total = large + small
    return dict(
        clear_top=post.profile_crossing(ys, small, st["small"]["alpha2"]/2,
                                        from_top=True),
        mixture_top=post.profile_crossing(ys, large, params["alpha1"]/2,
                                          from_top=True),
        sediment_top=post.profile_crossing(
            ys, total, (st["params"]["alpha_max"]
                        + params["alpha1"] + params["alpha2"])/2,
            from_top=False))


def tolerance(height):
    return max(0.02*height, 0.005)


def phase_masses(case):
    """Each phase's mass at the first and last rows of phases.dat."""
    rows = post.function_object_table(case, "packingMonitor", "phases")
    first, last = {}, {}
    for row in rows:
        phase = int(row[1])
        first.setdefault(phase, row[3])
        last[phase] = row[3]
    return {k: (first[k], last[k]) for k in first}


def summary(case, time):
    params = case_parameters(case)
    ref = from_rest(float(time), params)
    ys, large, small = profiles(case, time)
    ours = measured_fronts(ys, large, small, params, ref["states"])
    monitor = post.function_object_table(case, "packingMonitor")
    return dict(params=params, ref=ref, ours=ours, ys=ys, large=large,
                small=small, masses=phase_masses(case),
                above=max(int(r[5]) for r in monitor),
                maxCell=max(r[4] for r in monitor),
                equilibrium=exact.fronts(float(time), **params))


def record_rows(results):
    """The fronts at each time of results ((time, summary) pairs), then each
    phase's mass and the bound of the last."""
    rows = []
    for time, res in results:
        rows += front_rows(res, time)
    res = results[-1][1]
    for phase, (m0, m1) in sorted(res["masses"].items()):
        rows.append(record.row(
            "phase %d mass change, relative" % phase, abs(m1/m0 - 1),
            reference=0, reference_source="mass conservation",
            goal=record.at_most(1e-12)))
    rows.append(record.row(
        "cells above close pack (most at one step)", res["above"],
        reference=0, reference_source="the capacity limit",
        goal=record.at_most(0)))
    return rows


def front_rows(res, time):
    rows = []
    for name in FRONTS:
        exact_y = res["ref"][name]
        rows.append(record.row(
            "%s at %s s [m]" % (name.replace("_", " "), time),
            res["ours"][name], reference=exact_y,
            reference_source="exact kinematic-wave solution from rest "
            "(bidisperseFronts.py, bidisperseSedimentationResults.py)",
            goal=record.within(tolerance(exact_y), absolute=True),
            note="at equilibrium slip from t = 0: %.4f m"
            % res["equilibrium"][name]))
    return rows


def plot(res, time, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 6))
    ys = res["ys"]
    ax.plot(res["large"], ys, "b.-", ms=3, label="1 mm beads (phase 1)")
    ax.plot(res["small"], ys, "r.-", ms=3, label="0.5 mm beads (phase 2)")
    ax.plot(res["large"] + res["small"], ys, "k-", lw=0.8, label="total")
    y = np.linspace(0, 1, 2001)
    a1, a2 = exact.profiles(y, float(time), **res["params"])
    ax.plot(a1, y, "b--", lw=0.8, label="exact, equilibrium start")
    ax.plot(a2, y, "r--", lw=0.8)
    for name, colour in zip(FRONTS, ("tab:red", "tab:blue", "k")):
        ax.axhline(res["ref"][name], color=colour, ls=":", lw=1)
    ax.plot([], [], "k:", lw=1, label="exact fronts from rest")
    ax.set_xlabel("solids fraction (layer mean)")
    ax.set_ylabel("height y [m]")
    ax.set_xlim(0, 0.65)
    ax.set_ylim(0, 1)
    ax.set_title("Bidisperse sedimentation, t = %s s" % time)
    ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = post.results_parser(None, __doc__.split("\n")[0])
    parser.add_argument("--time", default="2")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--plot", action="store_true")
    record.add_record_argument(parser)
    args = parser.parse_args()
    res = summary(args.case, args.time)

    ok = True
    print("front | ours [m] | exact from rest [m] | ours - exact [m] | "
          "tolerance [m] | exact at equilibrium [m]")
    for name in FRONTS:
        ours, ref = res["ours"][name], res["ref"][name]
        good = abs(ours - ref) <= tolerance(ref)
        ok = ok and good
        print("%s | %.4f | %.4f | %+.4f | %.4f | %.4f%s" % (
            name, ours, ref, ours - ref, tolerance(ref),
            res["equilibrium"][name], "" if good else "  FAILS"))
    for phase, (m0, m1) in sorted(res["masses"].items()):
        change = abs(m1/m0 - 1)
        ok = ok and change <= 1e-12
        print("phase %d mass %.12g kg -> %.12g kg, relative change %.2e"
              % (phase, m0, m1, change))
    ok = ok and res["above"] == 0
    print("cells above close pack (most at one step) %d; largest cell "
          "solids fraction %.4f" % (res["above"], res["maxCell"]))

    png = "bidisperseSedimentation_%s.png" % args.time
    if args.plot:
        plot(res, args.time, os.path.join(args.case, png))
        print("wrote " + os.path.join(args.case, png))
    if args.record:
        times = sorted(set(["1", args.time]), key=float)
        record.write(args.record, "bidisperseSedimentation",
                     record_rows([(t, res if t == args.time
                                   else summary(args.case, t))
                                  for t in times]),
                     plots=[png] if args.plot else [],
                     settings=record.case_settings(args.case))
    if args.check and not ok:
        print("bidisperseSedimentationResults: check failed", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
