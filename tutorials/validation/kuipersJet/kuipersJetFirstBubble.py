#!/usr/bin/python3
"""The void over the Kuipers jet's nozzle, written time by written time.

Usage:
    kuipersJetFirstBubble.py [--case DIR ...] [--label NAME] [--threshold 0.2]
                             [--plot] [--times T ...]

For a run that writes its fields often (./Allrun 0.4 -write 0.01). At each
written time, on the solids fraction averaged over the depth (0/C and
alpha.kinematicCloud or 1 - alpha.air), the void is the cells at or below
--threshold (0.2: a gas fraction of 0.8, the usual bubble boundary) under the
bed surface (the highest row whose mean exceeds 0.3). Prints:
  - the void attached to the nozzle (connected, through face neighbours, to
    the two cells over the jet): its area [m2], width and top [m], and its
    area over the jet's excess gas injected so far per depth, (10 - 0.25) m/s
    x 0.015 m x t: the share of that gas the void holds (1 without leakage
    into the bed, 0 when all of it goes through the bed);
  - the largest void below 0.45 m not attached to the nozzle (a bubble that
    has detached), the same;
  - the first detachment: the first time the attached void is gone or less
    than a quarter of its largest area so far while a detached one is
    larger, and the attached void's largest width and share before it.
--plot writes kuipersJet_<label>_firstBubble.png (label: the first case's
folder name): the solids fraction at --times (default six times up to the
first case's detachment) with the voids outlined, a row for each case.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get(
    "MPPIC_PROJECT_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..")),
    "tutorials", "lib"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kuipersJetResults as jet  # noqa: E402 (beside this file)
from mppicPost import time_dirs  # noqa: E402 (tutorials/lib)

JET_EXCESS = (10 - 0.25)*0.015      # m2/s: excess jet gas per depth


def components(mask):
    """Labels of the face-connected components of a grid mask (-1: outside)."""
    ny, nx = len(mask), len(mask[0])
    label = [[-1]*nx for _ in range(ny)]
    count = 0
    for j0 in range(ny):
        for i0 in range(nx):
            if not mask[j0][i0] or label[j0][i0] >= 0:
                continue
            label[j0][i0] = count
            stack = [(j0, i0)]
            while stack:
                j, i = stack.pop()
                for jj, ii in ((j + 1, i), (j - 1, i), (j, i + 1), (j, i - 1)):
                    if 0 <= jj < ny and 0 <= ii < nx and mask[jj][ii] \
                            and label[jj][ii] < 0:
                        label[jj][ii] = count
                        stack.append((jj, ii))
            count += 1
    return label, count


def void_size(cells, xs, ys):
    """Area, width and top of a set of (row, column) cells."""
    dx, dy = xs[1] - xs[0], ys[1] - ys[0]
    columns = [i for _, i in cells]
    return (len(cells)*dx*dy, (max(columns) - min(columns) + 1)*dx,
            ys[max(j for j, _ in cells)] + 0.5*dy)


def voids(grid, xs, ys, threshold):
    """The attached and the largest detached void (cell lists, maybe empty)."""
    ny, nx = len(grid), len(grid[0])
    dense = [j for j in range(ny) if sum(grid[j])/nx > 0.3]
    surface = max(dense) if dense else -1
    mask = [[j <= surface and grid[j][i] <= threshold for i in range(nx)]
            for j in range(ny)]
    label, count = components(mask)
    nozzle = {label[0][nx//2 - 1], label[0][nx//2]} - {-1}
    members = [[] for _ in range(count)]
    for j in range(ny):
        for i in range(nx):
            if label[j][i] >= 0:
                members[label[j][i]].append((j, i))
    attached = [c for k in nozzle for c in members[k]]
    detached = [m for k, m in enumerate(members) if k not in nozzle
                and ys[max(j for j, _ in m)] < 0.45]
    return attached, max(detached, key=len) if detached else []


def history(case, threshold):
    """[(time name, t, grid, attached, detached)] over the written times."""
    cells, xs, ys = jet.cell_grid(case)
    out = []
    for t, name in time_dirs(case):
        values = jet.solids_field(case, name) if t > 0 else None
        if values is None:
            continue
        grid = jet.to_grid(values, cells, len(xs), len(ys))
        attached, detached = voids(grid, xs, ys, threshold)
        out.append((name, t, grid, attached, detached))
    return out, xs, ys


def first_detachment(rows):
    """Index of the first detachment, the attached void's largest area."""
    largest = 0.0
    for k, (_, _, _, attached, detached) in enumerate(rows):
        if largest > 0 and len(detached) > len(attached) \
                and len(attached) < 0.25*largest:
            return k, largest
        largest = max(largest, len(attached))
    return None, largest


def plot(runs, xs, ys, names, out):
    """Rows of snapshots at the written times names, one row a run."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    fig, axes = plt.subplots(len(runs), len(names),
                             figsize=(2.1*len(names) + 1, 2.9*len(runs)),
                             sharey=True, squeeze=False)
    extent = (0, jet.WIDTH, 0, ys[-1] + 0.5*(ys[1] - ys[0]))
    for axrow, (label, rows) in zip(axes, runs):
        byname = {r[0]: r for r in rows}
        for ax, name in zip(axrow, names):
            ax.tick_params(labelsize=6)
            if name not in byname:
                ax.set_axis_off()
                continue
            _, _, grid, attached, detached = byname[name]
            image = ax.imshow(np.array(grid), origin="lower", extent=extent,
                              vmin=0, vmax=jet.CLOSE_PACK, aspect="auto")
            for members, colour in ((attached, "w"), (detached, "r")):
                if members:
                    mask = np.zeros((len(ys), len(xs)))
                    for j, i in members:
                        mask[j, i] = 1
                    ax.contour(xs, ys, mask, levels=[0.5], colors=colour,
                               linewidths=0.7)
            ax.set_ylim(0, 0.7)
            ax.set_title("%s, t = %s s" % (label, name), fontsize=7)
        axrow[0].set_ylabel("y [m]", fontsize=7)
    for ax in axes[-1]:
        ax.set_xlabel("x [m]", fontsize=7)
    fig.colorbar(image, ax=axes.ravel().tolist(), shrink=0.8, label="solids fraction")
    fig.suptitle("The void on the nozzle (white) and detached (red), solids fraction"
                 " <= threshold", fontsize=9)
    fig.savefig(out, dpi=90)
    print("wrote %s" % out)


def report(rows, xs, ys, threshold):
    """Print the history and the first detachment; its index (or None)."""
    print("# t [s] | attached: area [m2] width [m] top [m] share of the jet's gas"
          " | detached: area width top   (void: solids fraction <= %g)" % threshold)
    for _, t, _, attached, detached in rows:
        line = "%6.3f |" % t
        if attached:
            a, w, top = void_size(attached, xs, ys)
            line += " %.4f %.3f %.2f %.2f |" % (a, w, top, a/(JET_EXCESS*t))
        else:
            line += " - - - - |"
        line += (" %.4f %.3f %.2f" % void_size(detached, xs, ys)) if detached else " -"
        print(line)

    k, _ = first_detachment(rows)
    before = [r for r in (rows[:k] if k is not None else rows) if r[3]]
    widths = [void_size(r[3], xs, ys)[1] for r in before]
    shares = [void_size(r[3], xs, ys)[0]/(JET_EXCESS*r[1]) for r in before]
    if k is not None:
        print("first detachment: %.3f s; before it the attached void was at most "
              "%.3f m wide, holding %.2f-%.2f of the jet's excess gas over its "
              "second half" % (rows[k][1], max(widths),
                               min(shares[len(shares)//2:]), max(shares[len(shares)//2:])))
    else:
        print("no detachment by %.3f s; the attached void at most %.3f m wide"
              % (rows[-1][1], max(widths) if widths else 0))
    return k


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--case", nargs="+", default=["."])
    parser.add_argument("--label", default=None)
    parser.add_argument("--threshold", type=float, default=0.2)
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--times", nargs="*", default=None)
    args = parser.parse_args()

    runs = []
    for case in args.case:
        rows, xs, ys = history(case, args.threshold)
        if not rows:
            sys.exit("no written times with a solids fraction in %s" % case)
        name = os.path.basename(os.path.abspath(case))
        print("== %s" % name)
        k = report(rows, xs, ys, args.threshold)
        runs.append((name, rows, k))

    if args.plot:
        names = args.times
        if not names:
            rows, k = runs[0][1], runs[0][2]
            end = k + 1 if k is not None else len(rows)
            step = max(1, end//6)
            names = [r[0] for r in rows[step - 1:end:step]][-6:]
        label = args.label or runs[0][0]
        plot([(n, r) for n, r, _ in runs], xs, ys, names,
             "kuipersJet_%s_firstBubble.png" % label)


if __name__ == "__main__":
    main()
