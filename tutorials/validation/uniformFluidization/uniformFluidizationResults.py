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
    - the rest, held by the walls' rebounds (the distributor's: the side
      walls are frictionless), from the cloud's momentum budget with its
      vertical momentum at the written times nearest the window's ends;
    - how much the bed moves: the median distance the parcels travelled
      between the last two written times, per second (parcels matched by
      origId). A bubbling bed stirs its parcels by centimetres per second;
      a bed that does not bubble (a static, layered packing) by a few
      millimetres.

Usage:
    uniformFluidizationResults.py [--case DIR] [--from T0] [--label L]
        [--row [--wallTime S] [--failure TEXT]] [--tableHead] [--plot]
    --row   one markdown table row (TABLE_HEAD; bin/compareSolvers)
    --plot  uniformFluidization_<label>_pressureDrop.png: deltaP/weight(t)
    uniformFluidizationResults.py --largest DIR:LABEL [DIR:LABEL ...]
        uniformFluidization_largestSolidsFraction.png: the largest
        solids fraction of the model's field at every step of each run,
        against the bound 1.15 x 0.6 = 0.69
"""
import argparse
import math
import os
import re
import sys

TABLE_HEAD = ("| run | window [s] | deltaP / weight | std | std error of mean "
              "| packing force / weight | max cell eps_s | wall s / sim s "
              "| failed |\n|---|---|---|---|---|---|---|---|---|")


def read_table(path):
    """Rows of a function object's .dat file (comment lines skipped)."""
    rows = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        rows.append([float(v) for v in line.split()])
    return rows


def pressure_ratio(case):
    """(t, (deltaP - gas head)/(W/A)) for every step."""
    rows = read_table(os.path.join(case, "postProcessing", "bedPressureDrop",
                                   "0", "bedPressureDrop.dat"))
    # columns: time pLower pUpper deltaP gasHead weightPerArea ratio
    return [(r[0], (r[3] - r[4])/r[5]) for r in rows]


def monitor(case):
    """packingMonitor rows: time, parcels, mass, max averaged, max cell..."""
    return read_table(os.path.join(case, "postProcessing", "packingMonitor",
                                   "0", "packingMonitor.dat"))


def mean_and_error(series, block):
    """Mean, standard deviation and the standard error of the mean from
    the means of consecutive blocks of the given duration."""
    values = [v for _, v in series]
    n = len(values)
    mean = sum(values)/n
    std = math.sqrt(sum((v - mean)**2 for v in values)/n)
    dt = (series[-1][0] - series[0][0])/max(n - 1, 1)
    size = max(1, int(round(block/dt)))
    blocks = [values[i:i + size] for i in range(0, n - size + 1, size)]
    if len(blocks) < 2:
        return mean, std, float("nan")
    means = [sum(b)/len(b) for b in blocks]
    spread = math.sqrt(sum((m - mean)**2 for m in means)/(len(means) - 1))
    return mean, std, spread/math.sqrt(len(means))


def packing_force(rows, g=9.81):
    """Mean upward force of the packing step over the cloud's weight
    (packingMonitor: the momentum it adds per step)."""
    if len(rows) < 2:
        return float("nan")
    duration = rows[-1][0] - rows[0][0] + (rows[1][0] - rows[0][0])
    return sum(r[9] for r in rows)/duration/(rows[-1][2]*g)


def lagrangian_field(path):
    """Values of a written lagrangian field (uniform N{v} or a list)."""
    text = open(path).read()
    text = text[text.index("}", text.index("FoamFile")) + 1:]
    m = re.search(r"(\d+)\s*\{([^}]*)\}", text)
    if m and (text.find("(") < 0 or text.find("(") > m.start()):
        value = [float(v) for v in m.group(2).strip("() \n").split()]
        return [value]*int(m.group(1))
    body = text[text.index("(") + 1:text.rindex(")")]
    if "(" in body:
        return [[float(v) for v in t.split()]
                for t in re.findall(r"\(([^()]*)\)", body)]
    return [[float(v)] for v in body.split()]


def cloud_momentum(case, time):
    """Vertical momentum of the cloud written at a time, kg m/s."""
    d = os.path.join(case, time, "lagrangian", "kinematicCloud")
    if not os.path.isdir(d):
        return None
    fields = [lagrangian_field(os.path.join(d, f))
              for f in ("nParticle", "rho", "d", "U")]
    return sum(n[0]*rho[0]*math.pi/6*dia[0]**3*u[1]
               for n, rho, dia, u in zip(*fields))


def wall_share(case, t0, t1, ratio, packing, mass, g=9.81):
    """The rest of the weight, held by the walls (the distributor: the side
    walls rebound without friction), from the cloud's momentum budget over
    the window, d(P_y)/dt = (ratio + packing + walls - 1) M g, with the
    momentum at the written times nearest the window's ends; None without
    them."""
    times = [d for d in os.listdir(case) if re.match(r"^[0-9.]+$", d)]
    def nearest(t):
        return min(times, key=lambda d: abs(float(d) - t)) if times else None
    a, b = nearest(t0), nearest(t1)
    if a is None or a == b:
        return None
    pa, pb = cloud_momentum(case, a), cloud_momentum(case, b)
    if pa is None or pb is None:
        return None
    rate = (pb - pa)/(float(b) - float(a))/(mass*g)
    return rate + 1 - ratio - packing


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
        ids = [int(v[0]) for v in lagrangian_field(os.path.join(d, "origId"))]
        pos = lagrangian_field(os.path.join(d, "positions"))
        where.append(dict(zip(ids, pos)))
    a, b = where
    dist = sorted(math.dist(a[i][:3], b[i][:3]) for i in a if i in b)
    if not dist:
        return None
    ta, tb = float(times[-2]), float(times[-1])
    return ta, tb, dist[len(dist)//2]/(tb - ta)


def summary(case, t0=None):
    everything = pressure_ratio(case)
    if t0 is None:
        t0 = 0.4*everything[-1][0]
    series = [(t, r) for t, r in everything if t >= t0 - 1e-12]
    if not series:
        raise SystemExit("no bedPressureDrop samples after %g s in %s" % (t0, case))
    mean, std, error = mean_and_error(series, 0.25)
    rows = [r for r in monitor(case) if r[0] >= t0 - 1e-12]
    max_cell = max(r[4] for r in rows) if rows else float("nan")
    max_field = max(r[3] for r in monitor(case))
    packing = packing_force(rows)
    walls = wall_share(case, t0, series[-1][0], mean, packing,
                       rows[-1][2]) if rows else None
    return {"t0": t0, "t1": series[-1][0], "ratio": mean, "std": std,
            "error": error, "maxCell": max_cell, "packing": packing,
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--case", default=".")
    parser.add_argument("--from", dest="t0", type=float, default=None,
                        help="start of the window (default 0.4 x the run's end)")
    parser.add_argument("--label", default="run")
    parser.add_argument("--row", action="store_true")
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--tableHead", action="store_true")
    parser.add_argument("--wallTime", type=float, default=None)
    parser.add_argument("--failure", default="")
    parser.add_argument("--largest", nargs="+", metavar="DIR:LABEL")
    args = parser.parse_args()
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
              "%.4f x weight; walls (distributor) %s x weight, by the "
              "momentum budget; max cell solids fraction %.3f; the model's "
              "field at most %.4f at every step"
              % (args.label, res["t0"], res["t1"], res["ratio"], res["std"],
                 res["error"], res["packing"], "-" if res["walls"] is None
                 else "%.4f" % res["walls"], res["maxCell"], res["maxField"]))
        if res["travel"]:
            print("%s: the parcels moved a median %.1f mm/s between %g and "
                  "%g s" % (args.label, 1e3*res["travel"][2],
                            res["travel"][0], res["travel"][1]))
    if args.plot:
        plot(res, args.case, args.label)
    return 0


if __name__ == "__main__":
    sys.exit(main())
