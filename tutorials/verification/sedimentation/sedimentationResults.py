#!/usr/bin/python3
"""Results of the sedimentation case: packing bounds and bed height.

Usage:
    sedimentationResults.py [--case DIR] [--label NAME] [--check] [--plot]
                            [--record FILE]
    sedimentationResults.py --tableHead
    sedimentationResults.py [--case DIR] --row [--label NAME] [--wallTime S]
                            [--failure TEXT]     (bin/compareSolvers)

Reads
  postProcessing/packingMonitor/0/packingMonitor.dat   (every step)
  <latest time>/alpha.kinematicCloud and C             (cell solids fraction,
                                                        cell centres; with
                                                        MPPICFoam 1 - alpha.air)
  constant/seededParcels                               (seeded solids volume)
and prints one table row:
  - max alpha_s (averaged): the largest value over all steps of the solids
    fraction as the cloud's averaging method gives it (the field the packing
    model works on; cell values for averagingMethod basic);
  - max alpha_s (cell): the same for the cell solids fraction;
  - min gas fraction: 1 - max alpha_s (cell), over all steps;
  - bed height: where the row-averaged solids fraction of the final field
    falls through half the close-pack fraction (linear between row centres),
    against the inventory height  H = V_solids/(alpha_cp*A)  with A the
    column's cross-section;
and the bounds of the verification:
  - every step: max alpha_s <= max(1.03*alpha_cp, alpha_cp + V_parcel/V_cell)
    (the second term is one parcel: a cell-based field moves in steps of one
    parcel), gas fraction >= 0;
  - final bed height within 3 % of H.
With --check the exit status is 1 when a bound is not met. With --plot it
writes sedimentation_<label>.png (max alpha_s against time, final profile).
With --record FILE it writes the validation matrix's record of the run
(tutorials/lib/validationRecord.py, case sedimentation): the three bounds.
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


def read_monitor(case):
    path = os.path.join(case, "postProcessing", "packingMonitor", "0",
                        "packingMonitor.dat")
    m = re.search(r"^#\s*closePackFraction\s*:\s*(\S+)", post.read_text(path),
                  re.M)
    return (float(m.group(1)) if m else None), post.read_table(path)


def seeded_solids_volume(case):
    text = open(os.path.join(case, "constant", "seededParcels")).read()
    return float(re.search(r"solidsVolume\s+([^;]+);", text).group(1))


def bed_profile(case, time):
    solids = os.path.join(case, time, "alpha.kinematicCloud")
    if os.path.exists(solids):
        alpha = post.internal_field(solids)
    else:
        # stock MPPICFoam writes the gas fraction only
        alpha = [1 - a for a in post.internal_field(os.path.join(case, time, "alpha.air"))]
    centres = post.internal_field(os.path.join(case, time, "C"))
    rows = {}
    for a, c in zip(alpha, centres):
        rows.setdefault(round(c[1], 9), []).append((a, c))
    ys = sorted(rows)
    profile = [sum(a for a, _ in rows[y])/len(rows[y]) for y in ys]
    dy = ys[1] - ys[0]
    xs = [c[0] for _, c in rows[ys[0]]]
    zs = [c[2] for _, c in rows[ys[0]]]
    nx, nz = len(set(round(x, 9) for x in xs)), len(set(round(z, 9) for z in zs))
    dx = (max(xs) - min(xs))/(nx - 1) if nx > 1 else None
    dz = (max(zs) - min(zs))/(nz - 1) if nz > 1 else None
    return ys, profile, dy, (nx, dx, min(xs)), (nz, dz, min(zs))


def surface_height(ys, profile, level, dy):
    top = max(j for j, a in enumerate(profile) if a >= level)
    if top + 1 >= len(profile):
        return ys[top] + dy/2
    a0, a1 = profile[top], profile[top + 1]
    return ys[top] + (a0 - level)/(a0 - a1)*dy


TABLE_HEAD = ("| packing model | max alpha_s (averaged) | max alpha_s (cell) | "
              "bound | min eps_g | bed H [m] | H error | bounds met | "
              "wall time [s] | failed |\n"
              "|---|---|---|---|---|---|---|---|---|---|")


def summary(case, width, depth):
    """The bounds and the bed height of the run in case (module doc)."""
    close_pack, rows = read_monitor(case)
    time = post.latest_time(case)
    ys, profile, dy, xinfo, zinfo = bed_profile(case, time)
    area = width*depth
    cell_volume = area/(xinfo[0]*zinfo[0])*dy
    solids = seeded_solids_volume(case)
    parcel_fraction = solids/rows[-1][1]/cell_volume
    res = dict(close_pack=close_pack, rows=rows, time=time, ys=ys,
               profile=profile, parcel_fraction=parcel_fraction,
               max_avg=max(r[3] for r in rows),
               max_cell=max(r[4] for r in rows),
               min_gas=min(r[6] for r in rows),
               height=surface_height(ys, profile, 0.5*close_pack, dy),
               expected=solids/(close_pack*area))
    res["height_error"] = (res["height"] - res["expected"])/res["expected"]
    res["bound"] = max(1.03*close_pack, close_pack + parcel_fraction)
    res["ok"] = dict(pack=res["max_avg"] <= res["bound"] + 1e-12,
                     gas=res["min_gas"] >= 0,
                     height=abs(res["height_error"]) <= 0.03)
    return res


def table_row(res, label, wall, failure):
    return "| %s | %.4f | %.4f | %.4f | %.4f | %.4f | %.1f %% | %s | %s | %s |" % (
        label, res["max_avg"], res["max_cell"], res["bound"], res["min_gas"],
        res["height"], 100*res["height_error"],
        "yes" if all(res["ok"].values()) else "no",
        "%.0f" % wall if wall else "-", failure or "no")


def record_rows(res):
    """The record's rows: the bounds of the verification (module doc)."""
    return [
        record.row("largest solids fraction, every step", res["max_avg"],
                   reference=res["close_pack"],
                   reference_source="close pack (packingMonitor)",
                   goal=record.at_most(res["bound"] + 1e-12),
                   note="the model's averaging; bound max(1.03 alpha_cp, "
                   "alpha_cp + one parcel = %.4f of a cell); cell field "
                   "at most %.4f" % (res["parcel_fraction"], res["max_cell"])),
        record.row("smallest gas fraction, every step", res["min_gas"],
                   goal=record.at_least(0)),
        record.row("bed height at %s s [m]" % res["time"], res["height"],
                   reference=res["expected"],
                   reference_source="inventory height V_solids/(alpha_cp A)",
                   goal=record.within(0.03),
                   note="where the row mean falls through alpha_cp/2")]


def main():
    parser = post.results_parser("coloringFunction")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--width", type=float, default=0.05)
    parser.add_argument("--depth", type=float, default=0.005)
    record.add_record_argument(parser)
    args = post.parse_results_args(parser, TABLE_HEAD)

    res = summary(args.case, args.width, args.depth)
    if args.row:
        print(table_row(res, args.label, args.wallTime, args.failure))
        return 0
    close_pack, rows, ys, profile = (res["close_pack"], res["rows"],
                                     res["ys"], res["profile"])
    bound, height, expected = res["bound"], res["height"], res["expected"]
    ok = res["ok"]

    print("%-18s %10s %10s %10s %10s %10s %9s" % (
        "packing model", "max as av", "max as cell", "bound", "min eps_g",
        "bed H [m]", "H error"))
    print("%-18s %10.4f %10.4f %10.4f %10.4f %10.4f %8.1f%%" % (
        args.label, res["max_avg"], res["max_cell"], bound, res["min_gas"],
        height, 100*res["height_error"]))
    print("close pack %.3f, one parcel = %.4f of a cell, inventory height %.4f m,"
          " final time %s" % (close_pack, res["parcel_fraction"], expected,
                              res["time"]))
    print("bounds: max alpha_s %s, gas fraction %s, bed height %s" % (
        "met" if ok["pack"] else "NOT met", "met" if ok["gas"] else "NOT met",
        "met" if ok["height"] else "NOT met"))

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
        t = [r[0] for r in rows]
        ax1.plot(t, [r[3] for r in rows], label="max $\\alpha_s$ (model's averaging)")
        ax1.plot(t, [r[4] for r in rows], "--", label="max $\\alpha_s$ (cell)")
        ax1.axhline(close_pack, color="k", lw=0.8, label="close pack")
        ax1.axhline(bound, color="r", lw=0.8, label="bound")
        ax1.set_xlabel("t [s]")
        ax1.set_ylabel("solids fraction")
        ax1.set_title("sedimentation, %s" % args.label)
        ax1.legend(fontsize=8)
        ax2.plot(profile, ys, "o-", ms=3, label="final, row average")
        ax2.axhline(expected, color="k", lw=0.8, label="inventory height")
        ax2.axhline(height, color="r", lw=0.8, ls="--", label="bed surface")
        ax2.axvline(close_pack, color="gray", lw=0.6)
        ax2.set_xlabel("solids fraction")
        ax2.set_ylabel("y [m]")
        ax2.set_ylim(0, 3*expected)
        ax2.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(args.case, "sedimentation_%s.png" % args.label),
                    dpi=100)
    if args.record:
        record.write(args.record, "sedimentation", record_rows(res),
                     plots=["sedimentation_%s.png" % args.label]
                     if args.plot else [], settings=record.case_settings(args.case))

    if args.check and not all(ok.values()):
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
