"""For the time spent, against the primary target: whether cost is set by spp (stats/fronts.cost_by_spp) and
the strict front across scenes (stats/fronts.summary_points: no point beaten in both median ratio and mean
cost)."""
from ..stats import fronts
from .study import Finding, fmt, method_key, method_name


def timing(s):
    return "thread CPU time" if "cpu_ms" in s.df.columns else "wall time (no measured spread)"


def cost_finding(s):
    levels = fronts.cost_by_spp(s.points())
    if not levels:
        return None
    parts, claims = [], []
    for x in levels:
        parts.append(f"at {x['spp']} spp {fmt(x['low'])}-{fmt(x['high'])} ms (spread {fmt(x['spread'])} ms: "
                     + ("within it" if x["set_by_spp"] else "beyond it") + ")")
        claims += [dict(kind="cost_low", spp=x["spp"], value=x["low"]), dict(kind="cost_high", spp=x["spp"], value=x["high"]),
                   dict(kind="set_by_spp", spp=x["spp"], value=int(x["set_by_spp"]))]
    every = all(x["set_by_spp"] for x in levels)
    text = (f"Time ({timing(s)}, mean over scenes per method) from the cheapest to the dearest method: "
            + "; ".join(parts) + " (spread: 2 standard errors of the difference of the two, each with the 15 % "
            "run-to-run floor). ")
    text += ("At every spp level the methods' times differ by less than that spread: **the cost is set by spp**, "
             "and at equal time the answer is the answer at equal spp." if every else
             "Where the range is beyond the spread the choice of method changes the cost at that spp; elsewhere "
             "the cost is set by spp.")
    return Finding("cost", "What sets the cost", text, claims)


def front_finding(s):
    pts = s.points()
    front = pts[pts["front"]].sort_values(["cost", "median_ratio"])
    if front.empty:
        return None
    first, last = front.iloc[0], front.iloc[-1]
    text = (f"Error against time ({timing(s)}, mean over scenes): {len(front)} of {len(pts)} (method, spp) points "
            "are on the front, where no other point has both a lower (or equal) median ratio and a lower (or equal) "
            f"time: from **{method_name(first)} at {int(first['spp'])} spp** ({fmt(first['cost'])} ms, median "
            f"{fmt(first['median_ratio'])}x each scene's best) to **{method_name(last)} at {int(last['spp'])} spp** "
            f"({fmt(last['cost'])} ms, {fmt(last['median_ratio'])}x). Points closer in time than its spread are not "
            "told apart by it: read the front with the cost finding above.")
    claims = [dict(kind="front_size", target=s.primary, value=len(front)),
              dict(kind="front_points", target=s.primary, value=len(pts))]
    for r in (first, last):
        claims.append(dict(kind="point_cost", target=s.primary, spp=int(r["spp"]), method=method_key(r),
                           value=float(r["cost"])))
    return Finding("front", "Error against time", text, claims)


def findings(s):
    return [cost_finding(s), front_finding(s)]
