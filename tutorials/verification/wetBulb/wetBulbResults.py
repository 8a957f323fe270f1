#!/usr/bin/python3
"""Wet-bulb evaporation (seed 2 section 2.4): the droplet's steady
temperature against seed 2's Table 5 (Mills 1999).

Usage: wetBulbResults.py [--check TOL] [--plot PREFIX] [--table FILE]
                         [--record FILE] RUN [RUN ...]
Each RUN is a case directory run by ./Allrun -humidity N. From its
log.mppicReactingPimpleFoam the droplet temperature after every step (the
cloud's "Temperature min/max", one parcel) and the droplet mass; the
humidity from log.inflow; Table 5's wet-bulb temperature from
constant/inflowConditions. Prints one row per run:
    humidity, ours (mean over the last 0.5 s), Mills, ours - Mills,
    change over the last 1 s (steadiness), droplet mass left, steps
and writes the same as wetBulbTable.md in the current directory.
With --check TOL exits 1 when any |ours - Mills| exceeds TOL kelvin;
with --plot PREFIX writes PREFIX_history.png (temperature against time,
one curve per humidity) and PREFIX_curve.png (steady temperature against
humidity, ours on Table 5's curve); with --record FILE writes the
validation matrix's record (tutorials/lib/validationRecord.py): per
humidity the droplet temperature against Table 5, within 0.3 K.
"""
import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import validationRecord as record  # noqa: E402 (tutorials/lib)

KELVIN = 273.15
WINDOW = 0.5    # s: the steady temperature, the mean over the run's last
GOAL = 0.3      # K: the record's goal for |ours - Mills| (README)


def history(case):
    """(time, droplet temperature, cloud mass) after every step."""
    out = []
    time = mass = None
    with open(os.path.join(case, "log.mppicReactingPimpleFoam")) as f:
        for line in f:
            if line.startswith("Time = "):
                time = float(line.split()[2])
            elif "Current mass in system" in line:
                mass = float(line.split()[-1])
            elif "Temperature min/max" in line and time is not None:
                tmin = float(line.split("=")[1].split(",")[0])
                out.append((time, tmin, mass))
    return out


def humidity(case):
    text = open(os.path.join(case, "log.inflow")).read()
    return int(re.match(r"humidity (\d+) %", text).group(1))


def table5(case):
    """{humidity: wet-bulb temperature [C]} from constant/inflowConditions."""
    text = open(os.path.join(case, "constant", "inflowConditions")).read()
    rows = re.findall(r"rh(\d+)\s*\{[^}]*wetBulb\s+([0-9.eE+-]+);", text)
    return {int(h): float(t) for h, t in rows}


def at(hist, t):
    """Temperature at the last step not after t."""
    best = hist[0][1]
    for ti, T, m in hist:
        if ti > t + 1e-12:
            break
        best = T
    return best


def summary(case):
    hist = history(case)
    if not hist:
        raise SystemExit("%s: no droplet temperature in the log" % case)
    tEnd, TEnd, mEnd = hist[-1]
    mills = table5(case)[humidity(case)]
    ours = post.window_mean([(t, T) for t, T, _ in hist],
                            tEnd - WINDOW, tEnd)[0] - KELVIN
    return {
        "case": case,
        "humidity": humidity(case),
        "tEnd": tEnd,
        "ours": ours,
        "mills": mills,
        "error": ours - mills,
        "drift": TEnd - at(hist, tEnd - 1.0),
        "massLeft": mEnd/hist[0][2],
        "steps": len(hist),
        "history": hist,
    }


def print_table(rows, out):
    head = ("| humidity % | ours [C] | Mills (Table 5) [C] | ours - Mills [K] "
            "| change over the last 1 s [K] | droplet mass left | simulated s |")
    lines = [head, "|" + "---|"*7]
    for r in rows:
        lines.append(
            "| %d | %.3f | %.1f | %+.3f | %+.4f | %.3f | %.3g |"
            % (r["humidity"], r["ours"], r["mills"], r["error"], r["drift"],
               r["massLeft"], r["tEnd"]))
    worst = max(abs(r["error"]) for r in rows)
    lines.append("")
    lines.append("largest |ours - Mills|: %.3f K over %d humidities"
                 % (worst, len(rows)))
    text = "\n".join(lines)
    print(text)
    if out:
        with open(out, "w") as f:
            f.write(text + "\n")
    return worst


def plot(rows, prefix):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for r in rows:
        t = [h[0] for h in r["history"]]
        T = [h[1] - KELVIN for h in r["history"]]
        line, = ax.plot(t, T, lw=1.2, label="%d %%" % r["humidity"])
        ax.axhline(r["mills"], color=line.get_color(), lw=0.6, ls=":")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("droplet temperature [C]")
    ax.set_title("Wet-bulb droplet: temperature history\n"
                 "(dotted: Table 5, Mills 1999)")
    ax.legend(title="humidity", fontsize=7, ncol=2, loc="upper right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(prefix + "_history.png", dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4.5))
    table = table5(rows[0]["case"])
    hs = sorted(table)
    ax.plot(hs, [table[h] for h in hs], "k-", lw=1,
            label="Table 5 (Mills 1999)")
    ax.plot([r["humidity"] for r in rows], [r["ours"] for r in rows], "o",
            mfc="none", color="C3", label="mppicReactingPimpleFoam")
    ax.set_xlabel("relative humidity [%]")
    ax.set_ylabel("wet-bulb temperature [C]")
    ax.set_title("Wet-bulb temperature of air at 30.0 C")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(prefix + "_curve.png", dpi=120)
    plt.close(fig)


def settings(case):
    """What the runs used, from one run's constant/reactingCloudProperties
    and system/controlDict."""
    path = os.path.join(case, "constant", "reactingCloudProperties")
    forces = re.search(r"particleForces\s*\{\s*(\w+)", post.read_text(path))
    return ("packingModel %s (closePackFraction %s); particle forces %s; "
            "heatTransferModel %s; phaseChangeModel %s; averagingMethod %s; "
            "solidsFractionFrom %s; deltaT %s s; %s simulated s per humidity"
            % (post.dict_entry(path, "packingModel"),
               post.dict_entry(path, "closePackFraction"),
               forces.group(1) if forces else "none",
               post.dict_entry(path, "heatTransferModel"),
               post.dict_entry(path, "phaseChangeModel"),
               post.dict_entry(path, "averagingMethod"),
               post.dict_entry(path, "solidsFractionFrom") or "cell",
               post.control_entry(case, "deltaT"),
               post.control_entry(case, "endTime")))


def write_record(args, rows):
    """The validation matrix's record (--record FILE): one row per humidity,
    the plots of --plot named from the current folder."""
    out = [record.row("droplet temperature at %d %% humidity [C]"
                      % r["humidity"], r["ours"], reference=r["mills"],
                      reference_source="Mills, seed 2 Table 5",
                      goal=record.within(GOAL, absolute=True),
                      note="change over the last 1 s %+.4f K" % r["drift"])
           for r in rows]
    plots = [os.path.relpath(args.plot + end)
             for end in ("_history.png", "_curve.png")] if args.plot else []
    ends = sorted(set("%g" % r["tEnd"] for r in rows), key=float)
    record.write(args.record, "wetBulb", out, plots=plots,
                 settings=settings(rows[0]["case"]),
                 window="the mean over the last %g s of each run (ending at "
                 "t = %s s)" % (WINDOW, ", ".join(ends)))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--check", type=float, default=None)
    parser.add_argument("--plot", default=None)
    parser.add_argument("--table", default="wetBulbTable.md")
    record.add_record_argument(parser)
    args = parser.parse_args(argv)

    rows = sorted((summary(c) for c in args.runs), key=lambda r: r["humidity"])
    worst = print_table(rows, args.table)
    if args.plot:
        plot(rows, args.plot)
    if args.record:
        write_record(args, rows)
    if args.check is not None and not worst <= args.check:
        print("FAIL: |ours - Mills| %.3f K above %.3f K" % (worst, args.check))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
