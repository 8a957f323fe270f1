"""The Kuipers central-jet bed's constants and the readers that
kuipersJetResults.py (the numbers) and kuipersJetPlots.py (their figures)
both use: the cell solids fraction and its grid over the depth, and the
seed's profiles (kuipersJetProfiles.csv) with the mean |difference| from
them. kuipersJetPlots imports these from here, not from kuipersJetResults,
so that kuipersJetResults --plot can import kuipersJetPlots without an
import cycle; kuipersJetResults keeps them as its own names too."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
from mppicPost import internal_field, interpolate  # noqa: E402 (tutorials/lib)

WIDTH, DEPTH, G = 0.57, 0.015, 9.81
CLOSE_PACK, AXIS = 0.62, 0.285
CELL_VOLUME = 0.0075*0.01*0.0075


def solids_field(case, time, mean=False):
    """Cell solids fraction: alpha.kinematicCloud[Mean], else 1 - alpha.air."""
    suffix = "Mean" if mean else ""
    path = os.path.join(case, time, "alpha.kinematicCloud" + suffix)
    if os.path.exists(path):
        return internal_field(path)
    path = os.path.join(case, time, "alpha.air" + suffix)
    if os.path.exists(path):
        return [1 - a for a in internal_field(path)]
    return None


def cell_grid(case):
    """Cell centres -> (column, row) indices, the x and y of the columns/rows."""
    centres = internal_field(os.path.join(case, "0", "C"))
    xs = sorted(set(round(c[0], 7) for c in centres))
    ys = sorted(set(round(c[1], 7) for c in centres))
    ix = {x: i for i, x in enumerate(xs)}
    iy = {y: j for j, y in enumerate(ys)}
    return [(ix[round(c[0], 7)], iy[round(c[1], 7)]) for c in centres], xs, ys


def to_grid(values, cells, nx, ny):
    """Average over the depth: grid[j][i]."""
    total = [[0.0]*nx for _ in range(ny)]
    count = [[0]*nx for _ in range(ny)]
    for v, (i, j) in zip(values, cells):
        total[j][i] += v
        count[j][i] += 1
    return [[t/max(c, 1) for t, c in zip(tr, cr)] for tr, cr in zip(total, count)]


def csv_rows(name):
    """Rows of a csv file beside this script (comment lines skipped)."""
    return [line.strip().split(",") for line in open(os.path.join(HERE, name))
            if line.strip() and not line.startswith("#")][1:]


def reference_profiles():
    data = {}
    for src, x, h, e in csv_rows("kuipersJetProfiles.csv"):
        data.setdefault((src, float(x)), []).append((float(h)/100, float(e)))
    return {k: sorted(v) for k, v in data.items()}


def mean_abs_difference(h, eps, measured):
    diffs = [abs(v - e) for hm, e in measured
             for v in [interpolate(h, eps, hm)] if v is not None]
    return sum(diffs)/len(diffs) if diffs else float("nan")
