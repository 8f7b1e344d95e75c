"""For the time spent: the error-vs-time front with ties across scenes (stats/fronts.summary_front_mask)
and the top groups at equal time (stats/fronts.equal_time), against the primary target."""
import numpy as np

from ..stats import fronts, rankings
from .study import Finding, fmt, method_key, method_name


def front_finding(s):
    pts = s.points()
    pts = pts[~pts["deterministic"].astype(bool)]
    front = pts[pts["front"]].sort_values(["cost", "median_ratio"])
    if front.empty:
        return None
    first, last = front.iloc[0], front.iloc[-1]
    timing = "thread CPU time" if "cpu_ms" in s.df.columns else "wall time (no measured spread)"
    text = (f"For the time spent ({timing}, mean over scenes), {len(front)} of {len(pts)} (method, spp) points are "
            f"on the front with ties: from **{method_name(first)} at {int(first['spp'])} spp** ({fmt(first['cost'])} ms, "
            f"median {fmt(first['median_ratio'])}x each scene's best) to **{method_name(last)} at {int(last['spp'])} "
            f"spp** ({fmt(last['cost'])} ms, {fmt(last['median_ratio'])}x). A point leaves the front only when another, "
            "not significantly slower (beyond 2 standard errors of the time difference), is significantly better "
            "across scenes (a paired bootstrap over scenes of the median log ratio between the two excludes 0); "
            "every method stays on the chart.")
    claims = [dict(kind="front_size", target=s.primary, value=len(front)),
              dict(kind="front_points", target=s.primary, value=len(pts))]
    for r in (first, last):
        claims.append(dict(kind="point_cost", target=s.primary, spp=int(r["spp"]), method=method_key(r),
                           value=float(r["cost"])))
    return Finding("front", "Error against time", text, claims)


def equal_time_finding(s):
    eq = fronts.equal_time(s.ranked[s.ranked["target"].astype(str) == s.primary])
    if eq.empty:
        return None
    parts, claims = [], []
    for spp, g in eq.groupby("budget_spp", sort=True):
        top = g[g["top"]]
        counts = top.groupby(rankings.METHOD + ["spp"], dropna=False)["scene"].nunique().sort_values(
            ascending=False, kind="stable")
        if counts.empty:
            continue
        need = s.majority if counts.iloc[0] >= s.majority else counts.iloc[0]
        chosen = counts[counts >= need].head(4)
        budget = float(np.median(g.drop_duplicates("scene")["budget_ms"]))
        names = []
        for key, n in chosen.items():
            r = dict(zip(rankings.METHOD, key[:-1]))
            names.append(f"**{method_name(r)} at {int(key[-1])} spp** ({int(n)} of {len(s.scenes)})")
            claims.append(dict(kind="equal_time_in_top", target=s.primary, budget_spp=int(spp),
                               method=tuple(key[:-1]), spp=int(key[-1]), value=int(n)))
        parts.append(f"for the time of a typical {int(spp)}-spp row (median over scenes {fmt(budget)} ms) "
                     + ", ".join(names))
    text = ("At equal time (any spp, rows not significantly dearer than the budget; ties in error as above), "
            "the methods most often in the top group (scenes): " + "; ".join(parts) + ".")
    return Finding("equal_time", "At equal time", text, claims)


def findings(s):
    return [front_finding(s), equal_time_finding(s)]
