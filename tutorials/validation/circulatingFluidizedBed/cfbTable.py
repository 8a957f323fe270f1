#!/usr/bin/python3
"""The CFB's operating cases against seed 2's Tables 8-9 (experiment of Xu et
al. 2017, MFiX-PIC, MFiX-DEM; cfbReference.csv).

Usage:
    cfbTable.py RUN [RUN ...] [--plot FILE] [--out FILE]
    RUN = CASE:DIR:T0:T1, e.g. 2:../runs/case2:10:14 (operating case 1-3,
          the run's directory, the averaging window in simulated seconds)

For each run, cfbResults.summary over the window: riser pressure drop,
standpipe pressure drop and the standpipe inventory height above the bend
(y 0.146; the experiment's datum is not public), each with the reference
values and our relative error (height: difference in m); and, to say how
steady the window is, the circulation down the standpipe and along the
crossover (equal in a steady loop) and the change of the level over the
window (slope of a straight-line fit). --out writes the table as Markdown;
--plot draws riser and standpipe pressure drop (every step faint, 0.1 s
means bold) and the level against time for all runs from --start (default
0.5 s, after the start-up transient), with the experiment's values as
dashed lines and, with --switch T, a vertical line where runs started from
another case's state (--switchText
says what happened there). --labels "A;B" colours the lines by run, one
label each, instead of by case.
"""
import argparse
import csv
import os
import sys

import cfbResults
from cfbResults import post

HERE = os.path.dirname(os.path.abspath(__file__))


def reference():
    rows = {}
    with open(os.path.join(HERE, "cfbReference.csv")) as f:
        lines = [l for l in f if not l.startswith("#")]
    for r in csv.DictReader(lines):
        rows[int(r["case"])] = {k: float(v) for k, v in r.items() if k != "case"}
    return rows


def slope(series, t0, t1):
    p = [(t, v) for t, v in series if t0 - 1e-12 <= t <= t1 + 1e-12]
    return post.fit_line(p)[0] if len(p) >= 3 else float("nan")


def parse(run):
    case, path, t0, t1 = run.rsplit(":", 3) if run.count(":") > 3 else run.split(":")
    return int(case), path, float(t0), float(t1)


def rows_for(case, path, t0, t1, ref):
    r = cfbResults.summary(path, t0, t1)
    x = ref[case]
    out = []
    for name, ours, key in (
        ("riser ΔP [Pa]", r["riserDp"], "riser_dp"),
        ("standpipe ΔP [Pa]", r["standpipeDp"], "standpipe_dp"),
    ):
        exp = x[key + "_exp"]
        out.append((name, "%.0f" % ours, "%.0f" % exp, "%+.0f %%" % (100*(ours/exp - 1)),
                    "%.0f" % x[key + "_mfixpic"], "%.0f" % x[key + "_mfixdem"]))
    h = r["heightAboveBend"]
    out.append(("standpipe height above the bend [m]", "%.3f" % h,
                "%.2f ± %.2f" % (x["height_exp"], x["height_exp_unc"]),
                "%+.3f m" % (h - x["height_exp"]), "%.3f" % x["height_mfixpic"],
                "%.2f" % x["height_mfixdem"]))
    steady = ("down the standpipe %.1f g/s, along the crossover %.1f g/s; level "
              "%+.3f m/s; riser %.3f kg"
              % (1e3*r["circulationStandpipe"], 1e3*r["circulationCrossover"],
                 slope(r["levelSeries"], t0, t1), r["riserMass"]))
    return r, out, steady


def table(runs, ref):
    lines = ["| case (window) | quantity | ours | experiment | ours vs experiment "
             "| MFiX-PIC | MFiX-DEM |", "|---|---|---|---|---|---|---|"]
    notes = []
    results = []
    for case, path, t0, t1 in runs:
        r, out, steady = rows_for(case, path, t0, t1, ref)
        results.append((case, path, r))
        for i, row in enumerate(out):
            label = "%d (%g–%g s)" % (case, t0, t1) if i == 0 else ""
            lines.append("| %s | %s |" % (label, " | ".join(row)))
        notes.append("Case %d, %g–%g s (%s): %s" % (case, t0, t1, path, steady))
    return "\n".join(lines + [""] + ["- " + n for n in notes]), results


def plot(results, ref, path, start, switch, labels=None,
         switchText="cases 2, 3 start from case 1 here"):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    keys = (("riserDpSeries", "riser_dp_exp", "riser ΔP [Pa]"),
            ("standpipeDpSeries", "standpipe_dp_exp", "standpipe ΔP [Pa]"),
            ("levelSeries", "height_exp", "level above the bend [m]"))
    for i, (case, _, r) in enumerate(results):
        colour = "C%d" % (i if labels else case - 1)
        name = labels[i] if labels else "case %d" % case
        for ax, (series, refKey, label) in zip(axes, keys):
            s = r[series]
            shift = cfbResults.STANDPIPE_Y0 if series == "levelSeries" else 0
            s = [(t, v) for t, v in s if t >= start]
            if series == "levelSeries":
                ax.plot([t for t, v in s], [v - shift for t, v in s], color=colour, lw=0.8,
                        label=name)
            else:
                # every step faint (the taps of a packed bed jump from step
                # to step), the 0.1 s means over it
                step = max(1, len(s)//4000)
                ax.plot([t for t, v in s[::step]], [v for t, v in s[::step]],
                        color=colour, lw=0.4, alpha=0.25)
                ax.plot(*zip(*post.block_means(s, 0.1)), color=colour, lw=1.2, label=name)
            ax.axhline(ref[case][refKey], color="k" if labels else colour,
                       ls="--", lw=1)
            ax.set_ylabel(label)
    for ax in axes[:2]:
        ax.set_ylim(0, 2000)
    if switch is not None:
        for ax in axes:
            ax.axvline(switch, color="k", lw=0.8, ls=":")
        axes[0].text(switch, 1900, " " + switchText, fontsize=8, va="top")
    axes[0].legend(loc="lower left", fontsize=8)
    axes[-1].set_xlabel("time [s]")
    axes[0].set_title("NETL CFB, coarse mesh: ours (lines) against the experiment (dashed)")
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("--plot")
    p.add_argument("--out")
    p.add_argument("--start", type=float, default=0.5)
    p.add_argument("--switch", type=float)
    p.add_argument("--switchText", default="cases 2, 3 start from case 1 here")
    p.add_argument("--labels", help="separated by ;, one per RUN: the plot's"
                   " lines by run instead of by case")
    a = p.parse_args(argv)
    ref = reference()
    text, results = table([parse(r) for r in a.runs], ref)
    print(text)
    if a.out:
        with open(a.out, "w") as f:
            f.write(text + "\n")
    if a.plot:
        labels = a.labels.split(";") if a.labels else None
        plot(results, ref, a.plot, a.start, a.switch, labels, a.switchText)
        print("wrote " + a.plot)


if __name__ == "__main__":
    main(sys.argv[1:])
