"""Error against time: strict Pareto fronts and whether cost is set by spp (docs/science.md "Time").

Cost. `cost` = cpu_ms (thread CPU time of the configuration's own work, mean over seeds) with `cost_se` =
sqrt(cpu_ms_se^2 + (0.15 cpu_ms)^2) (study_rows.py); a CSV without cpu_ms falls back to the wall time time_ms
with an unknown spread (NaN).

Front (front_mask, summary_front_mask). A point is on the front when no other point beats it in both error
and time: no j with e_j <= e_i and c_j <= c_i, one of them strictly (a strict Pareto front on the point
values; points equal in both are kept together). Every row with a finite error and cost takes part, the fixed
grid included (it is ranked like any method). Across scenes the points are (method, spp) with their median
ratio to each scene's best and their mean cost over the scenes.

Cost set by spp (cost_by_spp). Per spp level, over the (method, spp) points: the cheapest and the dearest
mean cost and the spread of their difference, Z sqrt(cse_min^2 + cse_max^2) (Z = 2). When the whole range
is within that spread, time within the spp level varies less than its spread: the cost is set by spp, and an
equal-time comparison is an equal-spp one.
"""
import numpy as np
import pandas as pd

from .ties import Z


def _spread(x):
    x = np.asarray(x, dtype=float)
    return np.where(np.isfinite(x), x, 0.0)


def pareto(err, cost):
    """A boolean per point: not dominated (module doc); points with a non-finite value are off it."""
    err = np.asarray(err, dtype=float)
    cost = np.asarray(cost, dtype=float)
    ok = np.isfinite(err) & np.isfinite(cost)
    e, c = err[ok], cost[ok]
    le = (e[None, :] <= e[:, None]) & (c[None, :] <= c[:, None])    # [i, j]: j at least as good as i in both
    lt = (e[None, :] < e[:, None]) | (c[None, :] < c[:, None])       # and strictly better in one
    out = np.zeros(len(err), dtype=bool)
    out[ok] = ~(le & lt).any(axis=1)
    return out


def front_mask(rows):
    """The front of one (scene, target)'s rows on (error, cost)."""
    return pareto(rows["error"], rows["cost"])


def fronts(rows):
    """The front rows of every (target, scene), sorted by cost, with `front_rank` 1, 2, ..."""
    parts = []
    for _, g in rows.groupby(["target", "scene"], sort=True):
        f = g[front_mask(g)].sort_values(["cost", "error"])
        parts.append(f.assign(front_rank=np.arange(1, len(f) + 1)))
    return pd.concat(parts) if parts else rows.iloc[0:0].assign(front_rank=0)


def summary_points(per, summary, target, method):
    """One point per (method, spp) against `target`: the across-scene record (equivalence.across) with `cost`
    (mean over its scenes), `cost_se` (the se of that mean), `cost_low` and `cost_high` (the lowest and the
    highest cost over the scenes) and `front` (pareto on median_ratio and cost)."""
    r = per[per["target"].astype(str) == target]
    key = ["spp"] + method
    agg = r.groupby(key, dropna=False).agg(cost=("cost", "mean"), n=("cost", "size"), cost_low=("cost", "min"),
                                          cost_high=("cost", "max"),
                                          var=("cost_se", lambda x: float(np.sum(_spread(x) ** 2))))
    agg["cost_se"] = np.sqrt(agg["var"]) / agg["n"]
    pts = summary[summary["target"].astype(str) == target]
    cols = key + ["cost", "cost_se", "cost_low", "cost_high"]
    if not len(pts):
        return pts.assign(**{c: [] for c in cols[len(key):]}, front=[])
    pts = pts.merge(agg.reset_index()[cols], on=key, how="left")
    pts["front"] = pareto(pts["median_ratio"], pts["cost"])
    return pts


def cost_by_spp(points, z=Z):
    """Per spp level: dict(spp, low, high (mean costs of the cheapest and dearest point), spread
    (z sqrt(cse_low^2 + cse_high^2)), set_by_spp (high - low <= spread), n (points))."""
    out = []
    for spp, g in points[np.isfinite(points["cost"].to_numpy(dtype=float))].groupby("spp", sort=True):
        lo, hi = g.loc[g["cost"].idxmin()], g.loc[g["cost"].idxmax()]
        spread = z * float(np.hypot(_spread([lo["cost_se"]])[0], _spread([hi["cost_se"]])[0]))
        out.append(dict(spp=int(spp), low=float(lo["cost"]), high=float(hi["cost"]), spread=spread,
                        set_by_spp=bool(hi["cost"] - lo["cost"] <= spread), n=len(g)))
    return out
