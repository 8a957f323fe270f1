#!/usr/bin/python3
"""Measurements of the circulating fluidized bed (tutorials/circulatingFluidizedBed).

Usage:
    cfbResults.py [case] [--from T0] [--to T1] [--plot] [--mesh]

Reads the case's postProcessing tables and logs and prints, over the window
[T0, T1] (default: the second half of the run):
  - riser pressure drop, Pa: rho_air*(p(0.282, 0.05) - p(0.282, 1.19)),
    probes riser005 and riser119 on the riser axis (p is kinematic);
  - standpipe pressure drop, Pa: rho_air*(p(0.0727, 0.16) - p(0.0727, 0.90)),
    probes standpipe016 and standpipe090 on the standpipe axis;
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
"""
import argparse
import glob
import math
import os
import re
import sys

RHO_P = 860.0            # HDPE, kg/m3 (constant/kinematicCloudProperties)
CLOSE_PACK = 0.6
STANDPIPE_Y0 = 0.146     # top of the bend, bottom of the straight standpipe
STANDPIPE_LENGTH = 0.932 - 0.146
HEIGHT_THRESHOLD = 0.3   # solids fraction at the inventory's top
HEIGHT_AVERAGE = 0.02    # m, running mean along the axis
TAPS = {"riser005": 0, "riser119": 4, "standpipe016": 5, "standpipe090": 8}


def rows(path):
    """Rows of numbers of a whitespace table, '#' comments skipped."""
    out = []
    for line in open(path):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        try:
            out.append([float(v) for v in line.split()])
        except ValueError:
            continue
    return out


def time_dirs(path):
    """Start-time subdirectories of a postProcessing folder, in order."""
    dirs = [d for d in glob.glob(os.path.join(path, "*")) if os.path.isdir(d)]
    return sorted(dirs, key=lambda d: float(os.path.basename(d)))


def series(path, name):
    """A postProcessing table over all start times (restarts), by time."""
    out = {}
    for d in time_dirs(path):
        f = os.path.join(d, name)
        if os.path.isfile(f):
            for r in rows(f):
                out[r[0]] = r
    return [out[t] for t in sorted(out)]


def dict_value(path, key):
    m = re.search(r"^\s*" + re.escape(key) + r"\s+([^;]+);", open(path).read(), re.M)
    return m.group(1).strip() if m else None


def internal_field(path):
    """Values of a volScalarField/volVectorField file (ascii)."""
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\((.*?)\n\)",
                  text, re.S)
    if m.group(1) == "scalar":
        return [float(v) for v in m.group(3).split()]
    return [tuple(map(float, t)) for t in
            re.findall(r"\(([-\d.eE+]+) ([-\d.eE+]+) ([-\d.eE+]+)\)", m.group(3))]


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
        for r in rows(f):
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
        prof = rows(f[0])
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


def window_mean(pairs, t0, t1):
    v = [x for t, x in pairs if t0 - 1e-12 <= t <= t1 + 1e-12 and x is not None]
    return (sum(v)/len(v), len(v)) if v else (float("nan"), 0)


def rate(pairs, t0, t1):
    """Slope of an accumulated mass between the first and last write times
    of the window (kg/s)."""
    p = [(t, m) for t, m in pairs if t0 - 1e-12 <= t <= t1 + 1e-12]
    if len(p) < 2:
        return float("nan")
    return (p[-1][1] - p[0][1])/(p[-1][0] - p[0][0])


def summary(case=".", t0=None, t1=None):
    rho = float(dict_value(os.path.join(case, "constant", "transportProperties"),
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

    riser = [(r[0], rho*(r[1 + TAPS["riser005"]] - r[1 + TAPS["riser119"]]))
             for r in probes]
    stand = [(r[0], rho*(r[1 + TAPS["standpipe016"]] - r[1 + TAPS["standpipe090"]]))
             for r in probes]
    res["riserDp"], _ = window_mean(riser, t0, t1)
    res["standpipeDp"], _ = window_mean(stand, t0, t1)
    res["riserDpSeries"], res["standpipeDpSeries"] = riser, stand

    inv = {}
    for zone in ("Riser", "Standpipe"):
        path = os.path.join(case, "postProcessing", "inventory" + zone)
        d = time_dirs(path)
        vol = zone_volume(os.path.join(d[0], "volFieldValue.dat")) if d else None
        s = series(path, "volFieldValue.dat")
        inv[zone] = (vol, [(r[0], r[1]) for r in s])
    res["riserMassSeries"] = [(t, v*RHO_P) for t, v in inv["Riser"][1]]
    res["riserMass"], _ = window_mean(res["riserMassSeries"], t0, t1)
    area = inv["Standpipe"][0]/STANDPIPE_LENGTH if inv["Standpipe"][0] else float("nan")
    res["standpipeArea"] = area
    res["packedHeightSeries"] = [(t, v/(CLOSE_PACK*area)) for t, v in inv["Standpipe"][1]]
    res["packedHeight"], _ = window_mean(res["packedHeightSeries"], t0, t1)

    levels = standpipe_heights(case)
    res["levelSeries"] = levels
    res["level"], res["nLevels"] = window_mean(levels, t0, t1)
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
    V = sorted(internal_field(os.path.join(case, "0", "V")))
    out["volume"] = math.fsum(V)
    out["minV"], out["medianV"], out["maxV"] = V[0], V[len(V)//2], V[-1]
    seeded = os.path.join(case, "constant", "seededParcels")
    d = float(dict_value(os.path.join(case, "system", "mppicSeedParcelsDict"), "diameter"))
    W = float(dict_value(os.path.join(case, "system", "mppicSeedParcelsDict"),
                         "statisticalWeight"))
    out["statisticalWeight"] = W
    out["nParticle"] = float(dict_value(seeded, "nParticle"))
    out["nParcels"] = int(float(dict_value(seeded, "nParcels")))
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
    print("  standpipe inventory level (axis, > 0.3)   %8.3f m  (%.3f m above the bend, "
          "%d profiles)" % (r["level"], r["heightAboveBend"], r["nLevels"]))
    print("  packed-equivalent height above the bend   %8.3f m" % r["packedHeight"])
    print("  solids in the riser                       %8.4f kg" % r["riserMass"])
    print("  circulation, standpipe plane y = 0.20     %8.4f kg/s" % r["circulationStandpipe"])
    print("  circulation, crossover plane              %8.4f kg/s" % r["circulationCrossover"])
    print("  mass lost through the outlet (to %.4g s)  %.6g kg (%d parcels)"
          % (r["tEnd"], r["massLost"], r["parcelsLost"]))
    print("  cloud mass %.10g kg, parcels %d; injected %s kg, %s parcels"
          % (r["cloudMass"], r["parcels"], r["injectedMass"], r["injectedParcels"]))
    if r["injectedMass"]:
        print("  (cloud + lost)/injected - 1 = %.3g"
              % ((r["cloudMass"] + r["massLost"])/r["injectedMass"] - 1))
    print("  largest cell solids fraction: %.4f in the window, %.4f over the run"
          % (r["maxAlphaCell"], r["maxAlphaCellAll"]))
    print("  wall time per simulated second            %8.0f s" % r["wallPerSimSecond"])


def plot(r, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(5, 1, figsize=(8, 13), sharex=True)
    t, v = zip(*r["riserDpSeries"])
    ax[0].plot(t, v, lw=0.5, label="riser (y 0.05-1.19)")
    t, v = zip(*r["standpipeDpSeries"])
    ax[0].plot(t, v, lw=0.5, label="standpipe (y 0.16-0.90)")
    ax[0].set_ylabel("pressure drop [Pa]")
    ax[0].set_ylim(-500, 3000)
    ax[0].legend(loc="upper right")
    lv = [(t, y) for t, y in r["levelSeries"] if y is not None]
    if lv:
        t, v = zip(*lv)
        ax[1].plot(t, v, ".", ms=3, label="level y, axis profile > 0.3")
    t, v = zip(*r["packedHeightSeries"])
    ax[1].plot(t, [h + STANDPIPE_Y0 for h in v], lw=1,
               label="0.146 + packed-equivalent height")
    ax[1].set_ylabel("standpipe level [m]")
    ax[1].legend(loc="upper right")
    t, v = zip(*r["riserMassSeries"])
    ax[2].plot(t, v, lw=1)
    ax[2].set_ylabel("solids in riser [kg]")
    for key, label in (("standpipeFluxSeries", "down the standpipe (y 0.20)"),
                       ("crossoverFluxSeries", "through the crossover")):
        if r[key]:
            t, v = zip(*r[key])
            ax[3].plot(t, v, "o-", ms=3, label=label)
    ax[3].set_ylabel("accumulated solids [kg]")
    ax[3].legend(loc="upper left")
    mon = r["monitor"]
    ax[4].plot([x[0] for x in mon], [x[4] for x in mon], lw=0.5, label="max cell solids fraction")
    ax[4].axhline(CLOSE_PACK, color="k", ls=":", lw=0.8)
    ax[4].set_ylabel("max cell eps_s")
    ax[4].set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def plot_geometry(case, path):
    """Boundary face centres by patch (x-y and z-y views), with the pressure
    taps, the collector planes and the inventory box."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def body(f):
        t = open(f).read()
        t = t[t.index("}", t.index("FoamFile")) + 1:]
        return re.sub(r"//.*", "", t)
    mesh = os.path.join(case, "constant", "polyMesh")
    P = [tuple(map(float, t)) for t in re.findall(
        r"\(([-\d.eE+]+) ([-\d.eE+]+) ([-\d.eE+]+)\)", body(os.path.join(mesh, "points")))]
    F = [list(map(int, f.split())) for f in
         re.findall(r"\d+\(([\d ]+)\)", body(os.path.join(mesh, "faces")))]
    patches = re.findall(r"(\w+)\s*\{[^}]*nFaces\s+(\d+);\s*startFace\s+(\d+);",
                         body(os.path.join(mesh, "boundary")))
    colours = {"walls": "0.75", "riserInlet": "tab:blue", "outlet": "tab:red",
               "aerationStandpipe": "tab:green", "aerationBend": "tab:purple"}
    fig, ax = plt.subplots(1, 2, figsize=(7.5, 12), gridspec_kw={"width_ratios": [2.13, 1]})
    for name, nf, sf in patches:
        nf, sf = int(nf), int(sf)
        cs = [tuple(sum(P[i][k] for i in F[f])/len(F[f]) for k in range(3))
              for f in range(sf, sf + nf)]
        size = 0.3 if name == "walls" else 10
        ax[0].scatter([c[0] for c in cs], [c[1] for c in cs], s=size,
                      c=colours.get(name, "k"), label=name)
        ax[1].scatter([c[2] for c in cs], [c[1] for c in cs], s=size,
                      c=colours.get(name, "k"))
    taps = [(0.282, 0.05), (0.282, 1.19), (0.0727, 0.16), (0.0727, 0.90)]
    ax[0].plot([t[0] for t in taps], [t[1] for t in taps], "k^", ms=6,
               label="pressure taps (dP)")
    ax[0].plot([0.0527, 0.0927], [0.20, 0.20], "r-", lw=2, label="standpipe collector")
    ax[0].plot([0.1783, 0.1874], [1.218, 1.218], "m-", lw=2, label="crossover collector")
    ax[0].add_patch(matplotlib.patches.Rectangle((0.045, 0), 0.2, 0.932, fill=False,
                                                 ls="--", lw=0.8, label="initial inventory box"))
    for a in ax:
        a.set_aspect("equal")
    ax[0].set_xlabel("x [m]")
    ax[0].set_ylabel("y [m]")
    ax[1].set_xlabel("z [m]")
    ax[0].legend(loc="center", bbox_to_anchor=(0.55, 0.55), fontsize=7, markerscale=2)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("case", nargs="?", default=".")
    p.add_argument("--from", dest="t0", type=float)
    p.add_argument("--to", dest="t1", type=float)
    p.add_argument("--plot", action="store_true")
    p.add_argument("--mesh", action="store_true")
    p.add_argument("--geometry", action="store_true",
                   help="draw cfb_geometry.png (patches, taps, planes) and stop")
    a = p.parse_args(argv)
    if a.geometry:
        plot_geometry(a.case, os.path.join(a.case, "cfb_geometry.png"))
        print("wrote cfb_geometry.png")
        return
    if a.mesh:
        print_mesh(mesh_figures(a.case))
    r = summary(a.case, a.t0, a.t1)
    print_summary(r)
    if a.plot:
        plot(r, os.path.join(a.case, "cfb_history.png"))
        print("wrote cfb_history.png")


if __name__ == "__main__":
    main(sys.argv[1:])
