"""Plots of the Kuipers central-jet bed's results (kuipersJetResults.py
--plot): kuipersJet_<label>_{pressureDrop,packing,profiles,snapshots,
slabs,packingForce}.png in the case. It takes kuipersJetResults.summary()'s
dict as an argument and its readers and constants from kuipersJetData.py:
it does not import kuipersJetResults, which imports it (inside main() only,
for --plot)."""
import os

import kuipersJetData as k
import kuipersJetSlabs as slabs
from mppicPost import time_dirs  # (tutorials/lib: kuipersJetData puts it on the path)

# the runs' lines (green and black are the seed's curves)
RUN_COLOURS = ("b", "tab:orange", "tab:red", "tab:purple", "tab:brown", "tab:cyan")


def plot_profiles(runs, name):
    """The time-averaged profiles of each run, [(label, {3.4: (h, eps),
    6.4: ...})], against Kuipers' points and MFiX-PIC's (seed 1 Fig. 6),
    with each run's mean |difference| from Kuipers' points, into name."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ref = k.reference_profiles()
    fig, axes = plt.subplots(1, 2, figsize=(9, 4), sharey=True)
    for ax, x_cm in zip(axes, (3.4, 6.4)):
        m = ref[("kuipers1990", x_cm)]
        p = ref[("mfix_pic", x_cm)]
        ax.plot([v[0] for v in p], [v[1] for v in p], "g-", lw=1,
                label="MFiX-PIC (seed 1 Fig. 6)")
        ax.plot([v[0] for v in m], [v[1] for v in m], "ko", ms=3,
                label="Kuipers (1990), measured")
        for (label, profiles), colour in zip(runs, RUN_COLOURS):
            if x_cm in profiles:
                h, eps = profiles[x_cm]
                ax.plot(h, eps, colour, lw=1.5, label="%s, MAD %.3f" % (
                    label, k.mean_abs_difference(h, eps, m)))
        ax.set_title("%.1f cm from the jet axis" % x_cm)
        ax.set_xlabel("height [m]")
        ax.set_xlim(0, 0.8)
        ax.legend(fontsize=7)
    axes[0].set_ylabel("time-averaged solids fraction")
    fig.tight_layout()
    fig.savefig(name, dpi=90)
    plt.close(fig)


def plot(res, case, label):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = []

    def save(fig, what):
        name = os.path.join(case, "kuipersJet_%s_%s.png" % (label, what))
        fig.tight_layout()
        fig.savefig(name, dpi=90)
        plt.close(fig)
        names.append(name)

    if res["dp"] and "weight" in res:
        fig, ax = plt.subplots(figsize=(8, 3.5))
        ax.plot([r[0] for r in res["dp"]], [r[3] for r in res["dp"]], lw=0.6,
                label="%s, inlet to outlet" % label)
        ax.axhline(res["weight"], color="k", lw=1, label="bed weight %.0f Pa"
                   % res["weight"])
        if "dpMean" in res:
            ax.hlines(res["dpMean"], res["t0"], res["endTime"], color="r",
                      label="mean from %g s: %.3f x weight" % (res["t0"],
                                                             res["dpRatio"]))
        ax.axhline(0.916*res["weight"], color="g", ls="--", lw=0.8,
                   label="MFiX-PIC mean 20-24 s (0.916 x)")
        for source, colour in (("mfix_pic", "g"), ("mfix_tfm", "m")):
            dps = [float(r[2])*1000
                   for r in k.csv_rows("kuipersJetPressureDrop.csv")
                   if r[0] == source]
            ax.axhspan(min(dps), max(dps), color=colour, alpha=0.12,
                       label="%s 20-24 s, range (seed 1 Fig. 7)" % source)
        ax.set_xlabel("t [s]")
        ax.set_ylabel("bed pressure drop [Pa]")
        ax.legend(fontsize=7)
        save(fig, "pressureDrop")

    if res["monitor"]:
        fig, ax = plt.subplots(figsize=(8, 3.5))
        ax.plot([r[0] for r in res["monitor"]], [r[4] for r in res["monitor"]],
                lw=0.6, label="max cell solids fraction")
        ax.axhline(k.CLOSE_PACK, color="k", lw=0.8, label="close pack 0.62")
        ax.axhline(res["bound"], color="r", lw=0.8, label="bound %.3f"
                   % res["bound"])
        ax.set_xlabel("t [s]")
        ax.set_ylabel("solids fraction")
        ax.set_title(label)
        ax.legend(fontsize=7)
        save(fig, "packing")

    if res["profiles"]:
        names.append(os.path.join(case, "kuipersJet_%s_profiles.png" % label))
        plot_profiles([(label, res["profiles"])], names[-1])

    if "grid" in res:
        cells, xs, ys = res["grid"]
        shots = [name for t, name in time_dirs(case) if t > 0][-4:]
        panels = [(n, k.solids_field(case, n)) for n in shots]
        panels = [(n, f) for n, f in panels if f is not None]
        if "meanGrid" in res:
            panels.append(("mean", None))
        if panels:
            fig, axes = plt.subplots(1, len(panels), figsize=(2.2*len(panels) + 1, 4.4),
                                     squeeze=False, constrained_layout=True)
            extent = (0, k.WIDTH, 0, ys[-1] + 0.5*(ys[1] - ys[0]))
            for ax, (name, field) in zip(axes[0], panels):
                grid = res["meanGrid"][1] if field is None else \
                    k.to_grid(field, cells, len(xs), len(ys))
                im = ax.imshow(grid, origin="lower", extent=extent, vmin=0,
                               vmax=0.65, cmap="viridis", aspect="equal")
                rows = None if field is None else slabs.slab_rows(grid)
                for row, colour in zip(rows or (), ("r", "w")):
                    ax.axhline(ys[row], color=colour, lw=0.8, ls="--")
                ax.set_title("time average from %g s" % res["t0"]
                             if field is None else "t = %s s%s" % (
                                 name, ", slab (red) over void (white)"
                                 if rows else ""), fontsize=7)
                ax.set_xlabel("x [m]", fontsize=8)
                ax.tick_params(labelsize=7)
            axes[0][0].set_ylabel("y [m]")
            fig.colorbar(im, ax=axes[0].tolist(), shrink=0.8,
                         label="solids fraction")
            fig.savefig(os.path.join(case, "kuipersJet_%s_snapshots.png" % label),
                        dpi=90)
            plt.close(fig)
            names.append(os.path.join(case, "kuipersJet_%s_snapshots.png" % label))
    if "forceGrid" in res:
        cells, xs, ys = res["grid"]
        depth = len(cells)/(len(xs)*len(ys))
        rows = [sum(r)*depth*k.CELL_VOLUME/(res["mass"][0]*k.G)
                for r in res["forceGrid"][1]]
        fig, axes = plt.subplots(1, 2, figsize=(8, 4.4),
                                 gridspec_kw={"width_ratios": [1.6, 1]})
        packed = k.CLOSE_PACK*2660*k.G
        im = axes[0].imshow([[f/packed for f in r] for r in res["forceGrid"][1]],
                            origin="lower", extent=(0, k.WIDTH, 0, ys[-1] + 0.005),
                            vmin=-0.5, vmax=0.5, cmap="RdBu_r")
        fig.colorbar(im, ax=axes[0], label="upward force / weight of a packed cell")
        axes[0].set_ylim(0, 0.8)
        axes[0].set_xlabel("x [m]")
        axes[0].set_ylabel("y [m]")
        axes[0].set_title("packing step's force, mean of %d written times"
                          % res["forceGrid"][0], fontsize=8)
        axes[1].plot(rows, ys)
        axes[1].axvline(0, color="k", lw=0.5)
        axes[1].set_ylim(0, 0.8)
        axes[1].set_xlabel("the row's force / bed weight")
        axes[1].set_title("%s: sum %.3f" % (label, sum(rows)), fontsize=8)
        save(fig, "packingForce")
    if res.get("slabFlags"):
        names.append(os.path.join(case, "kuipersJet_%s_slabs.png" % label))
        slabs.plot_slabs(res["slabFlags"], names[-1], label)
    return names
