#!/usr/bin/python3
"""Mixing layer of a run of the rayleighTaylor case.

Reads the gas fraction written every 0.02 s (function object alphaHistory,
<time>/alpha.air) and the cell centres (0/C), averages the solids fraction
1 - alpha.air over each horizontal row of cells, and finds, with the initial
interface at y0 = 0.3 m and the mixture's solids fraction eps0 = 0.2:
    spike front  y_s: the lowest row whose mean is above 0.05 eps0 (the
                      mixture fallen furthest into the clear gas);
    bubble front y_b: the first row above y_s whose mean reaches 0.95 eps0
                      (clear gas risen furthest into the mixture);
    h = (y_b - y_s)/2, the half-width of the mixing layer.
The whole mixture also settles through the gas (its particles' settling
velocity, g tau (1 - rho_g/rho_p) for tau = 1/100 s: 0.065 m/s at
rho_p 3), and at its top a clear layer opens under the outlet: the
half-width does not depend on that drift, the fronts' distances from y0
(also printed) do.
The Atwood number of the mixture set up (docs/VALIDATION.md,
"Conventions"), with the gas density rho_g and the particle density rho_p
of the case:
    rho_mix = (1 - eps0) rho_g + eps0 rho_p,  A = (rho_mix - rho_g)/(rho_mix + rho_g)
alpha is fitted to h = alpha A g t^2 by least squares through the origin
over the self-similar range: from the first time h exceeds 4 cells
(0.01 m; the seeding noise is about one cell) until the spike front comes
within 0.05 m of the bottom.

Usage:
    rayleighTaylorResults.py [--case DIR] [--label L] [--plot] [--row]
        [--tableHead] [--record FILE]
--plot writes rayleighTaylor_<label>.png (without --label:
rayleighTaylor_rho<particle density>.png). --record FILE writes the
validation matrix's record of the run (tutorials/lib/validationRecord.py,
case rayleighTaylor-<particle density>): alpha against the band 0.05-0.07
and the Atwood number.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import validationRecord as record  # noqa: E402 (tutorials/lib)

Y0 = 0.3
EPS0 = 0.2
G = post.G
HEIGHT = 0.6
TABLE_HEAD = ("| run | particle density | A | fit range [s] | alpha "
              "| in [0.05, 0.07] |\n|---|---|---|---|---|---|")


def atwood(case):
    rho_p = post.dict_number(os.path.join(case, "constant", "kinematicCloudProperties"), "rho0")
    rho_g = post.dict_number(os.path.join(case, "constant", "transportProperties"), "rho.air")
    rho_mix = (1 - EPS0)*rho_g + EPS0*rho_p
    return rho_p, (rho_mix - rho_g)/(rho_mix + rho_g)


def rows(case):
    """Row heights and, per written time, the row means of eps_s."""
    centres = post.internal_field(os.path.join(case, "0", "C"))
    times = sorted((d for d in os.listdir(case)
                    if re.match(r"^[0-9.]+$", d)
                    and os.path.exists(os.path.join(case, d, "alpha.air"))
                    and float(d) > 0), key=float)
    keys, history = None, []
    for t in times:
        alpha = post.internal_field(os.path.join(case, t, "alpha.air"))
        keys, means = post.layer_means([1 - a for a in alpha], centres,
                                       digits=6)
        history.append((float(t), means))
    if keys is None:
        keys = sorted({round(c[1], 6) for c in centres})
    return keys, history


def fronts(ys, profile):
    """Spike front y_s (lowest row above 0.05 eps0) and bubble front y_b
    (the first row above y_s whose mean reaches 0.95 eps0)."""
    y_s = next((y for y, e in zip(ys, profile) if e > 0.05*EPS0), Y0)
    y_b = next((y for y, e in zip(ys, profile) if y > y_s and e >= 0.95*EPS0),
               y_s)
    return y_b, y_s


def summary(case):
    rho_p, A = atwood(case)
    ys, history = rows(case)
    cell = ys[1] - ys[0]
    series = []
    for t, profile in history:
        y_b, y_s = fronts(ys, profile)
        series.append((t, 0.5*(y_b - y_s), y_b - Y0, Y0 - y_s))
    usable = []
    for t, h, hb, hs in series:
        if Y0 - hs < 0.05:
            break
        if h >= 4*cell:
            usable.append((t, h))
    res = {"rho_p": rho_p, "A": A, "series": series, "cell": cell}
    if len(usable) >= 3:
        res["range"] = (usable[0][0], usable[-1][0])
        res["alpha"] = post.fit_through_origin([(A*G*t*t, h) for t, h in usable])
    return res


def plot(res, case, label):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    A = res["A"]
    xs = [A*G*t*t for t, _, _, _ in res["series"]]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(xs, [h for _, h, _, _ in res["series"]], "o-", ms=3,
            label="half-width h = (y_b - y_s)/2")
    ax.plot(xs, [hb for _, _, hb, _ in res["series"]], "^", ms=2, color="0.6",
            label="y_b - y0 (bubbles)")
    ax.plot(xs, [hs for _, _, _, hs in res["series"]], "v", ms=2, color="0.4",
            label="y0 - y_s (spikes)")
    top = max(xs) if xs else 1
    for a, style in ((0.05, "--"), (0.07, ":")):
        ax.plot([0, top], [0, a*top], "k" + style, lw=1, label="alpha = %.2f" % a)
    if "range" in res:
        t0, t1 = res["range"]
        ax.axvspan(A*G*t0*t0, A*G*t1*t1, color="0.9", zorder=0,
                   label="fit: alpha %.3f" % res["alpha"])
    ax.set_xlabel("A g t^2 [m]")
    ax.set_ylabel("mixing layer [m]")
    ax.set_ylim(0, 0.3)
    ax.set_title("Rayleigh-Taylor, rho_p %g kg/m3, A = %.4f (%s)"
                 % (res["rho_p"], A, label), fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(case, "rayleighTaylor_%s.png" % label)
    fig.savefig(path, dpi=100)
    print("  wrote " + path)


def record_rows(res):
    """The record's rows: alpha against the literature's band, and the
    Atwood number."""
    fit = ("fit over %g-%g s" % res["range"] if "range" in res
           else "no self-similar range (h >= 4 cells before the spike front "
           "nears the bottom)")
    return [
        record.row("growth coefficient alpha of h = alpha A g t^2",
                   res.get("alpha"),
                   reference_source="Youngs; Snider & Andrews (seed 2 §3.1)",
                   goal=record.between(0.05, 0.07),
                   note="%s; no single reference value, the literature's "
                   "band is the goal; seed 2 Fig. 8 draws alpha = 0.07 beside "
                   "MFiX-PIC, which gives no number" % fit),
        record.row("Atwood number A of the mixture", res["A"],
                   note="informational: (rho_mix - rho_g)/(rho_mix + rho_g), "
                   "rho_mix = %g rho_g + %g rho_p, rho_p %g kg/m3"
                   % (1 - EPS0, EPS0, res["rho_p"]))]


def main():
    parser = post.results_parser("run", __doc__.split("\n")[0])
    parser.add_argument("--plot", action="store_true")
    record.add_record_argument(parser)
    args = post.parse_results_args(parser, TABLE_HEAD)
    res = summary(args.case)
    if args.row:
        if "range" in res:
            ok = 0.05 <= res["alpha"] <= 0.07
            print("| %s | %g | %.4f | %g-%g | %.4f | %s |"
                  % (args.label, res["rho_p"], res["A"], res["range"][0],
                     res["range"][1], res["alpha"], "yes" if ok else "no"))
        else:
            print("| %s | %g | %.4f | - | - | no |"
                  % (args.label, res["rho_p"], res["A"]))
    else:
        print("%s: particle density %g kg/m3, Atwood number %.4f, cell %.4f m"
              % (args.label, res["rho_p"], res["A"], res["cell"]))
        for t, h, hb, hs in res["series"]:
            print("  t %.2f s  A g t^2 %.4f m  h %.4f m  (y_b - y0 %.4f, y0 - y_s %.4f)"
                  % (t, res["A"]*G*t*t, h, hb, hs))
        if "range" in res:
            print("  fit %g-%g s: alpha %.4f" % (res["range"][0], res["range"][1],
                                                res["alpha"]))
        else:
            print("  no self-similar range yet")
    label = args.label
    if label == parser.get_default("label"):
        label = "rho%g" % res["rho_p"]
    if args.plot:
        plot(res, args.case, label)
    if args.record:
        # the seeded box spans the mesh's depth (Allrun)
        seeds = post.read_text(os.path.join(args.case, "system",
                                            "mppicSeedParcelsDict"))
        depth = float(re.search(r"^box\s.*\(\s*\S+\s+\S+\s+(\S+)\s*\);",
                                seeds, re.M).group(1))
        record.write(
            args.record, "rayleighTaylor-%g" % res["rho_p"], record_rows(res),
            plots=["rayleighTaylor_%s.png" % label] if args.plot else [],
            settings="%s; particle density %g kg/m3, cells %g m, %s" % (
                record.case_settings(args.case), res["rho_p"], res["cell"],
                "a slice one cell deep" if abs(depth - res["cell"]) < 1e-9
                else "depth %g m" % depth),
            window="fit %g-%g s" % res["range"] if "range" in res else "")
    return 0


if __name__ == "__main__":
    sys.exit(main())
