"""Effect sizes with a margin of practical equivalence (docs/science.md "Answers a practitioner can act on").

In one cell (target, scene, spp) every row's error e (mse_target) is stated as a ratio R = e / e_b to a
comparator row b, with a 95 % interval, and judged against a margin delta (MARGIN = 0.10 by default):
  equivalent    the interval's upper end is below 1 + delta (a significant difference inside the margin is
                equivalent: significance is not importance);
  worse         the interval's lower end is above 1 + delta;
  undetermined  otherwise (the interval holds 1 + delta, or the error is not known well enough).
A heavy-tailed row (stats/tails.py) is never equivalent, however its interval falls. The comparator of a
cell is its *best*: the lowest error among the rows whose error is told from zero (e > 2 se, the sweep's own
flag unset) and that are not heavy-tailed; the fixed grid is ranked like any other row (deterministic: no
seed spread, its se is the references' part only). The best's own verdict is equivalent with R = 1.

The interval, by the kind of row (column `interval`):
  log     (a measured row, e > 0) on the log scale by the delta method: log R +- t sqrt(V), with
          t = Student's t quantile (0.975) at the Welch-Satterthwaite degrees of freedom of V and
          - rows of one sample set (same scene, sampler, spp, prefilter, target: they differ in filter or
            radius and were made from the same traced samples) *paired*: V_seed = var_k(x_ik / e_i - x_bk / e_b)
            / K over the K per-seed values (mse_target_seeds, whose mean is e), K - 1 degrees of freedom;
          - other rows independent: V_seed = s_i^2 / e_i^2 + s_b^2 / e_b^2 with s^2 = var_k(x_k) / K, each
            with K - 1 degrees of freedom;
          - plus the references' part, V_ref = r_i^2 / e_i^2 + r_b^2 / e_b^2 with r^2 = se^2 - s^2 (what
            mse_target_se holds beyond the seeds: the target reference's error), taken as known (infinite
            degrees of freedom). Rows of one scene share that reference, so their reference parts move
            together; adding both counts the shared part twice (conservative, never narrower).
          Why this has the right coverage: a per-seed error is a mean over many pixels, close to normal; the
          log makes the ratio's sampling distribution symmetric to first order, and t with K - 1 (Welch) degrees
          of freedom accounts for the seed variance being estimated from K = 8 values (it varies by about
          40 % between sets of seeds, so +-2 se covers about 91 %, not 95 %). analysis/tests/test_effect.py
          checks the coverage by simulation.
  bootstrap  (a heavy-tailed row, or a heavy-tailed comparator) a percentile bootstrap over seeds of
          mean(x_i) / mean(x_b): N_BOOT resamples from numpy's default_rng(BOOT_SEED), idx = integers(0, K,
          (N_BOOT, K)) for the row, the same idx for a paired comparator, a second draw of the same shape for
          an independent one with per-seed values; a deterministic comparator stays fixed.
  linear  (a row whose error is not told from zero) R +- t(K - 1) se_i / e_b: such a row is equivalent only
          when even its upper end is below 1 + delta (a reference-limited row), else undetermined.
"""
import math

import numpy as np

from . import student, tails
from .ties import measured, sample_set_ids

MARGIN = 0.10
LEVEL = 0.95
BOOT_SEED = 44
N_BOOT = 2000
EQUIVALENT, WORSE, UNDETERMINED = "equivalent", "worse", "undetermined"


def verdict(low, high, margin=MARGIN, heavy=False):
    """The verdict of a ratio interval (module doc)."""
    if not (math.isfinite(low) and math.isfinite(high)):
        return UNDETERMINED
    if low > 1 + margin:
        return WORSE
    if high < 1 + margin and not heavy:
        return EQUIVALENT
    return UNDETERMINED


class Row:
    """One row's numbers for the comparisons: error e, se, per-seed values x (or None), seed part s^2 of the
    variance of e, reference part r^2, its degrees of freedom, and flags."""

    def __init__(self, error, se, seeds, deterministic, seeds_count):
        self.e = float(error)
        self.se = float(se) if math.isfinite(se) else 0.0
        self.x = None if seeds is None else np.asarray(seeds, dtype=float)
        self.det = bool(deterministic)
        k = len(self.x) if self.x is not None else int(seeds_count)
        self.k = k
        if self.det:
            self.s2 = 0.0
        elif self.x is not None and k >= 2:
            self.s2 = float(np.var(self.x, ddof=1) / k)
        else:
            self.s2 = self.se ** 2
        self.r2 = max(self.se ** 2 - self.s2, 0.0)
        self.df = (k - 1) if (k >= 2 and not self.det) else math.inf
        self.heavy = tails.heavy(self.x) and not self.det
        self.measured = bool(measured([self.e], [se])[0]) if math.isfinite(self.e) else False


def rows_of(cell):
    cnt = cell["seeds"] if "seeds" in cell.columns else [8] * len(cell)
    return [Row(e, se, x, d, k) for e, se, x, d, k in zip(cell["error"], cell["error_se"], cell["seed_values"],
                                                       cell["deterministic"], cnt)]


def t_quantile(df):
    return student.quantile(0.5 + LEVEL / 2, df)


def log_interval(a, b, paired):
    """(low, high) of e_a / e_b on the log scale (module doc)."""
    ref = a.r2 / a.e ** 2 + b.r2 / b.e ** 2
    if paired:
        d = a.x / a.e - b.x / b.e
        seed = [float(np.var(d, ddof=1) / len(d))]
        dfs = [len(d) - 1]
    else:
        seed = [a.s2 / a.e ** 2, b.s2 / b.e ** 2]
        dfs = [a.df, b.df]
    v = sum(seed) + ref
    h = t_quantile(student.welch_df(seed + [ref], dfs + [math.inf])) * math.sqrt(v)
    c = math.log(a.e / b.e)
    return math.exp(c - h), math.exp(c + h)


def boot_interval(a, b, paired):
    """(low, high): the percentile bootstrap over seeds of mean(x_a) / mean(x_b) (module doc)."""
    rng = np.random.default_rng(BOOT_SEED)
    if a.x is None:
        return math.nan, math.nan
    idx = rng.integers(0, len(a.x), size=(N_BOOT, len(a.x)))
    top = a.x[idx].mean(axis=1)
    if paired:
        bottom = b.x[idx].mean(axis=1)
    elif b.x is not None and not b.det:
        bottom = b.x[rng.integers(0, len(b.x), size=(N_BOOT, len(b.x)))].mean(axis=1)
    else:
        bottom = np.full(N_BOOT, b.e)
    with np.errstate(divide="ignore", invalid="ignore"):
        r = top / bottom
    q = (1 - LEVEL) / 2
    return float(np.quantile(r, q)), float(np.quantile(r, 1 - q))


def compare(a, b, paired):
    """(ratio, low, high, kind) of row a against comparator b."""
    ratio = a.e / b.e
    if a.heavy or b.heavy:
        return (ratio,) + boot_interval(a, b, paired) + ("bootstrap",)
    if a.measured and a.e > 0:
        return (ratio,) + log_interval(a, b, paired) + ("log",)
    h = t_quantile(a.df) * a.se / b.e
    return ratio, ratio - h, ratio + h, "linear"


def best_index(rows, flagged):
    """The index of the cell's best row (module doc), or None."""
    ok = [i for i, r in enumerate(rows) if r.measured and r.e > 0 and not r.heavy and not flagged[i]]
    return min(ok, key=lambda i: rows[i].e) if ok else None


def versus(cell, b, margin=MARGIN):
    """The cell's rows compared with its row at position b: a copy with ratio, ci_low, ci_high, interval,
    heavy_tailed, measured, verdict."""
    cell = cell.copy()
    rows = rows_of(cell)
    ids = sample_set_ids(cell)
    out = []
    for i, a in enumerate(rows):
        if i == b:
            out.append((1.0, 1.0, 1.0, "best"))
            continue
        paired = (ids[i] == ids[b] and a.x is not None and rows[b].x is not None and len(a.x) == len(rows[b].x)
                  and not a.det and not rows[b].det)
        out.append(compare(a, rows[b], paired) if math.isfinite(a.e) else (math.nan,) * 3 + ("none",))
    cell["ratio"], cell["ci_low"], cell["ci_high"], cell["interval"] = (list(c) for c in zip(*out))
    cell["heavy_tailed"] = [r.heavy for r in rows]
    cell["measured"] = [r.measured for r in rows]
    cell["verdict"] = [verdict(lo, hi, margin, r.heavy) for lo, hi, r in zip(cell["ci_low"], cell["ci_high"], rows)]
    return cell


def cell_effects(cell, margin=MARGIN):
    """versus(cell, its best); with `best` marking it. A cell without a best gets NaN ratios, undetermined."""
    rows = rows_of(cell)
    b = best_index(rows, (cell["flagged"].to_numpy(dtype=float) == 1))
    if b is None:
        return cell.assign(ratio=np.nan, ci_low=np.nan, ci_high=np.nan, interval="none", best=False,
                           heavy_tailed=[r.heavy for r in rows], measured=[r.measured for r in rows],
                           verdict=UNDETERMINED)
    out = versus(cell, b, margin)
    out["best"] = np.arange(len(out)) == b
    return out
