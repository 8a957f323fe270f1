#!/usr/bin/python3
"""Segregation of the binary bubbling bed over time.

Usage:
    binaryBedResults.py [--case DIR] [--from T0] [--window W] [--plot]
                        [--record FILE]

Reads postProcessing/packingMonitor/0/phases.dat (each phase's mass and
mass-weighted mean height at every step; phase 1 the 2.5 mm beads, phase 2
the 1.5 mm ones), packingMonitor.dat and bedPressureDrop.dat, and prints
Goldschmidt et al.'s segregation degree
    s = (S - 1)/(S_max - 1),   S = h_small/h_large,
h the phases' mean heights; S_max = 3 is S of the bed perfectly segregated
at rest with equal volumes of the two sizes (the small beads in a layer on
the large: mean heights 3H/4 and H/4); s = 0 for a bed mixed at random, 1
for one fully segregated, negative when the large beads ride higher. Prints
s and the mean heights over windows of W s (default 2) from T0 (default 0),
the gas pressure drop over the bed's weight and the packing bound.
--plot: binaryBed_segregation.png (s and the mean heights against time).
--record FILE: the validation matrix's record (case binaryBed, or
binaryBed-<packing model> for another model than coloringFunction).
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import validationRecord as record  # noqa: E402 (tutorials/lib)

LARGE, SMALL = 1, 2
S_MAX = 3.0


def phase_heights(case):
    """Times and each phase's mean height at every step."""
    rows = np.array(post.function_object_table(case, "packingMonitor",
                                               "phases"))
    large = rows[rows[:, 1] == LARGE]
    small = rows[rows[:, 1] == SMALL]
    n = min(len(large), len(small))
    return large[:n, 0], large[:n, 4], small[:n, 4]


def segregation(h_large, h_small):
    return (h_small/h_large - 1)/(S_MAX - 1)


def windows(t, values, t0, width):
    """Mean of values over windows [a, a + width) from t0 to the end."""
    out = []
    a = t0
    while a < t[-1] - 1e-9:
        m = (t >= a) & (t < a + width)
        if m.any():
            out.append((a, min(a + width, t[-1]), values[m].mean()))
        a += width
    return out


def summary(case, t0, width):
    t, hl, hs = phase_heights(case)
    s = segregation(hl, hs)
    monitor = post.function_object_table(case, "packingMonitor")
    dp = post.function_object_table(case, "bedPressureDrop")
    # columns: time pLower pUpper deltaP gasHead weightPerArea ratio
    ratio = np.array([(r[3] - r[4])/r[5] for r in dp if r[0] >= t0])
    return dict(t=t, h_large=hl, h_small=hs, s=s,
                windows=windows(t, s, t0, width),
                heights=list(zip(windows(t, hl, t0, width),
                                 windows(t, hs, t0, width))),
                dp_ratio=ratio.mean() if len(ratio) else float("nan"),
                dp_std=ratio.std() if len(ratio) else float("nan"),
                max_cell=max(r[4] for r in monitor),
                above=max(int(r[5]) for r in monitor))


def plot(res, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(6, 6), sharex=True)
    ax.plot(res["t"], res["s"], "k-", lw=0.6)
    for a, b, v in res["windows"]:
        ax.plot([a, b], [v, v], "r-", lw=2)
    ax.plot([], [], "r-", lw=2, label="window means")
    ax.axhline(0, color="gray", lw=0.5)
    ax.set_ylabel("segregation degree s")
    ax.legend(fontsize=8)
    bx.plot(res["t"], res["h_large"], "b-", lw=0.8, label="2.5 mm beads")
    bx.plot(res["t"], res["h_small"], "r-", lw=0.8, label="1.5 mm beads")
    bx.set_xlabel("time [s]")
    bx.set_ylabel("mean height [m]")
    bx.legend(fontsize=8)
    ax.set_title("Binary bed, 1.10 m/s: segregation")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def record_rows(res):
    rows = []
    for a, b, v in res["windows"]:
        rows.append(record.row(
            "segregation degree s, %.0f-%.0f s" % (a, b), v,
            reference_source="no measured values in the stored material "
            "(Goldschmidt et al. 2003 not available)"))
    rows.append(record.row(
        "(deltaP - gas head)/weight, mean", res["dp_ratio"],
        note="standard deviation %.3f" % res["dp_std"]))
    rows.append(record.row(
        "cells above close pack (most at one step)", res["above"],
        reference=0, reference_source="the capacity limit",
        goal=record.at_most(0),
        note="largest cell solids fraction %.4f" % res["max_cell"]))
    return rows


def main():
    parser = post.results_parser(None, __doc__.split("\n")[0])
    parser.add_argument("--from", dest="t0", type=float, default=0.0)
    parser.add_argument("--window", type=float, default=2.0)
    parser.add_argument("--plot", action="store_true")
    record.add_record_argument(parser)
    args = parser.parse_args()
    res = summary(args.case, args.t0, args.window)
    print("window [s] | s | mean height 2.5 mm [m] | mean height 1.5 mm [m]")
    for (a, b, v), (hl, hs) in zip(res["windows"], res["heights"]):
        print("%.1f-%.1f | %+.4f | %.4f | %.4f" % (a, b, v, hl[2], hs[2]))
    print("(deltaP - gas head)/weight from %.1f s: %.3f (std %.3f)"
          % (args.t0, res["dp_ratio"], res["dp_std"]))
    print("largest cell solids fraction %.4f; most cells above close pack "
          "at one step %d" % (res["max_cell"], res["above"]))
    if args.plot:
        path = os.path.join(args.case, "binaryBed_segregation.png")
        plot(res, path)
        print("wrote " + path)
    if args.record:
        model = post.dict_entry(os.path.join(
            args.case, "constant", "kinematicCloudProperties"), "packingModel")
        name = "binaryBed" + ("" if model == "coloringFunction" else "-" + model)
        record.write(args.record, name, record_rows(res),
                     plots=["binaryBed_segregation.png"] if args.plot else [],
                     settings=record.case_settings(args.case))
    return 0


if __name__ == "__main__":
    sys.exit(main())
