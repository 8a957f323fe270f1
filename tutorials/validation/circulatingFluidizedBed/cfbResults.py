#!/usr/bin/python3
"""Measurements of the circulating fluidized bed (tutorials/validation/circulatingFluidizedBed).

Usage:
    cfbResults.py [case] [--from T0] [--to T1] [--plot] [--mesh] [--record FILE]

Reads the case's postProcessing tables and logs and prints, over the window
[T0, T1] (default: the second half of the run):
  - riser pressure drop, Pa: rho_air*(p(0.282, 0.05) - p(0.282, 1.19)),
    probes riser005 and riser119 on the riser axis (p is kinematic);
  - standpipe pressure drop, Pa: rho_air*(p(0.0727, 0.16) - p(0.0727, 0.90)),
    probes standpipe016 and standpipe090 on the standpipe axis;
  - the loop's pressure balance, standpipe = riser + top + bottom: the top
    p(riser119) - p(standpipe090) (the riser's cap, the crossover, the
    cyclone), the bottom p(standpipe016) - p(riser005) (the L-valve); these
    four also as medians over the steps (for runs whose taps spike);
  - standpipe inventory height: the top of the region where the solids
    fraction on the standpipe axis (cell values every 4 mm, every 0.02 s),
    averaged over 2 cm, exceeds 0.3; given as the level y (above the riser
    inlet plane y = 0, the bottom of the loop) and above the top of the bend
    (y = 0.146, where the straight standpipe starts); and the packed-
    equivalent height above 0.146 from the solids volume in the standpipe
    cellZone, V_s/(0.6*A), A the zone's volume over its length 0.786 m;
  - solids in the riser, kg (solids volume of the riser cellZone x 860);
  - solids circulation, kg/s: net mass of parcels down through the
    standpipe plane y = 0.20 (particleCollector standpipeFlux) and along
    the crossover (crossoverFlux), from the accumulated masses at the write
    times in the window;
  - mass lost through the gas outlet, kg (localInteraction's outlet escape
    count), the cloud mass and parcels (packingMonitor), their sum against
    the injected mass, and the largest cell solids fraction of the window;
  - wall time per simulated second (the solver log's ClockTime).
--mesh prints the mesh figures (checkMesh, cell volumes, a parcel's share of
a cell). --plot draws cfb_history.png, --geometry cfb_geometry.png (the
patches, pressure taps, collector planes and the initial inventory box). The same numbers come from summary()
for the regression test.
--record FILE writes the validation matrix's record of the run (cfbRecord.py:
case cfb-<N>, N the operating case of constant/operatingConditions; the
pressure drops and the level against the experiment), and --plot then names
its plot cfb_case<N>_history.png.
"""
import argparse
import glob
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import cfbRecord  # noqa: E402 (beside this file)
# the case's constants (beside this file; cfbPlots reads them there too)
from cfbData import (CLOSE_PACK, HEIGHT_AVERAGE, HEIGHT_THRESHOLD,  # noqa: E402
                     RHO_P, STANDPIPE_LENGTH, STANDPIPE_Y0, TAPS)


def time_dirs(path):
    """Start-time subdirectories of a postProcessing folder, in order (a
    continued run writes one per start)."""
    dirs = [d for d in glob.glob(os.path.join(path, "*")) if os.path.isdir(d)]
    return sorted(dirs, key=lambda d: float(os.path.basename(d)))


def series(path, name):
    """A postProcessing table over all start times (restarts), by time."""
    out = {}
    for d in time_dirs(path):
        f = os.path.join(d, name)
        if os.path.isfile(f):
            for r in post.read_table(f):
                out[r[0]] = r
    return [out[t] for t in sorted(out)]


def solver_log(case):
    for name in ("log.mppicPimpleFoam", "log.cfbSolver"):
        p = os.path.join(case, name)
        if os.path.isfile(p):
            return p
    logs = glob.glob(os.path.join(case, "log.*Foam*"))
    return logs[0] if logs else None


def wall_time(case):
    """(simulated time, clock time) of the solver log: the time simulated
    since the log's start time (a restart), and the clock time of its end."""
    path = solver_log(case)
    if not path:
        return None, None
    text = open(path, errors="replace").read()
    times = re.findall(r"^Time = (\S+)", text, re.M)
    clocks = re.findall(r"ClockTime = (\S+) s", text)
    if not times or not clocks:
        return None, None
    # the first step's time minus its step: the start time of the log
    deltas = re.findall(r"^deltaT = (\S+)", text, re.M)
    start = max(float(times[0]) - (float(deltas[0]) if deltas else 0.0), 0.0)
    return float(times[-1]) - start, float(clocks[-1])


def injected(case):
    """Parcels and mass the injectors added (last report of the log)."""
    path = solver_log(case)
    if not path:
        return None, None
    text = open(path, errors="replace").read()
    n = re.findall(r"- parcels added\s+=\s+(\d+)", text)
    m = re.findall(r"- mass introduced\s+=\s+(\S+)", text)
    # one line per injector and report: sum the injectors of the last report
    injectors = len(re.findall(r"^\s+Injector \S+:", text[:text.index("Parcel fate")],
                               re.M)) if "Parcel fate" in text else 1
    injectors = max(injectors, 1)
    return (sum(int(v) for v in n[-injectors:]),
            math.fsum(float(v) for v in m[-injectors:]))


def outlet_escapes(case):
    """(time, parcels, mass) escaped through the outlet, per step."""
    path = glob.glob(os.path.join(case, "postProcessing", "lagrangian", "*",
                                  "patchInteractionModel"))
    if not path:
        return []
    out = []
    for d in time_dirs(path[0]):
        f = os.path.join(d, "localInteraction.dat")
        if not os.path.isfile(f):
            continue
        header = [l for l in open(f) if l.startswith("# Time")][0]
        names = header[1:].split()
        i_n = names.index("outlet_nEscape_0")
        i_m = names.index("outlet_massEscape_0")
        for r in post.read_table(f):
            out.append((r[0], r[i_n], r[i_m]))
    out.sort()
    return out


def zone_volume(path):
    for line in open(path):
        m = re.match(r"# Volume\s*:\s*(\S+)", line)
        if m:
            return float(m.group(1))
    return None


def standpipe_heights(case):
    """(time, level y of the inventory's top) from the axis profiles."""
    out = []
    base = os.path.join(case, "postProcessing", "standpipeProfile")
    for d in time_dirs(base) if os.path.isdir(base) else []:
        f = glob.glob(os.path.join(d, "standpipeAxis_*.xy"))
        if not f:
            continue
        prof = post.read_table(f[0])
        ys = [r[0] for r in prof]
        al = [r[1] for r in prof]
        dy = ys[1] - ys[0]
        half = max(1, int(round(0.5*HEIGHT_AVERAGE/dy)))
        level = None
        for i in range(len(ys) - 1, -1, -1):
            window = al[max(0, i - half):i + half + 1]
            if sum(window)/len(window) > HEIGHT_THRESHOLD:
                level = ys[i]
                break
        out.append((float(os.path.basename(d)), level))
    return out


def collector(case, name):
    """(write time, accumulated net mass) of a particleCollector."""
    path = os.path.join(case, "postProcessing", "lagrangian", "kinematicCloud", name)
    if not os.path.isdir(path):
        return []
    return [(r[0], r[2]) for r in series(path, "particleCollector.dat")]


def rate(pairs, t0, t1):
    """Slope of an accumulated mass between the first and last write times
    of the window (kg/s)."""
    p = [(t, m) for t, m in pairs if t0 - 1e-12 <= t <= t1 + 1e-12]
    if len(p) < 2:
        return float("nan")
    return (p[-1][1] - p[0][1])/(p[-1][0] - p[0][0])


def mass_balance(case, mon, esc):
    """The seeded mass, 0.6 x the seeded region's volume x 860 kg/m3
    (constant/seededParcels: solidsVolume, full precision), and the largest
    |cloud + escaped - seeded|/seeded over the monitor's steps (escapes
    matched by time; the log prints the injected mass to writePrecision
    digits only)."""
    path = os.path.join(case, "constant", "seededParcels")
    if not os.path.isfile(path) or not mon:
        return float("nan"), float("nan")
    seeded = float(post.dict_entry(path, "solidsVolume"))*RHO_P
    lost = {round(t, 9): m for t, n, m in esc}
    worst, last = 0.0, 0.0
    for r in mon:
        last = lost.get(round(r[0], 9), last)
        worst = max(worst, abs((r[2] + last)/seeded - 1))
    return seeded, worst


def summary(case=".", t0=None, t1=None):
    rho = float(post.dict_entry(os.path.join(case, "constant", "transportProperties"),
                           "rho.air"))
    probes = series(os.path.join(case, "postProcessing", "pressureTaps"), "p")
    mon = series(os.path.join(case, "postProcessing", "packingMonitor"),
                 "packingMonitor.dat")
    tEnd = mon[-1][0] if mon else 0.0
    if t1 is None:
        t1 = tEnd
    if t0 is None:
        t0 = 0.5*t1
    res = {"t0": t0, "t1": t1, "tEnd": tEnd, "rhoGas": rho}

    def drop(upstream, downstream):
        """(time, Pa) of p(upstream tap) - p(downstream tap), every step."""
        return [(r[0], rho*(r[1 + TAPS[upstream]] - r[1 + TAPS[downstream]]))
                for r in probes]

    riser, stand = drop("riser005", "riser119"), drop("standpipe016", "standpipe090")
    res["riserDp"], _ = post.window_mean(riser, t0, t1)
    res["standpipeDp"], _ = post.window_mean(stand, t0, t1)
    res["riserDpSeries"], res["standpipeDpSeries"] = riser, stand
    # The loop's balance: standpipe = riser + top + bottom, the top the riser's
    # cap, crossover and cyclone (riser119 -> standpipe090), the bottom the
    # L-valve (riser005 -> standpipe016, the bend's and leg's gain less loss)
    top, bottom = drop("riser119", "standpipe090"), drop("standpipe016", "riser005")
    res["loopTopDp"], _ = post.window_mean(top, t0, t1)
    res["loopBottomDp"], _ = post.window_mean(bottom, t0, t1)
    # medians too: the taps of a run with pressure spikes (mfixSnider)
    res["tapMedians"] = [post.percentile([v for t, v in x if t0 - 1e-12 <= t <= t1 + 1e-12], 50)
                         for x in (riser, stand, top, bottom)]

    inv = {}
    for zone in ("Riser", "Standpipe"):
        path = os.path.join(case, "postProcessing", "inventory" + zone)
        d = time_dirs(path)
        vol = zone_volume(os.path.join(d[0], "volFieldValue.dat")) if d else None
        s = series(path, "volFieldValue.dat")
        inv[zone] = (vol, [(r[0], r[1]) for r in s])
    res["riserMassSeries"] = [(t, v*RHO_P) for t, v in inv["Riser"][1]]
    res["riserMass"], _ = post.window_mean(res["riserMassSeries"], t0, t1)
    area = inv["Standpipe"][0]/STANDPIPE_LENGTH if inv["Standpipe"][0] else float("nan")
    res["standpipeArea"] = area
    res["packedHeightSeries"] = [(t, v/(CLOSE_PACK*area)) for t, v in inv["Standpipe"][1]]
    res["packedHeight"], _ = post.window_mean(res["packedHeightSeries"], t0, t1)

    levels = standpipe_heights(case)
    res["levelSeries"] = levels
    res["level"], res["nLevels"] = post.window_mean(levels, t0, t1)
    res["heightAboveBend"] = res["level"] - STANDPIPE_Y0

    res["standpipeFluxSeries"] = collector(case, "standpipeFlux")
    res["crossoverFluxSeries"] = collector(case, "crossoverFlux")
    res["circulationStandpipe"] = rate(res["standpipeFluxSeries"], t0, t1)
    res["circulationCrossover"] = rate(res["crossoverFluxSeries"], t0, t1)

    esc = outlet_escapes(case)
    res["escapeSeries"] = esc
    res["massLost"] = esc[-1][2] if esc else 0.0
    res["parcelsLost"] = int(esc[-1][1]) if esc else 0
    res["monitor"] = mon
    res["cloudMass"] = mon[-1][2] if mon else float("nan")
    res["parcels"] = int(mon[-1][1]) if mon else 0
    res["maxAlphaCell"] = max((r[4] for r in mon if t0 - 1e-12 <= r[0] <= t1 + 1e-12),
                              default=float("nan"))
    res["maxAlphaCellAll"] = max((r[4] for r in mon), default=float("nan"))
    res["maxFastParcels"] = max((r[7] for r in mon), default=0)
    res["injectedParcels"], res["injectedMass"] = injected(case)
    res["seededMass"], res["massBalanceWorst"] = mass_balance(case, mon, esc)

    tSim, clock = wall_time(case)
    res["wallPerSimSecond"] = clock/tSim if tSim else float("nan")
    res["clock"] = clock
    return res


def mesh_figures(case="."):
    """Cells and checkMesh quality, cell volumes, a parcel's share."""
    out = {}
    log = os.path.join(case, "log.checkMesh")
    text = open(log).read()
    def grab(pattern):
        m = re.search(pattern, text)
        return float(m.group(1)) if m else float("nan")
    out["cells"] = int(grab(r"cells:\s+(\d+)"))
    out["maxNonOrtho"] = grab(r"non-orthogonality Max: (\S+)")
    out["avgNonOrtho"] = grab(r"non-orthogonality Max: \S+ average: (\S+)")
    out["maxSkewness"] = grab(r"Max skewness = (\S+)")
    out["maxAspectRatio"] = grab(r"Max aspect ratio = (\S+)")
    out["meshOK"] = "Mesh OK." in text
    out["cellSize"] = None
    m = re.search(r"-setnumber cellSize (\S+)", open(os.path.join(case, "log.gmsh")).read()) \
        if os.path.isfile(os.path.join(case, "log.gmsh")) else None
    if m:
        out["cellSize"] = float(m.group(1))
    V = sorted(post.internal_field(os.path.join(case, "0", "V")))
    out["volume"] = math.fsum(V)
    out["minV"], out["medianV"], out["maxV"] = V[0], V[len(V)//2], V[-1]
    seeded = os.path.join(case, "constant", "seededParcels")
    d = float(post.dict_entry(os.path.join(case, "system", "mppicSeedParcelsDict"), "diameter"))
    W = float(post.dict_entry(os.path.join(case, "system", "mppicSeedParcelsDict"),
                         "statisticalWeight"))
    out["statisticalWeight"] = W
    out["nParticle"] = float(post.dict_entry(seeded, "nParticle"))
    out["nParcels"] = int(float(post.dict_entry(seeded, "nParcels")))
    vp = out["nParticle"]*math.pi/6*d**3
    out["parcelVolume"] = vp
    out["parcelOverMedianCell"] = vp/out["medianV"]
    out["parcelOverSmallestCell"] = vp/out["minV"]
    out["cellsAbove5pc"] = sum(1 for v in V if vp/v > 0.05)
    vp4 = 4*math.pi/6*d**3
    out["parcel4OverMedianCell"] = vp4/out["medianV"]
    out["parcel4OverSmallestCell"] = vp4/out["minV"]
    return out


def print_mesh(m):
    print("mesh: cellSize %s m, %d tetrahedra, volume %.4e m3, checkMesh %s"
          % (m["cellSize"], m["cells"], m["volume"], "OK" if m["meshOK"] else "FAILED"))
    print("  max non-orthogonality %.1f deg (average %.1f), max skewness %.2f, "
          "max aspect ratio %.1f" % (m["maxNonOrtho"], m["avgNonOrtho"],
                                     m["maxSkewness"], m["maxAspectRatio"]))
    print("  cell volume: smallest %.3g, median %.3g, largest %.3g m3"
          % (m["minV"], m["medianV"], m["maxV"]))
    print("  parcels: %d of %.4g particles (statistical weight %g), parcel volume %.3g m3"
          % (m["nParcels"], m["nParticle"], m["statisticalWeight"], m["parcelVolume"]))
    print("  one parcel = %.2f %% of the median cell, %.2f %% of the smallest; "
          "%d cells where it is above 5 %%"
          % (100*m["parcelOverMedianCell"], 100*m["parcelOverSmallestCell"],
             m["cellsAbove5pc"]))
    print("  at weight 4 (seed 2): %.2f %% of the median cell, %.2f %% of the smallest"
          % (100*m["parcel4OverMedianCell"], 100*m["parcel4OverSmallestCell"]))


def print_summary(r):
    print("window %.3g-%.3g s (run to %.4g s)" % (r["t0"], r["t1"], r["tEnd"]))
    print("  riser pressure drop (y 0.05-1.19 m)       %8.1f Pa" % r["riserDp"])
    print("  standpipe pressure drop (y 0.16-0.90 m)   %8.1f Pa" % r["standpipeDp"])
    print("  loop balance: standpipe = riser + top (y 1.19 riser -> 0.90 standpipe:"
          " %.1f Pa)\n                + bottom (y 0.05 riser -> 0.16 standpipe: %.1f Pa)"
          % (r["loopTopDp"], r["loopBottomDp"]))
    print("  medians over the steps: riser %.1f, standpipe %.1f, top %.1f, bottom %.1f Pa"
          % tuple(r["tapMedians"]))
    print("  standpipe inventory level (axis, > 0.3)   %8.3f m  (%.3f m above the bend, "
          "%d profiles)" % (r["level"], r["heightAboveBend"], r["nLevels"]))
    print("  packed-equivalent height above the bend   %8.3f m" % r["packedHeight"])
    print("  solids in the riser                       %8.4f kg" % r["riserMass"])
    print("  circulation, standpipe plane y = 0.20     %8.4f kg/s" % r["circulationStandpipe"])
    print("  circulation, crossover plane              %8.4f kg/s" % r["circulationCrossover"])
    print("  mass lost through the outlet (to %.4g s)  %.6g kg (%d parcels)"
          % (r["tEnd"], r["massLost"], r["parcelsLost"]))
    print("  cloud mass %.12g kg, parcels %d; injected %s kg, %s parcels"
          % (r["cloudMass"], r["parcels"], r["injectedMass"], r["injectedParcels"]))
    if r["injectedMass"]:
        print("  (cloud + lost)/injected - 1 = %.3g; against the seeded %.12g kg, largest "
              "over the steps %.3g" % ((r["cloudMass"] + r["massLost"])/r["injectedMass"] - 1,
                                       r["seededMass"], r["massBalanceWorst"]))
    print("  largest cell solids fraction: %.4f in the window, %.4f over the run"
          % (r["maxAlphaCell"], r["maxAlphaCellAll"]))
    print("  wall time per simulated second            %8.0f s" % r["wallPerSimSecond"])


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("case", nargs="?", default=".")
    p.add_argument("--from", dest="t0", type=float)
    p.add_argument("--to", dest="t1", type=float)
    p.add_argument("--plot", action="store_true")
    p.add_argument("--mesh", action="store_true")
    p.add_argument("--geometry", action="store_true",
                   help="draw cfb_geometry.png (patches, taps, planes) and stop")
    p.add_argument("--record", metavar="FILE",
                   help="write the validation matrix's record to FILE")
    a = p.parse_args(argv)
    # the plots module is imported here only (it imports cfbData, not this
    # module): --geometry and --plot
    if a.geometry:
        import cfbPlots
        cfbPlots.plot_geometry(a.case, os.path.join(a.case, "cfb_geometry.png"))
        print("wrote cfb_geometry.png")
        return
    if a.mesh:
        print_mesh(mesh_figures(a.case))
    r = summary(a.case, a.t0, a.t1)
    print_summary(r)
    plots = []
    if a.plot:
        import cfbPlots
        # the matrix's cases share the folder of records: named by the case
        name = ("cfb_case%d_history.png" % cfbRecord.operating_case(a.case)
                if a.record else "cfb_history.png")
        cfbPlots.plot(r, os.path.join(a.case, name))
        print("wrote " + name)
        plots.append(name)
    cfbRecord.write(a.record, r, a.case, plots)


if __name__ == "__main__":
    main(sys.argv[1:])
