"""Degenerate configurations: methods whose error is not a trade-off but a breakdown, so that charts mark them
and keep them out of colour scales and axis ranges (they stay in every table and ranking, as they are).

The rule, read from the CSV alone: a row is degenerate when its error against the target is not finite or
exceeds FACTOR (1000) times the median error of its (scene, spp, target) group. In the presented study these
are the filters with negative lobes squeezed into a small radius (Lanczos, Hann, Catmull-Rom, Mitchell at
r = 0.5, some at r = 1), whose sums of weights come near zero in some pixels: salt-and-pepper, not ringing.
A legitimately blurry method (the box at r = 2, about 100x the median) stays well below the factor.
"""
import numpy as np

FACTOR = 1000.0
RULE = f"error above {FACTOR:g}x the median of its scene and spp (weight sums near zero)"


def mask(df, column="error"):
    """Boolean array, True for the degenerate rows of df (rule above)."""
    keys = [k for k in ("scene", "spp", "target") if k in df.columns]
    v = df[column].to_numpy(dtype=float)
    med = df.groupby(keys, sort=False)[column].transform("median").to_numpy(dtype=float) if keys else np.nanmedian(v)
    with np.errstate(invalid="ignore"):
        return ~np.isfinite(v) | (v > FACTOR * np.abs(med))
