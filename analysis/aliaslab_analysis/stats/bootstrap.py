"""A seeded bootstrap of the median over scenes: reproducible (fixed seed), stated on the page.

interval(values) resamples the scenes' values with replacement N_BOOT times with numpy's default
generator seeded SEED and returns the 2.5 % and 97.5 % quantiles of the resampled medians (a 95 %
percentile interval). With one scene the interval is that scene's value.
"""
import numpy as np

SEED = 29
N_BOOT = 2000
LEVEL = 0.95


def interval(values, seed=SEED, n_boot=N_BOOT, level=LEVEL):
    """(low, high) of the percentile bootstrap interval of the median of `values` (NaN dropped)."""
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    if len(v) == 0:
        return np.nan, np.nan
    if len(v) == 1:
        return float(v[0]), float(v[0])
    rng = np.random.default_rng(seed)
    idx = rng.integers(0, len(v), size=(n_boot, len(v)))
    medians = np.median(v[idx], axis=1)
    a = (1 - level) / 2
    return float(np.quantile(medians, a)), float(np.quantile(medians, 1 - a))
