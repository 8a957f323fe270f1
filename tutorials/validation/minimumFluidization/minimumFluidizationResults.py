#!/usr/bin/python3
"""Fluidization curve of a run of the minimumFluidization case.

Reads postProcessing/bedPressureDrop/0/bedPressureDrop.dat (every step),
the inlet ramp (0/U.air: rampTime, rampVelocity; U = rampVelocity*t/rampTime)
and the bed (constant/kinematicCloudProperties: rho0, closePackFraction,
particle diameter, switchFraction; constant/transportProperties: rho.air,
nu). Prints and plots:

    dP* = (deltaP - gas head)/(m g/A)  against U           (seed 2, eq 12)

smoothed over 0.05 m/s of U (the bubbling bed's fluctuations), and the
seed's construction of Umf: a straight line fitted to the fixed-bed branch
(dP* < 0.8 of the plateau), a straight line for the plateau (U above
1.5 Umf; horizontal, the mean there), Umf where they cross (iterated
from the first U with dP* >= 0.95); and where the curve first falls 3 %
below the fixed-bed line, the velocity at which the bed unlocks.
Against:
  - Ergun for the bed's voidage eps = 1 - closePackFraction:
      dP*_Ergun = [150 mu (1-eps)^2 U/(eps^3 d^2) + 1.75 rho_g (1-eps) U^2/
                   (eps^3 d)] / (rho_p (1-eps) g)
    and the fixed-bed error: the mean of |dP*/dP*_Ergun - 1| over
    0.3-0.8 Umf;
  - Wen-Yu for the same bed (seed 2 eqs 13-14, what -drag wenYu uses);
  - the measured Umf 0.182 m/s and the plateau 1.

Usage:
    minimumFluidizationResults.py [--case DIR] [--label L] [--plot]
        [--row] [--tableHead] [--record FILE]
        --record FILE: the validation matrix's record of the run
        (tutorials/lib/validationRecord.py; rows in
        minimumFluidizationRecord.py)
    minimumFluidizationResults.py --overlay CASE:LABEL ... [--out PNG]
        [--title T]   (several runs on one plot: the sensitivity plots)
    minimumFluidizationResults.py --split T0 T1 [--case DIR]
        where the bed's weight goes over [T0, T1] s: the gas (the mean dP*),
        the packing step's mean upward force over m g (packingMonitor) and
        the rest of the cloud's vertical momentum budget, the walls' and the
        distributor's (mppicPost.packing_force, weight_rest)
"""
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import validationRecord as record  # noqa: E402 (tutorials/lib)
import minimumFluidizationRecord  # noqa: E402 (beside this script)

MEASURED_UMF = 0.182
G = post.G
TABLE_HEAD = ("| run | Umf, fits [m/s] | vs 0.182 | bed unlocks at [m/s] "
              "| plateau dP* | fixed bed vs Ergun | Ergun Umf [m/s] |\n"
              "|---|---|---|---|---|---|---|")


def particle_diameter(case):
    text = open(os.path.join(case, "constant", "kinematicCloudProperties")).read()
    return float(re.search(r"value\s+([0-9.eE+-]+)\s*;", text).group(1))


def bed(case):
    cloud = os.path.join(case, "constant", "kinematicCloudProperties")
    transport = os.path.join(case, "constant", "transportProperties")
    rho_g = post.dict_number(transport, "rho.air")
    close_pack = post.dict_number(cloud, "closePackFraction")
    # Ergun's voidage is the bed's: the seeded solids fraction (Allrun
    # -seedFraction; the close pack unless set)
    seeds = os.path.join(case, "system", "mppicSeedParcelsDict")
    seeded = (post.dict_number(seeds, "solidsFraction")
              if os.path.exists(seeds) else None)
    return {
        "rho_p": post.dict_number(cloud, "rho0"),
        "alpha": seeded if seeded is not None else close_pack,
        "closePack": close_pack,
        "switch": post.dict_number(cloud, "switchFraction"),
        "d": particle_diameter(case),
        "rho_g": rho_g,
        "mu": rho_g*post.dict_number(transport, "nu"),
        "rampTime": post.dict_number(os.path.join(case, "0", "U.air"), "rampTime"),
        "rampVelocity": post.dict_number(os.path.join(case, "0", "U.air"), "rampVelocity"),
    }


def ergun_star(b, U):
    eps = 1 - b["alpha"]
    grad = (150*b["mu"]*b["alpha"]**2*U/(eps**3*b["d"]**2)
            + 1.75*b["rho_g"]*b["alpha"]*U**2/(eps**3*b["d"]))
    return grad/(b["rho_p"]*b["alpha"]*G)


def wen_yu_star(b, U):
    """Wen-Yu on a fixed bed, in the form of Ergun's (two-fluid momentum
    with eps grad p): grad p = beta*slip/eps, slip = U/eps, Re = eps rho
    slip d/mu = rho U d/mu, beta = 3/4 Cd rho eps (1-eps) slip/d eps^-2.65."""
    eps = 1 - b["alpha"]
    Re = b["rho_g"]*U*b["d"]/b["mu"]
    cd_re = 0.44*Re if Re >= 1000 else 24*(1 + 0.15*Re**0.687)
    beta = 0.75*cd_re*b["mu"]/b["d"]**2*eps**-2.65*b["alpha"]
    return beta*(U/eps)/eps/(b["rho_p"]*b["alpha"]*G)


def crossing(f, target, lo=1e-4, hi=5.0):
    """U where f(U) = target (f increasing), by bisection."""
    for _ in range(100):
        mid = 0.5*(lo + hi)
        lo, hi = (mid, hi) if f(mid) < target else (lo, mid)
    return 0.5*(lo + hi)


def curve(case, b):
    path = os.path.join(case, "postProcessing", "bedPressureDrop", "0",
                        "bedPressureDrop.dat")
    points = []
    for row in post.read_table(path):
        t, _, _, dp, head, weight = row[:6]
        U = b["rampVelocity"]*min(t, b["rampTime"])/b["rampTime"]
        points.append((U, (dp - head)/weight))
    return points


def smooth(points, width=0.05):
    """Running mean over a window of U of the given width."""
    out = []
    j0 = 0
    total = 0.0
    window = []
    for U, p in points:
        window.append((U, p))
        total += p
        while window[0][0] < U - width:
            total -= window.pop(0)[1]
        out.append((U - 0.5*width, total/len(window)))
    return [(U, p) for U, p in out if U > 0]


def construct_umf(points):
    """The seed's construction: the fixed-bed line crosses the plateau, a
    horizontal line at the mean dP* above 1.5 Umf; also where the curve
    leaves the fixed-bed line (3 % below it): where the bed unlocks."""
    first = next((U for U, p in points if p >= 0.95), None)
    if first is None:
        return None
    umf = first
    for _ in range(5):
        plateau_pts = [p for U, p in points if U >= 1.5*umf]
        if len(plateau_pts) < 3:
            return None
        plateau = sum(plateau_pts)/len(plateau_pts)
        fixed_pts = [(U, p) for U, p in points
                     if 0.1*umf <= U and p < 0.8*plateau and U < umf]
        if len(fixed_pts) < 3:
            return None
        fs, fi = post.fit_line(fixed_pts)
        umf = (plateau - fi)/fs
    departure = next((U for U, p in points
                      if U > 0.5*umf and p < 0.97*(fi + fs*U)), None)
    return {"umf": umf, "plateau": plateau, "fixed": (fs, fi),
            "departure": departure}


def summary(case):
    b = bed(case)
    raw = curve(case, b)
    points = smooth(raw)
    res = {"bed": b, "raw": raw, "points": points,
           "ergunUmf": crossing(lambda U: ergun_star(b, U), 1.0),
           "wenYuUmf": crossing(lambda U: wen_yu_star(b, U), 1.0)}
    fit = construct_umf(points)
    if fit:
        res.update(fit)
        branch = [(U, p) for U, p in points
                  if 0.3*fit["umf"] <= U <= 0.8*fit["umf"]]
        if branch:
            res["fixedError"] = sum(abs(p/ergun_star(b, U) - 1)
                                    for U, p in branch)/len(branch)
    return res


def report(res, label):
    b = res["bed"]
    print("%s: ramp 0-%g m/s over %g s, close pack %g, bed seeded at %g "
          "(voidage %g), drag %s"
          % (label, b["rampVelocity"], b["rampTime"], b["closePack"], b["alpha"],
             1 - b["alpha"], "Wen-Yu" if b["switch"] < 0.1 else "Ergun/Wen-Yu"))
    print("  Umf of Ergun for this voidage %.4f m/s, of Wen-Yu %.4f m/s"
          % (res["ergunUmf"], res["wenYuUmf"]))
    if "umf" not in res:
        print("  no transition found")
        return
    print("  Umf (fits crossing) %.4f m/s: %+.1f %% from NETL's 0.182 (HDPE)"
          % (res["umf"], 100*(res["umf"]/MEASURED_UMF - 1)))
    print("  plateau dP* %.4f" % res["plateau"])
    if res.get("departure"):
        print("  the curve leaves the fixed-bed line (3 %% below it) at %.4f m/s: "
              "%+.1f %% from 0.182" % (res["departure"],
                                      100*(res["departure"]/MEASURED_UMF - 1)))
    if "fixedError" in res:
        print("  fixed-bed branch vs Ergun (0.3-0.8 Umf): mean |error| %.1f %%"
              % (100*res["fixedError"]))


def plot(res, case, label):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    b = res["bed"]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot([U for U, _ in res["raw"]], [p for _, p in res["raw"]], lw=0.3,
            color="0.7", label="every step")
    ax.plot([U for U, _ in res["points"]], [p for _, p in res["points"]],
            lw=1.5, color="tab:blue", label="ours, mean over 0.05 m/s")
    Us = [0.005*i for i in range(1, int(b["rampVelocity"]/0.005) + 1)]
    ax.plot(Us, [ergun_star(b, U) for U in Us], "k--", lw=1,
            label="Ergun, voidage %.2f" % (1 - b["alpha"]))
    ax.plot(Us, [wen_yu_star(b, U) for U in Us], ":", color="tab:green", lw=1.2,
            label="Wen-Yu, fixed bed")
    ax.axhline(1, color="k", lw=0.8)
    ax.axvline(MEASURED_UMF, color="tab:red", lw=0.8, ls="-.",
               label="measured Umf 0.182 m/s")
    if "umf" in res:
        fs, fi = res["fixed"]
        ax.plot([0, res["umf"]*1.2], [fi, fi + fs*res["umf"]*1.2], color="tab:orange",
                lw=1, label="fits, Umf %.3f m/s" % res["umf"])
        ax.plot([res["umf"]*0.8, b["rampVelocity"]], [res["plateau"]]*2,
                color="tab:orange", lw=1)
        if res.get("departure"):
            ax.axvline(res["departure"], color="tab:purple", lw=0.8, ls=":",
                       label="bed unlocks, %.3f m/s" % res["departure"])
    ax.set_xlim(0, b["rampVelocity"])
    ax.set_ylim(0, 1.6)
    ax.set_xlabel("inlet (superficial) gas velocity U [m/s]")
    ax.set_ylabel("dP* = deltaP/(m g/A)")
    ax.set_title("minimum fluidization, %s" % label)
    ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    path = os.path.join(case, "minimumFluidization_%s.png" % label)
    fig.savefig(path, dpi=100)
    print("  wrote " + path)


def plot_overlay(runs, path, title):
    """The smoothed curves of several runs (case, label) on one plot, with
    the Ergun line of the first run's bed: the sensitivity plots."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    top = 0
    for case, label in runs:
        res = summary(case)
        b = res["bed"]
        top = max(top, b["rampVelocity"])
        text = label
        if "umf" in res:
            text += ": Umf %.3f, plateau %.2f" % (res["umf"], res["plateau"])
        ax.plot([U for U, _ in res["points"]], [p for _, p in res["points"]],
                lw=1.3, label=text)
    b = summary(runs[0][0])["bed"]
    Us = [0.005*i for i in range(1, int(top/0.005) + 1)]
    ax.plot(Us, [ergun_star(b, U) for U in Us], "k--", lw=1,
            label="Ergun, voidage %.2f" % (1 - b["alpha"]))
    ax.axhline(1, color="k", lw=0.8)
    ax.axvline(MEASURED_UMF, color="tab:red", lw=0.8, ls="-.",
               label="measured Umf 0.182 m/s")
    ax.set_xlim(0, top)
    ax.set_ylim(0, 1.6)
    ax.set_xlabel("inlet (superficial) gas velocity U [m/s]")
    ax.set_ylabel("dP* = deltaP/(m g/A), mean over 0.05 m/s")
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    print("  wrote " + path)


def weight_split(case, t0, t1):
    """(gas, packing step, walls) shares of the weight over [t0, t1] s."""
    rows = [r for r in post.function_object_table(case, "bedPressureDrop")
            if t0 - 1e-9 <= r[0] <= t1 + 1e-9]
    monitor = post.function_object_table(case, "packingMonitor")
    window = [r for r in monitor if t0 - 1e-9 <= r[0] <= t1 + 1e-9]
    if not rows or len(window) < 2:
        return None
    mass = monitor[0][post.MONITOR_MASS]
    gas = sum((r[3] - r[4])/r[5] for r in rows)/len(rows)
    packing = post.packing_force(window, mass, G)
    walls = post.weight_rest(case, t0, t1, gas + packing, mass, G)
    return gas, packing, walls


def main():
    parser = post.results_parser("run", __doc__.split("\n")[0])
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--overlay", nargs="+", metavar="CASE:LABEL",
                        help="plot these runs' curves on one plot (--out)")
    parser.add_argument("--out", default="minimumFluidization_overlay.png")
    parser.add_argument("--title", default="minimum fluidization")
    parser.add_argument("--split", nargs=2, type=float, metavar=("T0", "T1"))
    record.add_record_argument(parser)
    args = parser.parse_args()
    if args.split:
        split = weight_split(args.case, *args.split)
        if split is None:
            print("no bedPressureDrop or packingMonitor rows in %g-%g s"
                  % tuple(args.split))
            return 1
        gas, packing, walls = split
        print("%g-%g s: the gas (dP*) %.3f, the packing step %.3f, the walls "
              "and distributor %s of the weight"
              % (args.split[0], args.split[1], gas, packing,
                 "%.3f" % walls if walls is not None else "- (no two written clouds)"))
        return 0
    if args.overlay:
        runs = [tuple(item.split(":", 1)) for item in args.overlay]
        plot_overlay(runs, args.out, args.title)
        return 0
    if args.tableHead:
        print(TABLE_HEAD)
        return 0
    res = summary(args.case)
    if args.row:
        if "umf" in res:
            print("| %s | %.4f | %+.1f %% | %s | %.4f | %.1f %% | %.4f |"
                  % (args.label, res["umf"], 100*(res["umf"]/MEASURED_UMF - 1),
                     "%.4f" % res["departure"] if res.get("departure") else "-",
                     res["plateau"], 100*res.get("fixedError", float("nan")),
                     res["ergunUmf"]))
        else:
            print("| %s | - | - | - | - | - | %.4f |" % (args.label, res["ergunUmf"]))
    else:
        report(res, args.label)
    if args.plot:
        plot(res, args.case, args.label)
    if args.record:
        record.write(args.record, "minimumFluidization",
                     minimumFluidizationRecord.rows(res, MEASURED_UMF),
                     plots=["minimumFluidization_%s.png" % args.label]
                     if args.plot else [],
                     settings=minimumFluidizationRecord.settings(args.case,
                                                                 res))
    return 0


if __name__ == "__main__":
    sys.exit(main())
