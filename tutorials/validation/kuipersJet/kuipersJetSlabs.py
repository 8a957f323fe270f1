"""Slab measure of the Kuipers central-jet bed (used by kuipersJetResults.py).

A packed slab lifted by the jet: at one instant, a row of cells (the bed's
solids fraction averaged over its depth) in which at least SLAB_WIDTH of the
width is at eps_s >= SLAB_LEVEL, above a row in which an unbroken run of
cells at eps_s <= VOID_LEVEL (a gas void) is wider than VOID_WIDTH of the
width. Kuipers saw bubbles rising through an expanded annulus, never that.

The measure is the fraction of the sampled instants in the statistics window
at which the bed holds such a slab. The instants are those of the
slabSamples function object (system/controlDict: every cell centre's
alpha.air every 0.1 s of the window), or, for runs made without it, the
written time directories.
"""
import glob
import os

SLAB_LEVEL, SLAB_WIDTH = 0.55, 0.8
VOID_LEVEL, VOID_WIDTH = 0.2, 0.5


def longest_run(row, test):
    """Length of the longest unbroken run of entries of row passing test."""
    best = run = 0
    for v in row:
        run = run + 1 if test(v) else 0
        best = max(best, run)
    return best


def slab_rows(grid):
    """(slab row, void row) of the highest slab over a void, else None.

    grid[j][i]: solids fraction of row j (upwards), column i."""
    nx = len(grid[0])
    void_rows = [j for j, row in enumerate(grid)
                 if longest_run(row, lambda v: v <= VOID_LEVEL) > VOID_WIDTH*nx]
    if not void_rows:
        return None
    for j in range(len(grid) - 1, void_rows[0], -1):
        dense = sum(1 for v in grid[j] if v >= SLAB_LEVEL)
        if dense >= SLAB_WIDTH*nx:
            below = [k for k in void_rows if k < j]
            return (j, below[-1])
    return None


def read_samples(path, nx, ny, width, height):
    """Depth-averaged grid from a raw set file of x y z alpha.air lines."""
    total = [[0.0]*nx for _ in range(ny)]
    count = [[0]*nx for _ in range(ny)]
    for line in open(path):
        parts = line.split()
        if len(parts) < 4 or line.startswith("#"):
            continue
        x, y, gas = float(parts[0]), float(parts[1]), float(parts[3])
        i = min(nx - 1, max(0, int(x/width*nx)))
        j = min(ny - 1, max(0, int(y/height*ny)))
        total[j][i] += 1 - gas
        count[j][i] += 1
    return [[t/max(c, 1) for t, c in zip(tr, cr)]
            for tr, cr in zip(total, count)]


def sample_grids(case, t0, shape, width, height):
    """[(t, grid)] from postProcessing/slabSamples, t >= t0."""
    out = []
    nx, ny = shape
    for d in glob.glob(os.path.join(case, "postProcessing", "slabSamples", "*")):
        try:
            t = float(os.path.basename(d))
        except ValueError:
            continue
        files = glob.glob(os.path.join(d, "*alpha.air*.xy"))
        if t >= t0 - 1e-9 and files:
            out.append((t, read_samples(files[0], nx, ny, width, height)))
    return sorted(out, key=lambda tg: tg[0])


def slab_measure(grids):
    """(fraction of instants with a slab, instants, [(t, rows or None)])."""
    flags = [(t, slab_rows(g)) for t, g in grids]
    if not flags:
        return None, 0, []
    n = sum(1 for _, rows in flags if rows is not None)
    return n/len(flags), len(flags), flags


def plot_slabs(flags, path, label):
    """Slab and void heights against time (empty where no slab)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 2.8))
    ts = [t for t, _ in flags]
    ax.plot(ts, [0]*len(ts), "|", color="0.6", label="sampled instants")
    hit = [(t, r) for t, r in flags if r is not None]
    if hit:
        ax.plot([t for t, _ in hit], [r[0] for _, r in hit], "rv", ms=4,
                label="slab row (>= %g of the width at eps_s >= %g)"
                % (SLAB_WIDTH, SLAB_LEVEL))
        ax.plot([t for t, _ in hit], [r[1] for _, r in hit], "b^", ms=4,
                label="void row below (> %g of the width at eps_s <= %g)"
                % (VOID_WIDTH, VOID_LEVEL))
    n = len(hit)
    ax.set_title("%s: slab at %d of %d instants (%.1f %%)"
                 % (label, n, len(flags), 100.0*n/max(len(flags), 1)),
                 fontsize=9)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("cell row")
    ax.set_ylim(-2, 100)
    ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
