"""Heavy tails: a row whose error is carried by one seed (docs/science.md "Answers a practitioner can act on").

Rule. With the K per-seed errors x_1..x_K of a row (mse_target_seeds; each is one image's mean squared error
against the target, so their sum is the row's summed squared error), the row is *heavy-tailed* when
    max_k x_k  >  SHARE_FACTOR / K  *  sum_k x_k        (SHARE_FACTOR = 2),
that is, when its largest seed carries more than twice an equal share of the summed error (the largest seed is
above twice the mean). Needs K >= MIN_SEEDS and a positive sum; a row without per-seed values is never flagged.

Why this rule. A per-seed error is a mean over the image's pixels and channels, so for a sound estimator it
varies little from seed to seed (in the presented study committed at 3d442ac the median relative sd over the
seeds is 0.65 %) and the largest of 8 seeds is near 1/8 of the sum; twice that needs a seed at more than twice
the mean, far beyond any such spread (it would need a relative sd of about 0.7). A filter whose weight sums come
near zero in a few pixels instead gives one seed a spike: in that study 1927 of the 1969 rows above the rule are
Lanczos, Hann, Catmull-Rom or Mitchell at r <= 1, 41 more Lanczos or Hann at r = 2 (still a squeezed three-lobe
sinc), one Blackman-Harris at r = 0.5. The other test the issue names, mean against median over seeds,
cannot see one wild seed: K - 1 equal seeds and one D above them move the mean from the median by D / K, and
the standard error is D / K too, so one outlier of any size is exactly one standard error from the median,
while a sound row's (mean - median) exceeds one standard error in about 9 % of rows by chance (its sd is about
0.76 se for a normal sample). So it is not used.

What follows. The normal standard error of such a row is meaningless (one seed sets it): its interval comes
from a bootstrap over seeds (stats/effect.py), and it is never equivalent to the best, whatever its interval.
The sweep's own flag (mse_target < 2 se) and its "unstable" kind (stats/flags.py) are kept as they are.
"""
import numpy as np

SHARE_FACTOR = 2.0
MIN_SEEDS = 4


def largest_share(values):
    """max_k x_k / sum_k x_k (NaN when the sum is not positive)."""
    v = np.asarray(values, dtype=float)
    total = v.sum()
    return float(v.max() / total) if len(v) and total > 0 else np.nan


def heavy(values):
    """True when the per-seed values `values` (or None) are heavy-tailed (module doc)."""
    if values is None or len(values) < MIN_SEEDS:
        return False
    share = largest_share(values)
    return bool(np.isfinite(share) and share > SHARE_FACTOR / len(values))


def flags(df):
    """A boolean per row of a loaded study (its `seed_values`): heavy-tailed."""
    if "seed_values" not in df.columns:
        return np.zeros(len(df), dtype=bool)
    return np.array([heavy(v) for v in df["seed_values"]], dtype=bool)
