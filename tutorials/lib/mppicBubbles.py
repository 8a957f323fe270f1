"""Bubbles of a bubbling bed, from the gas fraction sampled at regular times
on the front and back walls of a thin bed (a `surfaces` function object of
type patch, raw format, interpolate false: each face carries its cell's
value), and the bed's pressure-drop signal.

    read_slices(case, name, field)     times, cell-centre xs and ys, and the
                                       gas fraction eps[k, l, j, i] at time
                                       k in layer l (a sampled z: the front
                                       and the back wall), row j (height
                                       ys[j]), column i
    bed_heights(ys, eps, level)        each time's bed height: where the
                                       row-mean solids fraction falls
                                       through level, from the top
    find_bubbles(eps_k, xs, ys, top)   the bubbles of one time: connected
                                       regions (edge neighbours) of cells
                                       above the void threshold below top
    track(prev, curr, dt, cell)        rise velocities of the bubbles found
                                       again at the next time
    bubble_statistics(...)             all of it over a window, a dict
    darton_diameter(U, Umf, h)         Darton et al.'s bubble diameter
    two_phase_bubble_fraction(...)     two-phase theory's bubble fraction
    pressure_signal(times, values)     standard deviation, spectrum and its
                                       dominant frequency
    diameter_profile(bubbles, edges)   mean equivalent diameter per height
                                       band
    plot_diameters(path, ...)          bubble diameter against height,
                                       beside reference curves
    plot_snapshots(path, runs, times)  pictures of the gas fraction

Definitions (the usual ones of image analysis of pseudo-2D beds):
    - a cell is void at gas fraction > threshold (0.8);
    - a bubble is a connected region of void cells; its equivalent diameter
      is that of the circle of its area, D = sqrt(4 A/pi), its height the
      centroid's;
    - the bed height is where the row-mean solids fraction falls through
      surfaceFraction (0.1) from the top, linear between the rows' centres;
    - only cells below top = topShare (0.8) x the window's mean bed height
      count (the splash zone is not a bubble);
    - the bubble fraction is the share of those cells that are void; the
      coherent share counts only bubbles of at least minCells (3) cells;
    - a bubble at the next time is the same one when its centroid is the
      nearest within a bubble diameter, not more than one cell lower, its
      area within a factor of 3: its rise velocity is the centroid's
      vertical displacement over the interval.
"""
import glob
import math
import os

import numpy as np

import mppicPost as post

THRESHOLD = 0.8
SURFACE_FRACTION = 0.1
TOP_SHARE = 0.8
MIN_CELLS = 3


# * * * * * * * * * * * * * * * * * Reading  * * * * * * * * * * * * * * * * #

def read_slices(case, name="bubbleSlices", field="alpha.air", digits=7):
    """(times, xs, ys, eps) from postProcessing/<name>/<t>/<field>_*.raw
    (every surface of a time, its faces binned by rounded (x, y, z)); eps
    has shape (times, layers, rows, columns), a layer per sampled z (the
    front and the back wall), ascending in time, z, y and x."""
    folders = glob.glob(os.path.join(case, "postProcessing", name, "*"))
    times, frames = [], []
    for folder in sorted(folders, key=lambda f: float(os.path.basename(f))):
        points = []
        for path in glob.glob(os.path.join(folder, field + "_*.raw")):
            data = np.loadtxt(path, comments="#", ndmin=2)
            if data.size:
                points.append(data)
        if points:
            times.append(float(os.path.basename(folder)))
            frames.append(np.round(np.vstack(points), digits))
    if not frames:
        raise IOError("no %s samples under %s"
                      % (field, os.path.join(case, "postProcessing", name)))
    axes = [np.unique(frames[0][:, d]) for d in range(3)]
    shape = (len(axes[2]), len(axes[1]), len(axes[0]))
    eps = np.full((len(times),) + shape, np.nan)
    for k, data in enumerate(frames):
        i, j, l = (np.searchsorted(axes[d], data[:, d]) for d in range(3))
        if len(data) != shape[0]*shape[1]*shape[2] \
           or any((idx >= len(axes[d])).any() for d, idx in enumerate((i, j, l))):
            raise ValueError("time %g of %s: not the (x, y, z) of the first "
                             "time" % (times[k], name))
        eps[k][l, j, i] = data[:, 3]
    if np.isnan(eps).any():
        raise ValueError("%s: a face sampled twice or missing" % name)
    return np.array(times), axes[0], axes[1], eps


# * * * * * * * * * * * * * * * * The bed  * * * * * * * * * * * * * * * * * #

def bed_heights(ys, eps, level):
    """Each time's bed height: the highest height where the row-mean solids
    fraction 1 - eps (over the layers and columns) falls through level
    (mppicPost.profile_crossing); the top row's height where no row falls
    through it."""
    heights = []
    for frame in eps:
        solids = 1 - frame.reshape(-1, len(ys), frame.shape[-1]).mean(axis=(0, 2))
        h = post.profile_crossing(ys, solids, level, from_top=True)
        heights.append(float(ys[-1]) if math.isnan(h) else h)
    return np.array(heights)


# * * * * * * * * * * * * * * * * Bubbles  * * * * * * * * * * * * * * * * * #

def find_bubbles(frame, xs, ys, top, threshold=THRESHOLD):
    """The bubbles of one time's gas fraction frame[j, i]: void cells
    (eps > threshold) of the rows below top, connected through their edges.
    Returns (void cells counted, cells counted, bubbles), a bubble a dict of
    cells, area, diameter, x and y (centroid)."""
    from scipy import ndimage
    dx = float(np.diff(xs).mean()) if len(xs) > 1 else 1.0
    dy = float(np.diff(ys).mean()) if len(ys) > 1 else 1.0
    rows = ys < top
    void = (frame > threshold) & rows[:, None]
    labels, n = ndimage.label(void)
    bubbles = []
    for b in range(1, n + 1):
        j, i = np.nonzero(labels == b)
        area = len(j)*dx*dy
        bubbles.append({"cells": len(j), "area": area,
                        "diameter": math.sqrt(4*area/math.pi),
                        "x": float(xs[i].mean()), "y": float(ys[j].mean())})
    return int(void.sum()), int(rows.sum())*len(xs), bubbles


def track(prev, curr, dt, cell):
    """(diameter, rise velocity) of each bubble of prev found again in curr:
    the nearest centroid within max(its diameter, 2 cells), not more than a
    cell lower, with an area within a factor of 3."""
    pairs = []
    for b in prev:
        best, bestDistance = None, None
        for c in curr:
            distance = math.hypot(c["x"] - b["x"], c["y"] - b["y"])
            if distance > max(b["diameter"], 2*cell) \
               or c["y"] < b["y"] - cell \
               or not 1/3. <= c["area"]/b["area"] <= 3:
                continue
            if best is None or distance < bestDistance:
                best, bestDistance = c, distance
        if best is not None:
            pairs.append((0.5*(b["diameter"] + best["diameter"]),
                          (best["y"] - b["y"])/dt))
    return pairs


def bubble_statistics(times, xs, ys, eps, t0, t1,
                      surfaceFraction=SURFACE_FRACTION, threshold=THRESHOLD,
                      topShare=TOP_SHARE, minCells=MIN_CELLS):
    """The window t0 <= t <= t1's statistics over every sampled layer (each
    wall a picture, as a camera sees the front wall of a pseudo-2D bed;
    a bubble is found in one layer), a dict:
        bedHeight, bedHeightStd  the bed height (where the row-mean solids
                                 fraction falls through surfaceFraction)
                                 and its standard deviation
        top                      topShare x the mean bed height
        voidFraction             void cells below top over all cells there
        bubbleFraction           the same counting only bubbles of at least
                                 minCells cells
        bubblesPerFrame          such bubbles per time and layer
        meanDiameter, largest    their mean and largest equivalent diameter
        bubbles                  each such bubble (with its time "t")
        rise                     (diameter, rise velocity) pairs
        frames                   the times used"""
    use = [k for k, t in enumerate(times) if t0 - 1e-9 <= t <= t1 + 1e-9]
    if not use:
        raise ValueError("no sampled time in [%g, %g]" % (t0, t1))
    heights = bed_heights(ys, eps[use], surfaceFraction)
    top = topShare*float(heights.mean())
    cell = float(np.diff(ys).mean())
    void = cells = coherent = 0
    found, rise = [], []
    for layer in range(eps.shape[1]):
        previous = None
        for k in use:
            nVoid, nCells, bubbles = find_bubbles(eps[k, layer], xs, ys, top,
                                                  threshold)
            void += nVoid
            cells += nCells
            large = [dict(b, t=float(times[k]), layer=layer) for b in bubbles
                     if b["cells"] >= minCells]
            coherent += sum(b["cells"] for b in large)
            found += large
            if previous is not None:
                rise += track(previous[1], large, times[k] - previous[0],
                              cell)
            previous = (times[k], large)
    diameters = [b["diameter"] for b in found]
    return {"bedHeight": float(heights.mean()),
            "bedHeightStd": float(heights.std()),
            "top": top,
            "voidFraction": void/cells,
            "bubbleFraction": coherent/cells,
            "bubblesPerFrame": len(found)/(len(use)*eps.shape[1]),
            "meanDiameter": float(np.mean(diameters)) if diameters
            else float("nan"),
            "largest": max(diameters) if diameters else float("nan"),
            "bubbles": found, "rise": rise,
            "frames": [float(times[k]) for k in use]}


def diameter_profile(bubbles, edges):
    """(band mid-heights, mean diameters, bubble counts) of the bubbles
    whose centroid lies in each band [edges[n], edges[n+1]); nan where a
    band holds none."""
    mids, means, counts = [], [], []
    for lo, hi in zip(edges[:-1], edges[1:]):
        inside = [b["diameter"] for b in bubbles if lo <= b["y"] < hi]
        mids.append(0.5*(lo + hi))
        means.append(float(np.mean(inside)) if inside else float("nan"))
        counts.append(len(inside))
    return np.array(mids), np.array(means), np.array(counts)


# * * * * * * * * * * * * * * * Correlations * * * * * * * * * * * * * * * * #

def darton_diameter(U, Umf, h, orificeArea=0.0, g=9.81):
    """Darton, LaNauze, Davidson & Harrison (1977, Trans. IChemE 55, 274):
    the mean bubble diameter at height h of a freely bubbling bed,
        D = 0.54 (U - Umf)^0.4 (h + 4 sqrt(A0))^0.8 / g^0.2   [SI],
    A0 the distributor area per orifice (0: a porous plate). A correlation
    of three-dimensional beds' data."""
    h = np.asarray(h, dtype=float)
    return 0.54*(U - Umf)**0.4*(h + 4*math.sqrt(orificeArea))**0.8/g**0.2


def two_phase_bubble_fraction(U, Umf, epsMf, D, g=9.81):
    """The bubble fraction of two-phase theory (Kunii & Levenspiel 1991,
    Fluidization Engineering, ch. 6): the bubbles carry the gas beyond
    minimum fluidization at u_b = U - Umf + 0.711 sqrt(g D); with the
    emulsion's gas velocity u_e = Umf/eps_mf,
        delta = (U - Umf)/(u_b + 2 Umf)   u_b < u_e
                (U - Umf)/(u_b + Umf)     u_e <= u_b < 3 u_e
                (U - Umf)/u_b             3 u_e <= u_b < 5 u_e
                (U - Umf)/(u_b - Umf)     5 u_e <= u_b.
    Returns (delta, u_b)."""
    ub = U - Umf + 0.711*math.sqrt(g*D)
    ratio = ub/(Umf/epsMf)
    if ratio < 1:
        delta = (U - Umf)/(ub + 2*Umf)
    elif ratio < 3:
        delta = (U - Umf)/(ub + Umf)
    elif ratio < 5:
        delta = (U - Umf)/ub
    else:
        delta = (U - Umf)/(ub - Umf)
    return delta, ub


# * * * * * * * * * * * * * * The pressure signal  * * * * * * * * * * * * * #

def pressure_signal(times, values):
    """(standard deviation, frequencies, power spectral density, dominant
    frequency) of a signal sampled at (nearly) uniform times: the
    periodogram of the signal less its mean, Hann-windowed; the dominant
    frequency is the spectrum's peak above the lowest two frequencies."""
    t = np.asarray(times, dtype=float)
    v = np.asarray(values, dtype=float)
    dt = (t[-1] - t[0])/max(len(t) - 1, 1)
    x = (v - v.mean())*np.hanning(len(v))
    psd = np.abs(np.fft.rfft(x))**2*dt/len(v)
    f = np.fft.rfftfreq(len(v), dt)
    peak = 2 + int(np.argmax(psd[2:])) if len(psd) > 2 else 0
    return float(v.std()), f, psd, float(f[peak])


# * * * * * * * * * * * * * * * * * Plots  * * * * * * * * * * * * * * * * * #

def plot_diameters(path, runs, references=(), title=None, top=None):
    """Bubble equivalent diameter against height: for each run (label,
    bubbles, band edges) its bubbles as dots and its band means as a line;
    each reference (label, heights, diameters) as a dashed line."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 4.5))
    for n, (label, bubbles, edges) in enumerate(runs):
        colour = "C%d" % n
        ax.plot([b["y"] for b in bubbles],
                [1e3*b["diameter"] for b in bubbles], ".", ms=2,
                color=colour, alpha=0.3)
        mids, means, counts = diameter_profile(bubbles, edges)
        ax.plot(mids, 1e3*means, "o-", color=colour,
                label="%s (%d bubble%s)"
                % (label, len(bubbles), "" if len(bubbles) == 1 else "s"))
    for n, (label, heights, diameters) in enumerate(references):
        ax.plot(heights, 1e3*np.asarray(diameters), "--", color="k",
                alpha=1 - 0.3*n, label=label)
    if top is not None:
        ax.axvline(top, color="0.6", lw=0.8)
    ax.set_xlabel("height above the distributor [m]")
    ax.set_ylabel("bubble equivalent diameter [mm]")
    if title:
        ax.set_title(title, fontsize=10)
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_snapshots(path, runs, times, top=None, title=None):
    """The first sampled layer's gas fraction at the sampled times nearest
    the given ones, a row of pictures per run (label, xs, ys, sampled
    times, eps), up to top (default the sampled height)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(len(runs), len(times), squeeze=False,
                             figsize=(1.2*len(times) + 0.8, 2.8*len(runs)))
    for r, (label, xs, ys, sampled, eps) in enumerate(runs):
        dx, dy = xs[1] - xs[0], ys[1] - ys[0]
        extent = [xs[0] - dx/2, xs[-1] + dx/2, ys[0] - dy/2, ys[-1] + dy/2]
        for c, t in enumerate(times):
            k = int(np.argmin(np.abs(np.asarray(sampled) - t)))
            ax = axes[r, c]
            image = ax.imshow(eps[k, 0], origin="lower", extent=extent,
                              vmin=0.35, vmax=1, cmap="viridis")
            ax.set_ylim(extent[2], top or extent[3])
            ax.set_xticks([])
            ax.set_title("%s\n%.2f s" % (label, sampled[k]), fontsize=7)
            if c:
                ax.set_yticks([])
            else:
                ax.set_ylabel("height [m]", fontsize=8)
                ax.tick_params(labelsize=7)
    fig.colorbar(image, ax=axes, shrink=0.8, label="gas fraction")
    if title:
        fig.suptitle(title, fontsize=9)
    fig.savefig(path, dpi=110)
    plt.close(fig)
