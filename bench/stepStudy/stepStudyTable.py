#!/usr/bin/python3
"""Tables and plot of the gas-step study (bench/stepStudy/stepStudy).

Usage:
    stepStudyTable.py RUNDIR [--plot PNG]

Reads RUNDIR/kj_* (tutorials/validation/kuipersJet runs) with the Kuipers jet's
results module and RUNDIR/uf_* (tutorials/validation/uniformFluidization)
with the uniform bed's, and prints one markdown table per case: the step,
what else differs, the wall seconds per simulated second (run.info, the
whole Allrun with meshing, on cores shared by two runs), and the case's
figures over its statistics window. The spread row is |seed 1 - seed 2| at
5e-4 s: a step's figures are within the spread when they differ from the
5e-4 s seed-1 run by no more than that. --plot draws the figures against
the step (default docs/images/stepStudy.png of the project).
"""
import argparse
import glob
import importlib.util
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))


def load(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


kuipers = load(os.path.join(TOP, "tutorials", "validation", "kuipersJet",
                            "kuipersJetResults.py"),
               "kuipersJetResults")
uniform = load(os.path.join(TOP, "tutorials", "validation", "uniformFluidization",
                            "uniformFluidizationResults.py"),
               "uniformFluidizationResults")


def run_info(case):
    """(deltaT, description, wall s, simulated s) from run.info"""
    text = open(os.path.join(case, "run.info")).read()
    # the study's first runs were made by hand-written equivalents of
    # stepStudy's oneRun: kjStep.sh name dt seed subCycling endTime,
    # ufStep.sh name dt seed endTime [maxCo]
    hand = re.search(r"kjStep.sh \S+ (\S+) (\S+) (\S+) (\S+)", text)
    if hand:
        text += " deltaT %s seed %s solidsSubCycling %s Allrun %s" % hand.groups()
    hand = re.search(r"ufStep.sh \S+ (\S+) (\S+) (\S+)(?: (\S+))?;", text)
    if hand:
        text += " deltaT %s seed %s Allrun %s maxCo %s" % (
            hand.group(1), hand.group(2), hand.group(3), hand.group(4) or "0.3")
    dt = re.search(r"deltaT ([0-9.e-]+)", text)
    wall = re.search(r"(\d+(?:\.\d+)?) s wall", text)
    extra = []
    if re.search(r"seed 2", text):
        extra.append("parcel jitter seed 2")
    if re.search(r"solidsSubCycling true", text):
        extra.append("solids sub-cycling (eq 24, CFL 0.1)")
    if re.search(r"maxCo 1\b", text):
        extra.append("maxCo 1")
    if "kjStep2.sh" in text:
        extra.append("lean cloud step")
    end = re.search(r"Allrun ([0-9.]+)", text)
    return (float(dt.group(1)) if dt else float("nan"), ", ".join(extra) or "-",
            float(wall.group(1)) if wall else float("nan"),
            float(end.group(1)) if end else float("nan"))


def study_cases(run_dir, pattern):
    """The finished runs of the study (a run.info with its end)"""
    cases = []
    for case in sorted(glob.glob(os.path.join(run_dir, pattern))):
        info = os.path.join(case, "run.info")
        if os.path.isfile(info) and "s wall" in open(info).read():
            cases.append(case)
    return cases


def sub_steps(case):
    """Mean number of solids sub-steps per gas step from the solver log"""
    counts = []
    for log in glob.glob(os.path.join(case, "log.mppicPimpleFoam")):
        counts += [int(n) for n in
                   re.findall(r"Solids sub-cycling: (\d+) sub-step", open(log).read())]
    return sum(counts)/len(counts) if counts else 1.0


def kuipers_rows(run_dir):
    rows = []
    for case in study_cases(run_dir, "kj_*"):
        dt, extra, wall, end = run_info(case)
        res = kuipers.summary(case)
        rows.append({
            "name": os.path.basename(case), "dt": dt, "extra": extra,
            "cost": wall/end, "subSteps": sub_steps(case),
            "dp": res.get("dpRatio", float("nan")),
            "mad34": res["mad"].get(("ours", 3.4), float("nan")),
            "mad64": res["mad"].get(("ours", 6.4), float("nan")),
            "expansion": res.get("expansion", float("nan")),
            "maxCell": res.get("maxCell", float("nan")),
            "window": "%g-%g" % (res["t0"], res.get("endTime", end)),
        })
    return rows


def uniform_rows(run_dir):
    rows = []
    for case in study_cases(run_dir, "uf_*"):
        dt, extra, wall, end = run_info(case)
        res = uniform.summary(case, 1.2)
        rows.append({
            "name": os.path.basename(case), "dt": dt, "extra": extra,
            "cost": wall/end, "subSteps": sub_steps(case),
            "dp": res["ratio"], "error": res["error"],
            "packing": res["packing"], "maxCell": res["maxCell"],
            "window": "%g-%g" % (res["t0"], res["t1"]),
        })
    return rows


def spread(rows, keys):
    """|seed 1 - seed 2| at 5e-4 for each key"""
    base = [r for r in rows if r["dt"] == 5e-4 and r["extra"] == "-"]
    other = [r for r in rows if r["dt"] == 5e-4 and "seed 2" in r["extra"]]
    if not base or not other:
        return None, {}
    return base[0], {k: abs(base[0][k] - other[0][k]) for k in keys}


def within(row, base, sp, keys):
    if base is None:
        return "-"
    out = [k for k in keys if abs(row[k] - base[k]) > sp[k] + 1e-12]
    return "yes" if not out else "no (" + ", ".join(out) + ")"


def print_kuipers(rows):
    keys = ["dp", "mad34", "mad64", "expansion"]
    base, sp = spread(rows, keys)
    print("| run | gas step [s] | variant | window [s] | deltaP / weight | MAD 3.4 cm |"
          " MAD 6.4 cm | bed expansion [m] | max cell eps_s | solids sub-steps |"
          " wall s / sim s | within the spread |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(rows, key=lambda r: (-r["dt"], r["extra"])):
        print("| %s | %g | %s | %s | %.3f | %.4f | %.4f | %.3f | %.4f | %.1f | %.0f | %s |"
              % (r["name"], r["dt"], r["extra"], r["window"], r["dp"], r["mad34"],
                 r["mad64"], r["expansion"], r["maxCell"], r["subSteps"], r["cost"],
                 within(r, base, sp, keys)))
    if base is not None:
        print("| spread (seed 1 - seed 2 at 5e-4) | | | | %.3f | %.4f | %.4f | %.3f | | | | |"
              % (sp["dp"], sp["mad34"], sp["mad64"], sp["expansion"]))


def print_uniform(rows):
    keys = ["dp", "packing"]
    base, sp = spread(rows, keys)
    print("| run | gas step [s] | variant | window [s] | deltaP / weight | std error |"
          " packing force / weight | max cell eps_s | wall s / sim s | within the spread |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(rows, key=lambda r: (-r["dt"], r["extra"])):
        print("| %s | %g | %s | %s | %.4f | %.4f | %.4f | %.3f | %.0f | %s |"
              % (r["name"], r["dt"], r["extra"], r["window"], r["dp"], r["error"],
                 r["packing"], r["maxCell"], r["cost"], within(r, base, sp, keys)))
    if base is not None:
        print("| spread (seed 1 - seed 2 at 5e-4) | | | | %.4f | | %.4f | | | |"
              % (sp["dp"], sp["packing"]))


def plot(krows, urows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(15, 5))
    for rows, label, marker in ((krows, "Kuipers jet", "o"), (urows, "uniform bed", "s")):
        plain = sorted([r for r in rows if r["extra"] == "-"], key=lambda r: r["dt"])
        if not plain:
            continue
        dts = [r["dt"] for r in plain]
        axes[0].plot(dts, [r["dp"] for r in plain], marker + "-", label=label)
        axes[2].plot(dts, [r["cost"] for r in plain], marker + "-", label=label)
        for r in rows:
            if "seed 2" in r["extra"]:
                axes[0].plot([r["dt"]], [r["dp"]], marker, mfc="none", color="k",
                             label=label + ", jitter seed 2")
            elif r["extra"] != "-" and "sub-cycling" not in r["extra"]:
                axes[0].plot([r["dt"]], [r["dp"]], "x", ms=9,
                             label=label + ", " + r["extra"])
        if rows is krows:
            axes[1].plot(dts, [r["mad34"] for r in plain], "o-", label="3.4 cm")
            axes[1].plot(dts, [r["mad64"] for r in plain], "^-", label="6.4 cm")
            for r in rows:
                if "seed 2" in r["extra"]:
                    axes[1].plot([r["dt"]]*2, [r["mad34"], r["mad64"]], "o", mfc="none",
                                 color="k", label="seed 2 at 5e-4")
    axes[0].axhline(1.0, color="grey", lw=0.8)
    axes[0].set_ylabel("time-mean deltaP / bed weight")
    axes[1].set_ylabel("Kuipers profiles: mean |difference| from data")
    axes[2].set_ylabel("wall s per simulated s (Allrun, shared cores)")
    axes[2].set_yscale("log")
    for ax in axes:
        ax.set_xscale("log")
        ax.set_xticks([5e-4, 1e-3, 2e-3, 4e-3])
        ax.set_xticklabels(["5e-4", "1e-3", "2e-3", "4e-3"])
        ax.minorticks_off()
        ax.set_xlabel("gas step [s]")
        ax.legend(fontsize=7, loc="upper right" if ax is axes[0] else "best")
    fig.suptitle("Accuracy and cost against the gas step (bench/stepStudy)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print("wrote", path)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("runDir")
    parser.add_argument("--plot", default=os.path.join(TOP, "docs", "images",
                                                       "stepStudy.png"))
    args = parser.parse_args()
    krows, urows = kuipers_rows(args.runDir), uniform_rows(args.runDir)
    if krows:
        print("Kuipers jet")
        print_kuipers(krows)
    if urows:
        print("\nUniform bubbling bed")
        print_uniform(urows)
    if args.plot:
        plot(krows, urows, args.plot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
