"""answer.csv recomputed by another path, for test_answer_csv.py and test_findings.py: the study CSV
read by recompute.read (the csv module), plain loops and numpy, nothing of aliaslab_analysis. Each step follows
the rule as docs/science.md ("Answers a practitioner can act on") and the module docs state it, written again:
Student's t quantile by Gauss-Legendre integration of the density and bisection (the package uses the
incomplete beta function and Newton), the heavy-tail rule, the log-ratio interval, the bootstrap over seeds,
the verdicts, the across-scene median with its bootstrap over scenes."""
import math

import numpy as np

MARGIN = 0.10
NODES, WEIGHTS = np.polynomial.legendre.leggauss(96)


def t_pdf(x, df):
    return np.exp(math.lgamma((df + 1) / 2) - math.lgamma(df / 2)) / math.sqrt(df * math.pi) \
        * (1 + x * x / df) ** (-(df + 1) / 2)


def t_quantile(p, df):
    """By bisection on 1/2 + integral_0^x pdf (96-point Gauss-Legendre)."""
    if not math.isfinite(df):
        df = 1e9
    if df > 1e6:
        pdf = lambda x: np.exp(-x * x / 2) / math.sqrt(2 * math.pi)  # noqa: E731
    else:
        pdf = lambda x: t_pdf(x, df)  # noqa: E731
    lo, hi = 0.0, 40.0
    for _ in range(60):
        mid = (lo + hi) / 2
        cdf = 0.5 + mid / 2 * float(np.sum(WEIGHTS * pdf(mid / 2 * (NODES + 1))))
        lo, hi = (mid, hi) if cdf < p else (lo, mid)
    return (lo + hi) / 2


def heavy(r):
    v = r["seeds_v"]
    if v is None or len(v) < 4 or r["det"]:
        return False
    total = sum(v)
    return total > 0 and max(v) / total > 2.0 / len(v)


def measured(r):
    return r["err"] > 2 * r["se"] if math.isfinite(r["se"]) else r["err"] > 0


def parts(r):
    """(seed variance of e, reference variance, degrees of freedom)."""
    se = r["se"] if math.isfinite(r["se"]) else 0.0
    if r["det"]:
        s2 = 0.0
    elif r["seeds_v"] is not None:
        v = np.array(r["seeds_v"])
        s2 = float(np.sum((v - v.mean()) ** 2) / (len(v) - 1) / len(v))
    else:
        s2 = se * se
    k = len(r["seeds_v"]) if r["seeds_v"] is not None else int(r["seeds"])
    return s2, max(se * se - s2, 0.0), (k - 1) if (k >= 2 and not r["det"]) else math.inf


def welch(comps):
    total = sum(v for v, _ in comps)
    den = sum(v * v / d for v, d in comps if math.isfinite(d))
    return total * total / den if den > 0 and total > 0 else math.inf


def boot(a, b, paired):
    rng = np.random.default_rng(44)
    xa = np.array(a["seeds_v"])
    idx = rng.integers(0, len(xa), size=(2000, len(xa)))
    top = xa[idx].mean(axis=1)
    if paired:
        bottom = np.array(b["seeds_v"])[idx].mean(axis=1)
    elif b["seeds_v"] is not None and not b["det"]:
        xb = np.array(b["seeds_v"])
        bottom = xb[rng.integers(0, len(xb), size=(2000, len(xb)))].mean(axis=1)
    else:
        bottom = np.full(2000, b["err"])
    r = top / bottom
    return float(np.quantile(r, 0.025)), float(np.quantile(r, 0.975))


def versus(a, b, paired):
    """(ratio, low, high) of row a against its cell's best b."""
    ratio = a["err"] / b["err"]
    if heavy(a) or heavy(b):
        return (ratio,) + boot(a, b, paired)
    sa, ra, da = parts(a)
    sb, rb, db = parts(b)
    if measured(a) and a["err"] > 0:
        ref = ra / a["err"] ** 2 + rb / b["err"] ** 2
        if paired:
            d = np.array(a["seeds_v"]) / a["err"] - np.array(b["seeds_v"]) / b["err"]
            seed = [(float(np.sum((d - d.mean()) ** 2) / (len(d) - 1) / len(d)), len(d) - 1)]
        else:
            seed = [(sa / a["err"] ** 2, da), (sb / b["err"] ** 2, db)]
        v = sum(x for x, _ in seed) + ref
        h = t_quantile(0.975, welch(seed + [(ref, math.inf)])) * math.sqrt(v)
        return ratio, ratio * math.exp(-h), ratio * math.exp(h)
    h = t_quantile(0.975, da) * (a["se"] if math.isfinite(a["se"]) else 0.0) / b["err"]
    return ratio, ratio - h, ratio + h


def verdict(lo, hi, is_heavy, margin=MARGIN):
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return "undetermined"
    if lo > 1 + margin:
        return "worse"
    if hi < 1 + margin and not is_heavy:
        return "equivalent"
    return "undetermined"


def key(r):
    return (r["sampler"], r["filter"], r["radius"], r["filter_params"], r["reconstruction"], r["prefilter"])


def scenes(rows, margin=MARGIN):
    """{(target, spp, scene, method key): (ratio, low, high, verdict, heavy, best)}."""
    cells = {}
    for r in rows:
        if math.isfinite(r["err"]):
            cells.setdefault((r["target"], r["scene"], r["spp"]), []).append(r)
    out = {}
    for (target, scene, spp), cell in cells.items():
        ok = [r for r in cell if measured(r) and r["err"] > 0 and not heavy(r) and r["flagged"] != 1]
        b = min(ok, key=lambda r: r["err"]) if ok else None
        for r in cell:
            if b is None:
                res = (math.nan, math.nan, math.nan, "undetermined", heavy(r), False)
            elif r is b:
                res = (1.0, 1.0, 1.0, "equivalent", False, True)
            else:
                same = (r["sampler"], r["prefilter"]) == (b["sampler"], b["prefilter"])
                paired = (same and r["seeds_v"] is not None and b["seeds_v"] is not None and not r["det"]
                          and not b["det"] and len(r["seeds_v"]) == len(b["seeds_v"]))
                ratio, lo, hi = versus(r, b, paired)
                res = (ratio, lo, hi, verdict(lo, hi, heavy(r), margin), heavy(r), False)
            out[(target, spp, scene, key(r))] = res
    return out


def across(per, margin=MARGIN):
    """{(target, spp, method key): (median, low, high, verdict, heavy scenes, scenes, equivalent scenes)}."""
    groups = {}
    for (target, spp, scene, k), res in sorted(per.items(), key=lambda kv: kv[0][2]):
        groups.setdefault((target, spp, k), []).append(res)
    out = {}
    for gk, rs in groups.items():
        v = np.array([x[0] for x in rs if math.isfinite(x[0])])
        n_heavy = sum(1 for x in rs if x[4])
        if len(v) == 0:
            med, lo, hi = math.nan, math.nan, math.nan
        elif len(v) == 1:
            med = lo = hi = float(v[0])
        else:
            med = float(np.median(v))
            idx = np.random.default_rng(29).integers(0, len(v), size=(2000, len(v)))
            m = np.median(v[idx], axis=1)
            lo, hi = float(np.quantile(m, 0.025)), float(np.quantile(m, 0.975))
        n_eq = sum(1 for x in rs if x[3] == "equivalent")
        v_all = verdict(lo, hi, n_heavy > 0, margin)
        if v_all == "equivalent" and n_eq < len(v) / 2:  # equivalent in fewer than half of its scenes
            v_all = "undetermined"
        out[gk] = (med, lo, hi, v_all, n_heavy, len(v), n_eq)
    return out


def picks(summary, target, spp):
    """{sampler: (method key, record)}: each sampler's method with the lowest median (then most scenes
    equivalent), plain sampling only."""
    out = {}
    for (t, s, k), rec in summary.items():
        if t != target or s != spp or k[5] != "none" or not math.isfinite(rec[0]):
            continue
        if k[0] not in out or (rec[0], -rec[6]) < (out[k[0]][1][0], -out[k[0]][1][6]):
            out[k[0]] = (k, rec)
    return out


def leaders(summary, target, spp, n_scenes):
    """The leading samplers (stats/factors.leaders' rule, written again)."""
    p = picks(summary, target, spp)
    half = (n_scenes + 1) // 2
    lead = [s for s, (_, rec) in p.items() if rec[3] == "equivalent" or rec[6] >= half]
    if lead:
        return sorted(lead)
    most = max((rec[6] for _, rec in p.values()), default=0)
    if most > 0:
        return sorted(s for s, (_, rec) in p.items() if rec[6] == most)
    return [min(p, key=lambda s: (p[s][1][0], -p[s][1][6]))] if p else []


CACHE = {}


def study(rows, margin=MARGIN):
    """(per, summary) of a rows list (recompute.read), cached per list."""
    k = (id(rows), margin)
    if k not in CACHE:
        per = scenes(rows, margin)
        CACHE.clear()
        CACHE[k] = (per, across(per, margin))
    return CACHE[k]


def best_rows(rows):
    """{(target, scene, spp): the cell's best row} (measured, error > 0, not heavy-tailed, not flagged)."""
    out = {}
    for r in rows:
        if math.isfinite(r["err"]) and measured(r) and r["err"] > 0 and not heavy(r) and r["flagged"] != 1:
            k = (r["target"], r["scene"], r["spp"])
            if k not in out or r["err"] < out[k]["err"]:
                out[k] = r
    return out


def points(rows, target):
    """{(spp, method key): (median ratio, mean cost, se of that mean)} across scenes against `target`."""
    _, summary = study(rows)
    costs = {}
    for r in rows:
        if r["target"] == target and math.isfinite(r["err"]):
            se = r["cost_se"] if math.isfinite(r["cost_se"]) else 0.0
            costs.setdefault((r["spp"], key(r)), []).append((r["cost"], se))
    out = {}
    for (t, spp, k), rec in summary.items():
        if t == target:
            c = costs[(spp, k)]
            out[(spp, k)] = (rec[0], sum(a for a, _ in c) / len(c), math.sqrt(sum(b * b for _, b in c)) / len(c))
    return out


def front(pts):
    """The keys of the points no other point beats in both median ratio and cost."""
    ok = {k: p for k, p in pts.items() if math.isfinite(p[0]) and math.isfinite(p[1])}
    return [k for k, p in ok.items() if not any(q[0] <= p[0] and q[1] <= p[1] and (q[0] < p[0] or q[1] < p[1])
                                                for j, q in ok.items() if j != k)]
