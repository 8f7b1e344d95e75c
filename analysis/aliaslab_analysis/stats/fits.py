"""The log-log slope fit (as lib's fitLogLogSlope) and the Pareto front (both axes minimised)."""
import math

import numpy as np

# A slope needs this many spp levels (two points always fit a line exactly).
MIN_SLOPE_LEVELS = 3


def slope_or_none(n, y):
    """The log-log slope of y against n when at least MIN_SLOPE_LEVELS distinct n have y > 0, else None."""
    n = np.asarray(n, dtype=float)
    y = np.asarray(y, dtype=float)
    ok = np.isfinite(y) & (y > 0) & (n > 0)
    if len(np.unique(n[ok])) < MIN_SLOPE_LEVELS:
        return None
    return fit_loglog_slope(n[ok], y[ok])[0]


def fit_loglog_slope(n, y, n_min=None, n_max=None, powers_of_two_only=False):
    """Least squares of log y on log n over n_min <= n <= n_max (and y > 0).
    Returns (slope, intercept, slope_standard_error, points); raises
    ValueError with fewer than two usable points or a single distinct n.
    Same definition as fitLogLogSlope in lib/measure/convergence.h."""
    n = np.asarray(n, dtype=float)
    y = np.asarray(y, dtype=float)
    keep = np.isfinite(y) & (y > 0) & (n > 0)
    if n_min is not None:
        keep &= n >= n_min
    if n_max is not None:
        keep &= n <= n_max
    if powers_of_two_only:
        with np.errstate(divide="ignore"):
            l2 = np.log2(np.where(n > 0, n, 1))
        keep &= np.abs(l2 - np.round(l2)) < 1e-9
    lx, ly = np.log(n[keep]), np.log(y[keep])
    if len(lx) < 2:
        raise ValueError("fewer than two points in the N range")
    sxx = float(np.sum((lx - lx.mean()) ** 2))
    if sxx <= 0:
        raise ValueError("every point has the same N")
    slope = float(np.sum((lx - lx.mean()) * (ly - ly.mean())) / sxx)
    intercept = float(ly.mean() - slope * lx.mean())
    se = 0.0
    if len(lx) > 2:
        rss = float(np.sum((ly - intercept - slope * lx) ** 2))
        se = math.sqrt(rss / (len(lx) - 2) / sxx)
    return slope, intercept, se, int(len(lx))


def pareto_front(x, y):
    """Indices of the points no other point beats in both x and y (both
    minimised), sorted by x. A point equal to another in both is kept once."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    order = np.lexsort((y, x))
    front, best = [], math.inf
    for i in order:
        if y[i] < best:
            front.append(int(i))
            best = y[i]
    return front
