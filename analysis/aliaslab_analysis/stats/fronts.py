"""The error-vs-time front with ties, and the top groups at equal time.

Cost. `cost` = cpu_ms (thread CPU time of the configuration's own work, mean over seeds) with
`cost_se` = cpu_ms_se; a CSV without them falls back to the wall time time_ms with an unknown spread
(cost_se NaN, compared as exact numbers; study_csv.load_study says so in its notes).

Front (front_mask). A row is on the front unless another row is significantly better in error and not
significantly slower:  e_i - e_j > Z se(e_i - e_j)  (ties.diff_se_matrix: paired within a sample set)
and  c_j - c_i <= Z sqrt(cse_i^2 + cse_j^2)  (an unknown cse counts as 0). With no spread at all this is
the usual Pareto front; spreads only keep more points on it (a point is dropped only on evidence). A row
whose error is not told from zero (ties.measured false) is on it only when its upper bound (e + Z se) is
below every measured row's, as in the top groups: a huge error with a huger spread is undetermined, not a
front point, while a nearly exact row stays.

Front across scenes (summary_front_mask): the same rule for (method, spp) points summarised over scenes,
where "significantly better" is a paired bootstrap over scenes of the median log ratio (its doc).

Equal time (equal_time). For a budget B (per spp level: the median cost of the scene's rows at that spp),
the candidates are the rows not significantly dearer than B (c - B <= Z cse) at any spp, and their top
group is ties.top_group of the candidates: what one can get for about that time, with ties.
"""
import warnings

import numpy as np
import pandas as pd

from . import bootstrap, ties


def rankings_deterministic(rows):
    return rows["deterministic"].to_numpy(dtype=bool) if "deterministic" in rows.columns else np.zeros(len(rows), bool)


def _spread(x):
    x = np.asarray(x, dtype=float)
    return np.where(np.isfinite(x), x, 0.0)


def front_mask(rows, z=ties.Z):
    """A boolean per row of one (scene, target): on the front with ties (module doc)."""
    err = rows["error"].to_numpy(dtype=float)
    cost = rows["cost"].to_numpy(dtype=float)
    cse = _spread(rows["cost_se"])
    se, _ = ties.diff_se_matrix(rows)
    se = np.where(np.isfinite(se), se, 0.0)
    better = (err[:, None] - err[None, :]) > z * se                      # [i, j]: j significantly better than i
    not_slower = (cost[None, :] - cost[:, None]) <= z * np.sqrt(cse[:, None] ** 2 + cse[None, :] ** 2)
    own = rows["error_se"].to_numpy(dtype=float)
    meas = ties.measured(err, own, z)
    upper = err + z * np.where(np.isfinite(own), own, 0.0)
    bound = ~meas[:, None] & meas[None, :] & (upper[None, :] < upper[:, None])
    dominated = (better & not_slower).any(axis=1) | bound.any(axis=1)
    return np.isfinite(err) & np.isfinite(cost) & ~dominated


def fronts(ranked, z=ties.Z):
    """The front rows of every (target, scene), sorted by cost, with `front_rank` 1, 2, ..."""
    parts = []
    for _, g in ranked[~rankings_deterministic(ranked)].groupby(["target", "scene"], sort=True):
        f = g[front_mask(g, z)].sort_values(["cost", "error"])
        parts.append(f.assign(front_rank=np.arange(1, len(f) + 1)))
    return pd.concat(parts) if parts else ranked.iloc[0:0].assign(front_rank=0)


CANDIDATES = 10  # dominators tested per point (those not significantly slower with the lowest medians)


def summary_front_mask(points, logs, z=ties.Z, seed=bootstrap.SEED, n_boot=bootstrap.N_BOOT):
    """The front over (method, spp) points across scenes. points: columns median_ratio, cost, cost_se
    (and deterministic); logs: points x scenes, log of each scene's ratio (NaN where absent or <= 0).
    Point i leaves the front when a point j, not significantly slower (as in front_mask) and with a lower
    median, is significantly better across scenes: the bootstrap interval (scenes resampled, the same
    resample for both: paired) of the median over scenes of log(ratio_i / ratio_j) lies wholly above 0.
    Only the CANDIDATES such j with the lowest medians (then the cheapest) are tested."""
    med = points["median_ratio"].to_numpy(dtype=float)
    cost = points["cost"].to_numpy(dtype=float)
    cse = _spread(points["cost_se"])
    ok = np.isfinite(med) & np.isfinite(cost)
    if "deterministic" in points.columns:
        ok &= ~points["deterministic"].to_numpy(dtype=bool)
    logs = np.asarray(logs, dtype=float)
    n, scenes = logs.shape if logs.ndim == 2 else (len(points), 0)
    if scenes == 0:
        return ok
    boot = np.random.default_rng(seed).integers(0, scenes, size=(n_boot, scenes))
    lower = (1 - bootstrap.LEVEL) / 2
    on = ok.copy()
    for i in np.nonzero(ok)[0]:
        slower = (cost - cost[i]) > z * np.sqrt(cse[i] ** 2 + cse ** 2)
        cand = np.nonzero(ok & ~slower & (med < med[i]))[0]
        if not len(cand):
            continue
        cand = cand[np.lexsort((cost[cand], med[cand]))[:CANDIDATES]]  # lowest median, then cheapest
        d = logs[i][None, :] - logs[cand]                     # (c, scenes)
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            m = np.nanmedian(d[:, boot], axis=2)              # (c, n_boot)
            low = np.nanquantile(m, lower, axis=1)
        if np.any(np.isfinite(low) & (low > 0)):
            on[i] = False
    return on


def budgets(scene_rows):
    """Per spp level: the median cost of the scene's rows at that spp ({spp: ms})."""
    return {int(s): float(np.nanmedian(g["cost"].to_numpy(dtype=float)))
            for s, g in scene_rows.groupby("spp", sort=True)}


def equal_time(ranked, z=ties.Z):
    """Per (target, scene, budget spp level): the candidates within the budget with the columns of
    ties.top_group; `budget_spp` and `budget_ms` name the budget."""
    parts = []
    for (target, scene), g in ranked[~rankings_deterministic(ranked)].groupby(["target", "scene"], sort=True):
        cse = _spread(g["cost_se"])
        for spp, b in budgets(g).items():
            cand = g[(g["cost"].to_numpy(dtype=float) - b) <= z * cse]
            if cand.empty:
                continue
            parts.append(ties.top_group(cand, z).assign(budget_spp=spp, budget_ms=b))
    return pd.concat(parts) if parts else ranked.iloc[0:0]


def summary_points(ranked, summary, target, method):
    """One point per (method, spp) against `target`: the across-scene record (rankings.across_scenes) with
    `cost` = the mean cost over its scenes, `cost_se` = the se of that mean (NaN when unknown) and `front`
    (summary_front_mask on the per-scene log ratios)."""
    r = ranked[ranked["target"].astype(str) == target]
    key = ["spp"] + method
    agg = r.groupby(key, dropna=False).agg(cost=("cost", "mean"), n=("cost", "size"),
                                          var=("cost_se", lambda x: float(np.sum(np.asarray(x, float) ** 2))))
    agg["cost_se"] = np.sqrt(agg["var"]) / agg["n"]
    pts = summary[summary["target"].astype(str) == target]
    if not len(pts):  # (no finite error to rank: an empty frame's key columns may not merge with agg's)
        pts = pts.assign(cost=[], cost_se=[])
    else:
        pts = pts.merge(agg.reset_index()[key + ["cost", "cost_se"]], on=key, how="left")
    if not len(pts):
        pts["front"] = []
        return pts
    with np.errstate(divide="ignore", invalid="ignore"):
        logr = np.log(np.where(r["ratio"].to_numpy(dtype=float) > 0, r["ratio"].to_numpy(dtype=float), np.nan))
    wide = r.assign(logr=logr).pivot_table(index=key, columns="scene", values="logr", aggfunc="first",
                                           dropna=False)
    logs = wide.reindex(pd.MultiIndex.from_frame(pts[key])).to_numpy(dtype=float)
    pts["front"] = summary_front_mask(pts, logs)
    return pts
