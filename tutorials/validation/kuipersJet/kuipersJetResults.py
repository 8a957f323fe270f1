#!/usr/bin/python3
"""Results of the Kuipers central-jet bed.

Usage:
    kuipersJetResults.py [--case DIR] [--label NAME] [--plot] [--check]
                         [--tolerance 0.15] [--from T0] [--row] [--wallTime S]
                         [--against DIR ...] [--record FILE]

Reads postProcessing/{bedPressureDrop,packingMonitor}/0/*.dat (deltaP, every
step; parcels, mass, largest cell solids fraction), the profiles sets
(postProcessing/profiles/<t>/*34*.xy, *64*.xy: time-averaged solids fraction
at 3.4 and 6.4 cm each side of the axis), the written fields
(alpha.kinematicCloud[Mean] or 1 - alpha.air[Mean], packingForce, 0/C)
and prints:
  - deltaP over the statistics window (from --from, default the averaging
    start averageStart of system/controlDict): mean / bed weight, standard
    deviation and half the 5-95 % range (fluctuation amplitude), in Pa; the
    bed weight is m g/(0.57 m x 0.015 m), over the whole bottom;
  - where the rest of the weight goes over the window: the packing step's
    mean upward force over the weight (packingMonitor) and what neither it
    nor the gas carries, from the cloud's vertical momentum written at the
    window's ends: the walls' rebounds and, without balanceImplicitDrag,
    the drag the parcels got beyond the gas's (tutorials/lib/mppicPost.py);
  - the largest cell solids fraction over all steps, the 99th percentile of
    the per-step largest value, the smallest gas fraction, against the
    bound max(1.05 alpha_cp, alpha_cp + V_parcel/V_cell) (a cell-based field
    moves in steps of one parcel, 0.12 of a cell here);
  - bed expansion: the height where the time-averaged solids fraction,
    averaged across the width, drops below 0.05;
  - the mean absolute difference of the time-averaged profiles (left and
    right averaged) from Kuipers' points and MFiX-PIC's curve
    (kuipersJetProfiles.csv, seed 1 Fig. 6), at heights the profile reaches;
  - the slab measure (kuipersJetSlabs.py): the share of the instants in the
    statistics window at which a packed slab lies over a gas void;
  - with packingMonitor writePackingForce: where the packing step acts, the
    field packingForce over the window, split annulus / beside / over the
    jet / bottom row, over the bed weight.
--row prints one markdown table row instead (for compareSolvers). --plot
writes kuipersJet_<label>_{pressureDrop,packing,profiles,snapshots,slabs,
packingForce}.png (the snapshots mark a slab and the void under it).
--against DIR ...: for each other run, the mean absolute difference of its
time-averaged profiles from this run's, its deltaP/weight and bed expansion;
with --plot, every run's profiles in kuipersJet_<label>_profiles.png.
--check: exit status 1 unless the parcel count and mass stay at their first
values, the largest cell solids fraction keeps the bound, and the mean deltaP
is within --tolerance of the bed weight.
--record FILE: the validation matrix's record of the run (kuipersJetRecord.py:
deltaP/weight, the profiles' mean |difference| at 3.4 and 6.4 cm, the slab
measure and the largest cell solids fraction against their goals).
"""
import glob
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import kuipersJetRecord  # noqa: E402 (beside this file)
import kuipersJetSlabs as slabs  # noqa: E402 (beside this file)
# the case's constants and the readers it shares with kuipersJetPlots.py
# (beside this file); its importers (kuipersJetGasBudget, kuipersJetFirstBubble,
# compareSolvers, the regression test) still find them here
from kuipersJetData import (AXIS, CELL_VOLUME, CLOSE_PACK, DEPTH, G,  # noqa: E402
                            WIDTH, cell_grid, mean_abs_difference,
                            reference_profiles, solids_field, to_grid)
import mppicPost as post  # noqa: E402 (tutorials/lib)
from mppicPost import (control_entry, function_object_table,  # noqa: E402
                       percentile, time_dirs)


def bed_expansion(grid, ys, level=0.05):
    rows = [sum(r)/len(r) for r in grid]
    dense = [j for j, a in enumerate(rows) if a >= level]
    if not dense:
        return 0.0
    top = max(dense)
    if top + 1 >= len(rows):
        return ys[top] + 0.5*(ys[1] - ys[0])
    a0, a1 = rows[top], rows[top + 1]
    return ys[top] + (a0 - level)/(a0 - a1)*(ys[top + 1] - ys[top])


def sampled_profiles(case):
    """{3.4: (h, eps_s), 6.4: ...} from the latest sets output, both sides."""
    times = sorted(glob.glob(os.path.join(case, "postProcessing", "profiles", "*")),
                   key=lambda p: float(os.path.basename(p)))
    if not times:
        return {}
    out = {}
    for tag, x_cm in (("34", 3.4), ("64", 6.4)):
        sides = []
        for side in ("left", "right"):
            files = glob.glob(os.path.join(times[-1], side + tag + "_*.xy"))
            if not files:
                continue
            fields = os.path.basename(files[0])[:-3].split("_")[1:]
            rows = post.read_table(files[0])
            if "alpha.kinematicCloudMean" in fields:
                k = 1 + fields.index("alpha.kinematicCloudMean")
                sides.append([(r[0], r[k]) for r in rows])
            elif "alpha.airMean" in fields:
                k = 1 + fields.index("alpha.airMean")
                sides.append([(r[0], 1 - r[k]) for r in rows])
        if sides:
            h = [p[0] for p in sides[0]]
            eps = [sum(s[i][1] for s in sides)/len(sides) for i in range(len(h))]
            out[x_cm] = (h, eps)
    return out


def packed_share(grid, level=0.59):
    """The share of the bed's solids in cells packed throughout the window
    (time-mean eps_s >= level, with close pack 0.62 and 5 parcels = 0.60):
    defluidized regions, which rest on what is below them."""
    total = sum(sum(row) for row in grid)
    packed = sum(a for row in grid for a in row if a >= level)
    return packed/total if total > 0 else float("nan")


def packing_force_split(case, res):
    """The window's mean of packingForce [N/m3] as a grid, and its upward
    part over the bed weight in the annulus (|x - axis| > 0.10 m), beside
    the jet (0.03-0.10 m), over it (<= 0.03 m) and in the bottom row."""
    force, n = post.time_mean_field(case, "packingForce", res["t0"],
                                     res.get("endTime", 1e9), 1)
    if force is None or "grid" not in res or "mass" not in res:
        return
    cells, xs, ys = res["grid"]
    weight = res["mass"][0]*G
    share = dict.fromkeys(("annulus", "beside the jet", "over the jet",
                           "bottom row"), 0.0)
    for f, (i, j) in zip(force*CELL_VOLUME/weight, cells):
        off = abs(xs[i] - AXIS)
        share["annulus" if off > 0.1 else "beside the jet" if off > 0.03
              else "over the jet"] += f
        share["bottom row"] += f if j == 0 else 0.0
    res["forceGrid"] = (n, to_grid(force, cells, len(xs), len(ys)))
    res["forceSplit"] = share


def summary(case, t0=None):
    """Every number of the case, as a dict (missing pieces are absent)."""
    res = {}
    if t0 is None:
        t0 = float(control_entry(case, "averageStart") or 0)
    res["t0"] = t0
    dp = function_object_table(case, "bedPressureDrop")
    mon = function_object_table(case, "packingMonitor")
    res["dp"], res["monitor"] = dp, mon
    if mon:
        res["endTime"] = mon[-1][0]
        res["nParcels"] = (mon[0][1], mon[-1][1])
        res["mass"] = (mon[0][2], mon[-1][2])
        res["weight"] = mon[0][2]*G/(WIDTH*DEPTH)
        res["parcelFraction"] = mon[0][2]/mon[0][1]/2660/CELL_VOLUME
        res["bound"] = max(1.05*CLOSE_PACK, CLOSE_PACK + res["parcelFraction"])
        cell = [r[4] for r in mon]
        res["maxCell"] = max(cell)
        res["p99Cell"] = percentile(cell, 99)
        res["maxAveraged"] = max(r[3] for r in mon)
        res["minGas"] = min(r[6] for r in mon)
    window = [r[3] for r in dp if r[0] >= t0 - 1e-9]
    if window and "weight" in res:
        mean = sum(window)/len(window)
        res["dpMean"] = mean
        res["dpRatio"] = mean/res["weight"]
        res["dpStd"] = math.sqrt(sum((v - mean)**2 for v in window)/len(window))
        res["dpAmplitude"] = 0.5*(percentile(window, 95) - percentile(window, 5))
        rows = [r for r in mon if r[0] >= t0 - 1e-9]
        res["packing"] = post.packing_force(rows, mon[0][2], G)
        # handed to the gas (freePackReactionsToGas): it pushes the gas as
        # the drag's reaction does, so the drag on the parcels is
        # dpRatio + toGas
        res["toGas"] = post.gas_packing_force(rows, mon[0][2], G)
        rest = post.weight_rest(case, t0, mon[-1][0],
                                res["dpRatio"] + res["toGas"]
                                + res["packing"], mon[0][2], G)
        if rest is not None:
            res["walls"] = rest
    times = time_dirs(case)
    if os.path.exists(os.path.join(case, "0", "C")) and len(times) > 1:
        cells, xs, ys = cell_grid(case)
        res["grid"] = (cells, xs, ys)
        for t, name in reversed(times):
            mean = solids_field(case, name, mean=True)
            if mean is not None:
                grid = to_grid(mean, cells, len(xs), len(ys))
                res["meanGrid"] = (name, grid)
                res["expansion"] = bed_expansion(grid, ys)
                res["packedShare"] = packed_share(grid)
                break
    slab_grids(case, res)
    packing_force_split(case, res)
    res["profiles"] = sampled_profiles(case)
    ref = reference_profiles()
    res["mad"] = {}
    for x_cm in (3.4, 6.4):
        measured = ref[("kuipers1990", x_cm)]
        mfix = ref[("mfix_pic", x_cm)]
        res["mad"][("mfix_pic", x_cm)] = mean_abs_difference(
            [p[0] for p in mfix], [p[1] for p in mfix], measured)
        if x_cm in res["profiles"]:
            h, eps = res["profiles"][x_cm]
            res["mad"][("ours", x_cm)] = mean_abs_difference(h, eps, measured)
    return res


def slab_grids(case, res):
    """The slab measure (kuipersJetSlabs) over the statistics window, from
    the slabSamples output, else from the written fields."""
    grids = slabs.sample_grids(case, res["t0"], (76, 100), WIDTH, 1.0)
    res["slabSource"] = "slabSamples every 0.1 s"
    if not grids and "grid" in res:
        cells, xs, ys = res["grid"]
        res["slabSource"] = "written fields"
        for t, name in time_dirs(case):
            field = solids_field(case, name) if t >= res["t0"] - 1e-9 else None
            if field is not None and t > 0:
                grids.append((t, to_grid(field, cells, len(xs), len(ys))))
    res["slab"], res["slabCount"], res["slabFlags"] = slabs.slab_measure(grids)


def fmt(res, key, form, scale=1.0):
    return form % (res[key]*scale) if key in res else "-"


def print_report(res, label):
    print("Kuipers jet, %s: %s s simulated, statistics from %g s"
          % (label, fmt(res, "endTime", "%g"), res["t0"]))
    if "nParcels" in res:
        print("  parcels %d -> %d, mass %.6g -> %.6g kg, bed weight %.1f Pa"
              % (res["nParcels"] + res["mass"] + (res["weight"],)))
    print("  deltaP mean %s Pa = %s x bed weight, std %s Pa, amplitude "
          "(half 5-95 %% range) %s Pa"
          % (fmt(res, "dpMean", "%.1f"), fmt(res, "dpRatio", "%.3f"),
             fmt(res, "dpStd", "%.1f"), fmt(res, "dpAmplitude", "%.1f")))
    print("  reference deltaP/weight (seed 1 Fig. 7, 20-24 s): MFiX-PIC 0.916,"
          " MFiX-TFM 1.026, CPFD 1.089")
    if "packing" in res:
        print("  the weight over the window: the gas (deltaP) %s, the packing"
              " step %s, the rest (walls; drag beyond the gas's pressure drop)"
              " %s" % (fmt(res, "dpRatio", "%.3f"),
                               fmt(res, "packing", "%.3f"),
                               fmt(res, "walls", "%.3f")))
        if res.get("toGas"):
            print("  the packs' reactions handed to the gas %.3f of the weight"
                  " (the gas takes it; the drag on the parcels is the gas's share"
                  " plus this)" % res["toGas"])
    if "forceSplit" in res:
        print("  where the packing step acts (packingForce, %d written times): %s"
              % (res["forceGrid"][0],
                 ", ".join("%s %.3f" % kv for kv in res["forceSplit"].items())))
    if "maxCell" in res:
        print("  cell solids fraction: max %.4f, 99th percentile of the per-step"
              " max %.4f, max of the model's averaging %.4f, min gas fraction"
              " %.4f; bound max(1.05*%.2f, %.2f + %.4f) = %.4f"
              % (res["maxCell"], res["p99Cell"], res["maxAveraged"],
                 res["minGas"], CLOSE_PACK, CLOSE_PACK, res["parcelFraction"],
                 res["bound"]))
    if res.get("slab") is not None:
        print("  slab measure: a packed slab over a void at %d of %d instants"
              " (%s) from %g s: %.1f %%" % (
                  round(res["slab"]*res["slabCount"]), res["slabCount"],
                  res["slabSource"], res["t0"], 100*res["slab"]))
    print("  bed expansion (time-averaged eps_s < 0.05 above): %s m (initial 0.5 m)"
          % fmt(res, "expansion", "%.3f"))
    print("  solids in cells packed throughout the window (time-mean eps_s"
          " >= 0.59): %s of the bed" % fmt(res, "packedShare", "%.3f"))
    for x_cm in (3.4, 6.4):
        print("  profile %.1f cm: mean |difference| from Kuipers' points: ours"
              " %s, MFiX-PIC %.4f" % (
                  x_cm, "%.4f" % res["mad"][("ours", x_cm)]
                  if ("ours", x_cm) in res["mad"] else "-",
                  res["mad"][("mfix_pic", x_cm)]))


TABLE_HEAD = ("| run | deltaP / weight | deltaP amplitude [Pa] | max cell eps_s "
              "| 99th pct | min eps_g | bed expansion [m] | MAD 3.4 cm | MAD 6.4 cm "
              "| slab [%] | wall s / sim s | diverged |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|")


def table_row(res, label, wall, failure):
    mad = res.get("mad", {})
    per_sim = "-"
    if wall and res.get("endTime"):
        per_sim = "%.0f" % (wall/res["endTime"])
    slab = "-" if res.get("slab") is None else "%.0f" % (100*res["slab"])
    return "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
        label, fmt(res, "dpRatio", "%.3f"), fmt(res, "dpAmplitude", "%.0f"),
        fmt(res, "maxCell", "%.3f"), fmt(res, "p99Cell", "%.3f"),
        fmt(res, "minGas", "%.3f"), fmt(res, "expansion", "%.3f"),
        "%.3f" % mad[("ours", 3.4)] if ("ours", 3.4) in mad else "-",
        "%.3f" % mad[("ours", 6.4)] if ("ours", 6.4) in mad else "-",
        slab, per_sim, failure or "no")


def compare_runs(case, others, t0):
    """Profile distance between this run and each other run, and their
    deltaP/weight and bed expansion; returns every run's profiles, [(name,
    profiles)] (each run's latest sampled window), which main() draws with
    --plot into kuipersJet_<label>_profiles.png."""
    mine, base = sampled_profiles(case), summary(case, t0)
    print("run | profile 3.4 cm: mean abs difference from %s | 6.4 cm | "
          "deltaP/weight | bed expansion [m]" % case)
    print("%s | - | - | %.3f | %.3f" % (case, base.get("dpRatio", float("nan")),
                                        base.get("expansion", float("nan"))))
    runs = [(os.path.basename(os.path.abspath(case)), mine)]
    for other in others:
        theirs, res = sampled_profiles(other), summary(other, t0)
        runs.append((os.path.basename(os.path.abspath(other)), theirs))
        cells = ["%.4f" % mean_abs_difference(*theirs[x], list(zip(*mine[x])))
                 if x in mine and x in theirs else "-" for x in (3.4, 6.4)]
        print("%s | %s | %s | %.3f | %.3f" % (
            other, cells[0], cells[1], res.get("dpRatio", float("nan")),
            res.get("expansion", float("nan"))))
    return runs


def main():
    parser = post.results_parser("coloringFunction")
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--tolerance", type=float, default=0.15)
    parser.add_argument("--from", dest="t0", type=float, default=None)
    parser.add_argument("--against", nargs="+", default=[])
    parser.add_argument("--record", metavar="FILE",
                        help="write the validation matrix's record to FILE")
    args = post.parse_results_args(parser, TABLE_HEAD)
    # the plots module is imported here only (it imports kuipersJetData, not
    # this module): --plot and --against --plot
    if args.against:
        runs = compare_runs(args.case, args.against, args.t0)
        if args.plot and args.label:
            import kuipersJetPlots
            kuipersJetPlots.plot_profiles(runs, os.path.join(
                args.case, "kuipersJet_%s_profiles.png" % args.label))
        return 0

    res = summary(args.case, args.t0)
    if args.row:
        print(table_row(res, args.label, args.wallTime, args.failure))
    else:
        print_report(res, args.label)
    plots = []
    if args.plot:
        import kuipersJetPlots
        for name in kuipersJetPlots.plot(res, args.case, args.label):
            print("  wrote " + name)
            plots.append(os.path.relpath(name, args.case))
    kuipersJetRecord.write(args.record, res, args.case, plots)

    if args.check:
        checks = [
            ("parcel count constant", "nParcels" in res
             and res["nParcels"][0] == res["nParcels"][1]),
            ("cloud mass constant", "mass" in res
             and abs(res["mass"][1]/res["mass"][0] - 1) < 1e-9),
            ("max cell solids fraction <= bound", "maxCell" in res
             and res["maxCell"] <= res["bound"] + 1e-12),
            ("mean deltaP within %g of the bed weight" % args.tolerance,
             "dpRatio" in res and abs(res["dpRatio"] - 1) <= args.tolerance),
        ]
        for what, ok in checks:
            print(("PASS " if ok else "FAIL ") + what)
        return 0 if all(ok for _, ok in checks) else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
