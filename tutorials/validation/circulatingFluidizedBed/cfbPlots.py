#!/usr/bin/python3
"""The circulating fluidized bed's plots, for cfbResults.py --plot and
--geometry: the histories of a summary (cfb_history.png) and the mesh's
patches with the pressure taps, collector planes and inventory box
(cfb_geometry.png). It takes the summary as an argument and the case's
constants from cfbData.py: it does not import cfbResults, which imports it
(inside main() only, for --plot and --geometry)."""
import os
import re

from cfbData import CLOSE_PACK, STANDPIPE_Y0


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
