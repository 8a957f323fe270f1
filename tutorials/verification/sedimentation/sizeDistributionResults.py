#!/usr/bin/python3
"""The sedimentation case run with a size distribution (Allrun
-sizeDistribution): the mass per size class and the packing bound.

Usage:
    sizeDistributionResults.py [--case DIR] [--check] [--plot] [--record FILE]
    sizeDistributionResults.py --volume-diameter FILE

Reads the parcels (d, nParticle, rho, coordinates) of the first written time
that holds them and of the latest, 0/V and <latest>/C (cell volumes,
centres) and
postProcessing/packingMonitor/0/packingMonitor.dat (every step). Prints:
  - per size class (20-60, 60-100, 100-140, 140-180 um): parcels, mass [kg],
    its share of the cloud's mass and its mass-weighted mean height [m], at
    the first written time and at the end; the class masses are kept (no
    parcel changes size);
  - the largest cell solids fraction over every step (packingMonitor)
    against the bound close pack + the largest parcel's volume over its
    cell's (a cell may take the parcel count nearest close pack), and the
    cells above max(1.05 alpha_cp, alpha_cp + V_parcel/V_cell) at every
    written time (mppicPost.cells_above_bound);
  - the bed height (the row mean falling through alpha_cp/2) against the
    inventory height m/(rho_p alpha_cp A).
--check: exit 1 unless the bound holds at every step and at every written
time and each class keeps its mass to 1e-12. --plot:
sizeDistribution_<packing model>.png
(each class's layer-mean solids fraction at the end). --record FILE: the
validation matrix's record (case sizeDistribution-<packing model>).
--volume-diameter FILE: the volume mean diameter (E[d^3])^(1/3) of the
normalDistribution in FILE as OpenFOAM samples it (x = expectation +
variance*erfinv(u), u uniform between the erf of the cut-offs: a normal
distribution of standard deviation variance/sqrt(2), cut at minValue and
maxValue), for the seeder (Allrun).
"""
import math
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import validationRecord as record  # noqa: E402 (tutorials/lib)
from sedimentationResults import read_monitor, bed_profile, \
    surface_height  # noqa: E402

EDGES = (20e-6, 60e-6, 100e-6, 140e-6, 180e-6 + 1e-12)
WIDTH, DEPTH = 0.05, 0.005


def volume_diameter(path):
    """(E[d^3])^(1/3) of the normalDistribution in path (module doc)."""
    text = open(path).read()

    def number(key):
        return float(re.search(r"\b%s\s+([^;\s]+)\s*;" % key, text).group(1))
    mu, v = number("expectation"), number("variance")
    lo, hi = number("minValue"), number("maxValue")
    sigma = v/math.sqrt(2)
    d = np.linspace(lo, hi, 200001)
    weight = np.exp(-0.5*((d - mu)/sigma)**2)
    return (np.trapz(weight*d**3, d)/np.trapz(weight, d))**(1/3)


def cell_centres(case):
    """The cell centres (written at the latest time by Allrun)."""
    return np.array(post.internal_field(
        os.path.join(case, post.latest_time(case), "C")))


def parcels(case, time):
    """Diameter, mass, height and cell of each parcel at a written time."""
    folder = os.path.join(case, time, "lagrangian", "kinematicCloud")
    d = np.array(post.lagrangian_field(os.path.join(folder, "d")))[:, 0]
    n = np.array(post.lagrangian_field(os.path.join(folder, "nParticle")))[:, 0]
    rho = np.array(post.lagrangian_field(os.path.join(folder, "rho")))[:, 0]
    cells, volume, _ = post.parcel_cells_volumes(case, time)
    centres = cell_centres(case)
    return dict(d=d, mass=n*rho*math.pi/6*d**3, y=centres[cells, 1],
                cells=cells, volume=volume)


def classes(p):
    """Per size class: parcels, mass, mass-weighted mean height."""
    out = []
    for lo, hi in zip(EDGES[:-1], EDGES[1:]):
        m = (p["d"] >= lo) & (p["d"] < hi)
        mass = p["mass"][m].sum()
        out.append(dict(lo=lo, hi=min(hi, EDGES[-1] - 1e-12), parcels=int(m.sum()),
                        mass=mass, height=(p["mass"][m]*p["y"][m]).sum()/mass
                        if mass > 0 else float("nan")))
    return out


def summary(case):
    close_pack, rows = read_monitor(case)
    times = [d for _, d in post.time_dirs(case)
             if os.path.exists(os.path.join(case, d, "lagrangian",
                                            "kinematicCloud", "d"))]
    first, last = parcels(case, times[0]), parcels(case, times[-1])
    volumes = np.asarray(post.internal_field(os.path.join(case, "0", "V")),
                         dtype=float)
    largest = max((p["volume"]/volumes[p["cells"]]).max()
                  for p in (first, last))
    ys, profile, dy, _, _ = bed_profile(case, times[-1])
    res = dict(close_pack=close_pack, times=(times[0], times[-1]),
               first=classes(first), last=classes(last),
               max_cell=max(r[4] for r in rows),
               most_above=max(int(r[5]) for r in rows),
               bound=close_pack + largest, largest_parcel=largest,
               written=post.cells_above_bound(case, close_pack),
               height=surface_height(ys, profile, 0.5*close_pack, dy),
               expected=last["volume"].sum()/(close_pack*WIDTH*DEPTH))
    res["class_change"] = max(abs(b["mass"]/a["mass"] - 1)
                              for a, b in zip(res["first"], res["last"])
                              if a["mass"] > 0)
    return res


def class_profiles(case, time, close_pack):
    """Layer heights and each class's layer-mean solids fraction."""
    p = parcels(case, time)
    volumes = np.asarray(post.internal_field(os.path.join(case, "0", "V")),
                         dtype=float)
    centres = cell_centres(case)
    out = []
    for lo, hi in zip(EDGES[:-1], EDGES[1:]):
        m = (p["d"] >= lo) & (p["d"] < hi)
        alpha = np.bincount(p["cells"][m], weights=p["volume"][m],
                            minlength=len(volumes))/volumes
        ys, means = post.layer_means(alpha, centres)
        out.append((lo, hi, np.array(ys), np.array(means)))
    return out


def plot(case, res, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5, 5))
    total = None
    for lo, hi, ys, means in class_profiles(case, res["times"][1],
                                            res["close_pack"]):
        ax.plot(means, ys, ".-", ms=3, label="%.0f-%.0f um" % (lo*1e6, hi*1e6))
        total = means if total is None else total + means
    ax.plot(total, ys, "k-", lw=1, label="all sizes")
    ax.axvline(res["close_pack"], color="gray", ls=":", lw=1,
               label="close pack %.2f" % res["close_pack"])
    ax.axhline(res["expected"], color="gray", ls="--", lw=1,
               label="inventory height %.4f m" % res["expected"])
    ax.set_xlabel("solids fraction (layer mean)")
    ax.set_ylabel("height y [m]")
    ax.set_ylim(0, 0.1)
    ax.set_title("Sedimentation, sizes 20-180 um, t = %s s" % res["times"][1])
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def record_rows(res):
    rows = [record.row(
        "largest cell solids fraction, every step", res["max_cell"],
        reference=res["close_pack"], reference_source="close pack",
        goal=record.at_most(res["bound"]),
        note="bound: close pack + the largest parcel over its cell (%.4f)"
        % res["largest_parcel"]),
        record.row(
            "cells above their bound, written times", res["written"]["cellsAbove"],
            reference=0, reference_source="mppicPost.cells_above_bound",
            goal=record.at_most(0)),
        record.row(
            "class masses kept (largest relative change)", res["class_change"],
            reference=0, reference_source="no parcel changes size",
            goal=record.at_most(1e-12))]
    for a, b in zip(res["first"], res["last"]):
        rows.append(record.row(
            "%.0f-%.0f um: mass share; mean height [m]"
            % (a["lo"]*1e6, a["hi"]*1e6), b["mass"]/sum(c["mass"] for c in res["last"]),
            note="%d parcels, %.4g kg; mean height %.4f m at %s s, %.4f m at %s s"
            % (b["parcels"], b["mass"], a["height"], res["times"][0],
               b["height"], res["times"][1])))
    rows.append(record.row(
        "bed height [m]", res["height"], reference=res["expected"],
        reference_source="inventory height V_solids/(alpha_cp A)",
        goal=record.within(0.03)))
    return rows


def main():
    parser = post.results_parser(None, __doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--volume-diameter", metavar="FILE")
    record.add_record_argument(parser)
    args = parser.parse_args()
    if args.volume_diameter:
        print("%.9g" % volume_diameter(args.volume_diameter))
        return 0

    res = summary(args.case)
    total = sum(c["mass"] for c in res["last"])
    print("size class [um] | parcels | mass [kg] | share | mean height [m] "
          "at %s s | at %s s" % res["times"])
    for a, b in zip(res["first"], res["last"]):
        print("%3.0f-%3.0f | %d | %.6g | %.4f | %.4f | %.4f" % (
            a["lo"]*1e6, a["hi"]*1e6, b["parcels"], b["mass"],
            b["mass"]/total, a["height"], b["height"]))
    print("class masses kept to %.2e (largest relative change)"
          % res["class_change"])
    print("largest cell solids fraction, every step: %.4f; bound %.4f "
          "(close pack %.2f + largest parcel %.4f); steps' most cells above "
          "close pack %d" % (res["max_cell"], res["bound"], res["close_pack"],
                             res["largest_parcel"], res["most_above"]))
    print("cells above their bound at the %d written times: %d (largest "
          "%.4f)" % (res["written"]["times"], res["written"]["cellsAbove"],
                     res["written"]["largest"]))
    print("bed height %.4f m, inventory height %.4f m (%+.1f %%)" % (
        res["height"], res["expected"],
        100*(res["height"]/res["expected"] - 1)))
    model = post.dict_entry(os.path.join(
        args.case, "constant", "kinematicCloudProperties"), "packingModel")
    png = "sizeDistribution_%s.png" % model
    if args.plot:
        plot(args.case, res, os.path.join(args.case, png))
        print("wrote " + os.path.join(args.case, png))
    if args.record:
        record.write(args.record, "sizeDistribution-%s" % model,
                     record_rows(res),
                     plots=[png] if args.plot else [],
                     settings=record.case_settings(args.case))
    ok = (res["max_cell"] <= res["bound"]
          and res["written"]["cellsAbove"] == 0
          and res["class_change"] <= 1e-12)
    if args.check and not ok:
        print("sizeDistributionResults: check failed", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
