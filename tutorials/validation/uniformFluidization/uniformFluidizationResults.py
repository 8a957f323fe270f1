#!/usr/bin/python3
"""Uniformly fluidized bed: does the gas carry the bed's weight?

Reads the function objects' output of a run of this case (or of a copy):
    postProcessing/bedPressureDrop/0/bedPressureDrop.dat  every step
    postProcessing/packingMonitor/0/packingMonitor.dat    every step
and prints, over t0 <= t <= end (default t0: 0.4 x end, after the start-up):
    - the time-mean bed pressure drop less the gas head, over the bed's
      weight per area (W/A = m_cloud g / A); 1 = the gas carries the weight
      (the buoyancy, rho_g/rho_p = 4.8e-4 of it, is left in);
    - its standard deviation and the standard error of the mean from the
      autocorrelation of the series (blocks of 0.25 s);
    - the largest cell solids fraction over the window (packingMonitor),
      and the largest of the field the model reads (the averaging's: the
      linear hat's with -packing mfixSnider) at every step of the run;
    - the mean upward force of the packing step over the weight,
      sum(m dU_y)/dt/(m g) (packingMonitor): where the weight goes that the
      gas does not carry (every cell of this 2-cell-deep box touches a
      wall, so the monitor's wall part is all of it and is not shown);
    - the rest, from the cloud's momentum budget with its vertical
      momentum at the written times nearest the window's ends: the walls'
      rebounds (the distributor's: the side walls are frictionless) and,
      without PIMPLE balanceImplicitDrag, the drag the parcels got beyond
      the gas's pressure drop (0.079 of the weight at 3 parcels per packed
      cell with no parcel at the distributor; docs/VALIDATION.md);
    - how much the bed moves: the median distance the parcels travelled
      between the last two written times, per second (parcels matched by
      origId). A bubbling bed stirs its parcels by centimetres per second;
      a bed that does not bubble (a static, layered packing) by a few
      millimetres;
    - the bubbles (uniformFluidizationBubbles.py) where the run sampled
      them (postProcessing/bubbleSlices): void cells, bubble fraction
      against two-phase theory, bubble sizes and rise velocities, the bed
      height and its fluctuation, the pressure signal's fluctuation and
      dominant frequency;
    - with --rows, per row of cells over the window's written times: the
      mean solids fraction, the share of cells at close pack, the packing
      step's force on the row over the bed's weight (the packingForce field
      that packingMonitor writes, sum f_y V/(m g)) and the gas velocity
      U.air_y; the cell centres and volumes are written by the Allrun.

Usage:
    uniformFluidizationResults.py [--case DIR] [--from T0] [--label L]
        [--row [--wallTime S] [--failure TEXT]] [--tableHead] [--rows]
        [--plot] [--record FILE]
    --row   one markdown table row (TABLE_HEAD; bin/compareSolvers)
    --plot  uniformFluidization_<label>_pressureDrop.png: deltaP/weight(t);
            with --rows also uniformFluidization_<label>_rows.png; with
            the bubble samples also _bubbles.png and _snapshots.png
    --record FILE  the validation matrix's record (tutorials/lib/
            validationRecord.py) of case uniformBed-<N>, N the parcels per
            packed cell of system/mppicSeedParcelsDict: deltaP/weight
            against 1.00 +- 0.02 (MFiX-PIC's 1.075 beside it), its standard
            error, the largest cell solids fraction against max(1.03
            alpha_cp, alpha_cp + one parcel); with the default --label the
            plots are named by the count (label perCell<N>)
    uniformFluidizationResults.py --largest DIR:LABEL [DIR:LABEL ...]
        uniformFluidization_largestSolidsFraction.png: the largest
        solids fraction of the model's field at every step of each run,
        against the bound 1.15 x 0.6 = 0.69
"""
import collections
import math
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import validationRecord as record  # noqa: E402 (tutorials/lib)
import uniformFluidizationBubbles as bubbles  # noqa: E402 (beside this file)

# MFiX-PIC 21.3.2 on this bed, mean deltaP/weight over 1-4 s: the project's
# shared reference/mfix_pic_uniform_bed.csv, deltaP_over_weight_mean (no copy
# of it in this folder)
MFIX_PIC_RATIO = 1.075

TABLE_HEAD = ("| run | window [s] | deltaP / weight | std | std error of mean "
              "| packing force / weight | max cell eps_s | wall s / sim s "
              "| failed |\n|---|---|---|---|---|---|---|---|---|")


def pressure_ratio(case):
    """(t, (deltaP - gas head)/(W/A)) for every step."""
    rows = post.function_object_table(case, "bedPressureDrop")
    # columns: time pLower pUpper deltaP gasHead weightPerArea ratio
    return [(r[0], (r[3] - r[4])/r[5]) for r in rows]


def monitor(case):
    """packingMonitor rows: time, parcels, mass, max averaged, max cell..."""
    return post.function_object_table(case, "packingMonitor")


def median_travel(case):
    """(t_a, t_b, median |X(t_b) - X(t_a)|/(t_b - t_a) in m/s) of the
    parcels, matched by origId, between the last two written times; None
    without two."""
    times = sorted((d for d in os.listdir(case) if re.match(r"^[0-9.]+$", d)
                    and os.path.isdir(os.path.join(case, d, "lagrangian"))),
                   key=float)
    if len(times) < 2:
        return None
    where = []
    for t in times[-2:]:
        d = os.path.join(case, t, "lagrangian", "kinematicCloud")
        ids = [int(v[0])
               for v in post.lagrangian_field(os.path.join(d, "origId"))]
        pos = post.lagrangian_field(os.path.join(d, "positions"))
        where.append(dict(zip(ids, pos)))
    a, b = where
    dist = sorted(math.dist(a[i][:3], b[i][:3]) for i in a if i in b)
    if not dist:
        return None
    ta, tb = float(times[-2]), float(times[-1])
    return ta, tb, dist[len(dist)//2]/(tb - ta)


def rows(case, t0, t1, close_pack=0.6):
    """Per row of cells, from the bottom, over the written times t0 < t <=
    t1 that hold packingForce: (height, solids fraction, share of cells at
    close pack, packing force/(m g), U.air_y); None without such times."""
    force, count = post.time_mean_field(case, "packingForce", t0, t1, component=1)
    if not count:
        return None
    zero = os.path.join(case, "0")
    centres = post.internal_field(os.path.join(zero, "C"))
    volumes = np.asarray(post.internal_field(os.path.join(zero, "V")), float)
    weight = monitor(case)[-1][2]*9.81

    def layers(values):
        """Row means of a cell field (a uniform value spread to the cells)."""
        return post.layer_means(np.broadcast_to(values, volumes.shape), centres)

    def mean(name, **kwargs):
        return post.time_mean_field(case, name, t0, t1, **kwargs)[0]

    heights, solids = layers(mean("alpha.kinematicCloud"))
    full = layers(mean("alpha.kinematicCloud",
                       transform=lambda alpha: alpha >= close_pack - 1e-6))[1]
    # the force summed over the row: its row mean times the row's cells
    cells = collections.Counter(round(c[1], 9) for c in centres)
    pushed = layers(force*volumes/weight)[1]
    gas = layers(mean("U.air", component=1))[1]
    return [(h, solids[i], full[i], pushed[i]*cells[h], gas[i])
            for i, h in enumerate(heights)]


def bed_rows(profile):
    """The profile's rows up to one above the last with solids."""
    return profile[:max(i for i, r in enumerate(profile) if r[1] > 0.01) + 2]


def summary(case, t0=None):
    everything = pressure_ratio(case)
    if t0 is None:
        t0 = 0.4*everything[-1][0]
    series = [(t, r) for t, r in everything if t >= t0 - 1e-12]
    if not series:
        raise SystemExit("no bedPressureDrop samples after %g s in %s" % (t0, case))
    mean, std, error = post.mean_and_error(series, 0.25)
    rows = [r for r in monitor(case) if r[0] >= t0 - 1e-12]
    max_cell = max(r[4] for r in rows) if rows else float("nan")
    max_field = max(r[3] for r in monitor(case))
    packing = post.packing_force(rows)
    # The packs' reactions handed to the gas push it as the drag's
    # reaction does: deltaP = drag - to_gas, so the drag on the parcels is
    # the pressure drop's share plus to_gas
    to_gas = post.gas_packing_force(rows)
    walls = post.weight_rest(case, t0, series[-1][0],
                             mean + to_gas + packing,
                             rows[-1][2]) if rows else None
    return {"t0": t0, "t1": series[-1][0], "ratio": mean, "std": std,
            "error": error, "maxCell": max_cell, "packing": packing,
            "toGas": to_gas,
            "walls": walls, "series": everything, "maxField": max_field,
            "travel": median_travel(case)}


def plot(res, case, label):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ts = [t for t, _ in res["series"]]
    rs = [r for _, r in res["series"]]
    fig, ax = plt.subplots(figsize=(8, 3.6))
    ax.plot(ts, rs, lw=0.5, color="tab:blue", label="(deltaP - gas head)/weight")
    ax.axhline(1, color="k", lw=0.8, label="bed weight")
    ax.axhline(res["ratio"], color="tab:red", lw=1.2, ls="--",
               label="mean %.3f over %g-%g s" % (res["ratio"], res["t0"], res["t1"]))
    ax.axvspan(res["t0"], res["t1"], color="0.9", zorder=0)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("deltaP / (W/A)")
    ax.set_ylim(0, 2.5)
    ax.set_title("uniform fluidization, 0.5 m/s, %s" % label)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    path = os.path.join(case, "uniformFluidization_%s_pressureDrop.png" % label)
    fig.savefig(path, dpi=100)
    print("wrote", path)


def plot_rows(profile, case, label, window):
    """Solids fraction, share of full cells and the packing force per row
    against height."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    bed = bed_rows(profile)
    y = [1e3*r[0] for r in bed]
    fig, (left, right) = plt.subplots(1, 2, figsize=(8, 4.2), sharey=True)
    left.plot([r[1] for r in bed], y, "o-", ms=3, label="solids fraction")
    left.plot([r[2] for r in bed], y, "s-", ms=3,
              label="share of cells at close pack")
    left.set_xlim(0, 1.05)
    left.set_xlabel("row mean")
    left.set_ylabel("height of the row [mm]")
    left.legend(fontsize=8, loc="upper right")
    right.barh(y, [r[3] for r in bed], height=4, color="tab:red")
    right.axvline(0, color="k", lw=0.8)
    right.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(4))
    right.set_xlabel("packing force on the row / bed weight (up +)")
    right.set_title("sum %+.4f" % sum(r[3] for r in profile), fontsize=9)
    fig.suptitle("uniform fluidization, %s: rows over %g-%g s" % ((label,) + window),
                 fontsize=10)
    fig.tight_layout()
    path = os.path.join(case, "uniformFluidization_%s_rows.png" % label)
    fig.savefig(path, dpi=100)
    print("wrote", path)


def plot_largest(runs, bound=0.69):
    """The largest solids fraction of the model's field against time, one
    line per run (DIR:LABEL), with the bound."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 3.6))
    for run in runs:
        case, _, label = run.partition(":")
        rows = monitor(case)
        ax.plot([r[0] for r in rows], [r[3] for r in rows], lw=0.6,
                label="%s (max %.3f)" % (label or case, max(r[3] for r in rows)))
    ax.axhline(bound, color="k", lw=1, ls="--",
               label="bound 1.15 x 0.6 = %.2f" % bound)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("largest solids fraction")
    ax.set_ylim(0.4, 0.9)
    ax.set_title("uniform fluidization, mfixSnider: the model's field (linear hat)")
    ax.legend(fontsize=8, loc="lower center", ncol=2)
    fig.tight_layout()
    path = "uniformFluidization_largestSolidsFraction.png"
    fig.savefig(path, dpi=100)
    print("wrote", path)


def run_settings(case):
    """What the run used, from its files: (packing model, close pack, parcels
    per packed cell, one parcel's share of a cell, the settings' text)."""
    cloud = os.path.join(case, "constant", "kinematicCloudProperties")
    seeds = os.path.join(case, "system", "mppicSeedParcelsDict")
    model = post.dict_entry(cloud, "packingModel")
    found = re.search(r"\b(?:closePackFraction|alphaPacked)\s+([-0-9.eE+]+)",
                      record.coeffs_text(cloud, model + "Coeffs"))
    close_pack = float(found.group(1)) if found else float("nan")
    per_cell = int(post.dict_number(seeds, "parcelsPerCell"))
    # arrangement cell: parcelsPerCell equal parcels in each (equal) cell at
    # solidsFraction, so one parcel is solidsFraction/parcelsPerCell of a cell
    parcel = post.dict_number(seeds, "solidsFraction")/per_cell
    text = "%s; seeding jitter %s" % (record.case_settings(case),
                                      post.dict_entry(seeds, "jitter"))
    return model, close_pack, per_cell, parcel, text


def write_record(path, res, case, plots, extra=()):
    """The validation matrix's record of the run (validationRecord), with
    the extra rows (the bubbles')."""
    _, close_pack, per_cell, parcel, settings = run_settings(case)
    bound = max(1.03*close_pack, close_pack + parcel)
    rows = [
        record.row("(deltaP - gas head)/weight", res["ratio"], reference=1.0,
                   reference_source="the bed's weight (the gas carries it)",
                   peer=MFIX_PIC_RATIO, goal=record.within(0.02, absolute=True),
                   note="MFiX-PIC 21.3.2 on this bed over 1-4 s "
                   "(reference/mfix_pic_uniform_bed.csv); std %.3f"
                   % res["std"]),
        record.row("standard error of the mean deltaP/weight",
                   res["error"] if math.isfinite(res["error"]) else None,
                   note="from the means of 0.25 s blocks (none: a window of "
                   "fewer than two blocks)"),
        record.row("packing step's upward force/weight", res["packing"],
                   note="what the packing rules carry; with the next row and "
                   "the cloud's momentum change, the weight's share the gas "
                   "pressure drop does not carry"),
        record.row("rest of the momentum budget/weight", res["walls"],
                   note="the distributor's rebounds and the drag the parcels "
                   "got that the gas never gave (semi-implicit coupling, "
                   "README)"),
        record.row("largest cell solids fraction", res["maxCell"],
                   reference=round(bound, 4),
                   reference_source="max(1.03 x %g, %g + one parcel %.4f)"
                   % (close_pack, close_pack, parcel),
                   goal=record.at_most(bound + 1e-12),
                   note="over the window; the model's field at most %.4f at "
                   "every step" % res["maxField"]),
    ] + list(extra)
    record.write(path, "uniformBed-%d" % per_cell, rows, plots=plots,
                 settings=settings,
                 window="%g-%g s" % (res["t0"], res["t1"]))


def main():
    parser = post.results_parser("run", __doc__.split("\n")[0])
    parser.add_argument("--from", dest="t0", type=float, default=None,
                        help="start of the window (default 0.4 x the run's end)")
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--rows", action="store_true")
    parser.add_argument("--largest", nargs="+", metavar="DIR:LABEL")
    record.add_record_argument(parser)
    args = parser.parse_args()
    if args.record and args.label == parser.get_default("label"):
        args.label = "perCell%d" % run_settings(args.case)[2]
    if args.largest:
        plot_largest(args.largest)
        return 0
    if args.tableHead:
        print(TABLE_HEAD)
        return 0
    res = summary(args.case, args.t0)
    if args.row:
        per_second = ("%.0f" % (args.wallTime/res["t1"])
                      if args.wallTime and res["t1"] > 0 else "-")
        print("| %s | %g-%g | %.4f | %.3f | %.4f | %.4f | %.3f | %s | %s |"
              % (args.label, res["t0"], res["t1"], res["ratio"], res["std"],
                 res["error"], res["packing"], res["maxCell"], per_second,
                 args.failure or "no"))
    else:
        print("%s: (deltaP - gas head)/weight over %g-%g s = %.4f "
              "(std %.3f, standard error of the mean %.4f); packing force "
              "%.4f x weight; the rest (walls, drag beyond the gas's) %s x weight, "
              "by the momentum budget; max cell solids fraction %.3f; the model's "
              "field at most %.4f at every step"
              % (args.label, res["t0"], res["t1"], res["ratio"], res["std"],
                 res["error"], res["packing"], "-" if res["walls"] is None
                 else "%.4f" % res["walls"], res["maxCell"], res["maxField"]))
        if res["toGas"]:
            print("%s: the packs' reactions handed to the gas %.4f x weight "
                  "(the gas takes it: the drag on the parcels is the "
                  "gas's share plus this)" % (args.label, res["toGas"]))
        if res["travel"]:
            print("%s: the parcels moved a median %.1f mm/s between %g and "
                  "%g s" % (args.label, 1e3*res["travel"][2],
                            res["travel"][0], res["travel"][1]))
    bubbly = None if args.row else bubbles.summary(args.case, res["t0"],
                                                    res["t1"], res["series"])
    if bubbly:
        print("\n".join(bubbles.lines(bubbly, args.label)))
    profile = rows(args.case, res["t0"], res["t1"]) if args.rows else None
    if args.rows and profile is None:
        print("%s: no written packingForce in the window (packingMonitor "
              "writePackingForce)" % args.label)
    elif profile:
        print("row  height [mm]  solids fraction  at close pack  "
              "packing force/weight  U.air_y [m/s]")
        for i, (h, alpha, full, force, gas) in enumerate(bed_rows(profile)):
            print("%3d %8.1f %12.3f %14.2f %+18.4f %14.3f"
                  % (i, 1e3*h, alpha, full, force, gas))
    plots = []
    if args.plot:
        plot(res, args.case, args.label)
        plots.append("uniformFluidization_%s_pressureDrop.png" % args.label)
        if profile:
            plot_rows(profile, args.case, args.label, (res["t0"], res["t1"]))
            plots.append("uniformFluidization_%s_rows.png" % args.label)
        if bubbly:
            plots += bubbles.plots(bubbly, args.case, args.label)
    if args.record:
        write_record(args.record, res, args.case, plots,
                     bubbles.record_rows(bubbly) if bubbly else ())
    return 0


if __name__ == "__main__":
    sys.exit(main())
