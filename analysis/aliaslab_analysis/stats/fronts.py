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

Equal time (equal_time). For a budget B (per spp level: the median cost of the scene's rows at that spp),
the candidates are the rows not significantly dearer than B (c - B <= Z cse) at any spp, and their top
group is ties.top_group of the candidates: what one can get for about that time, with ties.
"""
import numpy as np
import pandas as pd

from . import ties


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


def summary_front_mask(points, z=ties.Z):
    """The front over (method, spp) points across scenes: columns median_ratio, ci_low, ci_high, cost,
    cost_se. Point i leaves it when another's interval lies wholly below i's (ci_high_j < ci_low_i) and
    it is not significantly slower."""
    lo = points["ci_low"].to_numpy(dtype=float)
    hi = points["ci_high"].to_numpy(dtype=float)
    cost = points["cost"].to_numpy(dtype=float)
    cse = _spread(points["cost_se"])
    better = hi[None, :] < lo[:, None]
    not_slower = (cost[None, :] - cost[:, None]) <= z * np.sqrt(cse[:, None] ** 2 + cse[None, :] ** 2)
    ok = np.isfinite(points["median_ratio"].to_numpy(dtype=float)) & np.isfinite(cost)
    if "deterministic" in points.columns:
        ok &= ~points["deterministic"].to_numpy(dtype=bool)
    return ok & ~(better & not_slower & ok[None, :]).any(axis=1)


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
    (summary_front_mask)."""
    r = ranked[ranked["target"].astype(str) == target]
    key = ["spp"] + method
    agg = r.groupby(key, dropna=False).agg(cost=("cost", "mean"), n=("cost", "size"),
                                          var=("cost_se", lambda x: float(np.sum(np.asarray(x, float) ** 2))))
    agg["cost_se"] = np.sqrt(agg["var"]) / agg["n"]
    pts = summary[summary["target"].astype(str) == target].merge(agg.reset_index()[key + ["cost", "cost_se"]],
                                                                 on=key, how="left")
    pts["front"] = summary_front_mask(pts) if len(pts) else []
    return pts
