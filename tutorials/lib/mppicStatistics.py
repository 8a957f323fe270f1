"""Statistics of the tutorials' results scripts, re-exported by mppicPost
(post.percentile, ...):
    percentile(values, q)              linear between order statistics
    mean_and_error(series, block)      mean, std and the standard error of
                                       the mean from block means
    block_means(series, width)         (mid-time, mean) of a [(t, v)] series
                                       in consecutive blocks of width s
    interpolate(xs, ys, x)             linear, None outside [xs[0], xs[-1]]
    window_mean(pairs, t0, t1)         mean of [(t, v)] over t0 <= t <= t1
    fit_line(points)                   least-squares slope and intercept
    fit_through_origin(points)         least-squares slope of y = a*x
"""
import math

import numpy as np


def percentile(values, q):
    """The q-th percentile, linear between order statistics (numpy's
    default); nan for no values."""
    if len(values) == 0:
        return float("nan")
    return float(np.percentile(np.asarray(values, dtype=float), q))


def mean_and_error(series, block):
    """Mean, standard deviation and the standard error of the mean of a
    [(t, value)] series, the error from the means of consecutive blocks of
    the given duration (nan with fewer than two blocks)."""
    t = np.array([s[0] for s in series], dtype=float)
    v = np.array([s[1] for s in series], dtype=float)
    mean, std = float(v.mean()), float(v.std())
    dt = (t[-1] - t[0])/max(len(v) - 1, 1)
    size = max(1, int(round(block/dt)))
    nBlocks = len(v)//size
    if nBlocks < 2:
        return mean, std, float("nan")
    means = v[:nBlocks*size].reshape(nBlocks, size).mean(axis=1)
    spread = math.sqrt(((means - mean)**2).sum()/(nBlocks - 1))
    return mean, std, spread/math.sqrt(nBlocks)


def block_means(series, width):
    """(mid-time, mean) of a [(t, value)] series in consecutive blocks of
    the given duration from its first time (empty blocks left out)."""
    blocks = {}
    for t, v in series:
        blocks.setdefault(int((t - series[0][0])/width), []).append(v)
    return [(series[0][0] + (k + 0.5)*width, sum(v)/len(v))
            for k, v in sorted(blocks.items())]


def interpolate(xs, ys, x):
    """ys at x, linear in xs (ascending); None outside [xs[0], xs[-1]]."""
    if x < xs[0] or x > xs[-1]:
        return None
    return float(np.interp(x, xs, ys))


def window_mean(pairs, t0, t1):
    """Mean of the values v of [(t, v)] with t0 <= t <= t1 (to 1e-12) that
    are not None, and their count; (nan, 0) if none."""
    v = [x for t, x in pairs if t0 - 1e-12 <= t <= t1 + 1e-12 and x is not None]
    return (sum(v)/len(v), len(v)) if v else (float("nan"), 0)


def fit_line(points):
    """Least-squares line through [(x, y)]: (slope, intercept); slope 0
    where the x do not vary."""
    n = len(points)
    mx = sum(x for x, _ in points)/n
    my = sum(y for _, y in points)/n
    sxx = sum((x - mx)**2 for x, _ in points)
    slope = sum((x - mx)*(y - my) for x, y in points)/sxx if sxx > 0 else 0.0
    return slope, my - slope*mx


def fit_through_origin(points):
    """Least-squares a of y = a*x through [(x, y)]; nan where all x = 0."""
    sxx = sum(x*x for x, _ in points)
    return sum(x*y for x, y in points)/sxx if sxx > 0 else float("nan")
