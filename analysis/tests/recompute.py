"""An independent recomputation of the findings' numbers, for test_findings.py: the study
CSV read with the csv module, plain loops and numpy, no pandas and nothing of aliaslab_analysis. Each
function follows the rule stated in the module it checks (stats/ties.py, rankings.py, fronts.py,
bootstrap.py, findings/*.py), written again from the statement."""
import csv
import gzip
import io
import math

import numpy as np

Z = 2.0
METHOD = ("sampler", "filter", "radius", "filter_params", "reconstruction", "prefilter")


def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return math.nan


def read(path):
    CACHE.clear()
    with open(path, "rb") as f:
        data = f.read()
    if data[:2] == b"\x1f\x8b":  # a gzipped study (study.csv.gz)
        data = gzip.decompress(data)
    with io.StringIO(data.decode("utf-8"), newline="") as f:
        rows = list(csv.DictReader(f))
    out = []
    for r in rows:
        d = dict(r)
        d["target"] = r.get("target") or "box:0.5"
        d["prefilter"] = r.get("prefilter") or "none"
        for c in ("spp", "radius", "mse", "noise", "aliasing", "aliasing_se", "flagged", "width", "height",
                  "seeds", "ref_spp", "trace_ms", "reconstruct_ms", "blur", "cross", "mse_area"):
            d[c] = num(r.get(c))
        d["spp"] = int(d["spp"])
        d["err"] = num(r["mse_target"]) if "mse_target" in r else d["mse_area"]
        d["se"] = num(r.get("mse_target_se"))
        d["tre"] = num(r.get("target_ref_error", r.get("ref_error")))
        if "deterministic" in r:
            d["det"] = num(r["deterministic"]) != 0
        else:
            d["det"] = d["noise"] == 0 and math.isfinite(d["se"]) and d["se"] <= 1e-12 * max(abs(d["err"]), 1e-300)
        if "cpu_ms" in r:
            seed_se = num(r.get("cpu_ms_se"))
            d["cost"] = num(r["cpu_ms"])
            # the seeds' se and the 15 % run-to-run floor (study_rows.COST_FLOOR), added in quadrature
            d["cost_se"] = math.sqrt((seed_se if math.isfinite(seed_se) else 0.0) ** 2 + (0.15 * d["cost"]) ** 2)
        else:
            d["cost"], d["cost_se"] = d["trace_ms"] + d["reconstruct_ms"], math.nan
        seeds = [p for p in (r.get("mse_target_seeds") or "").split(";") if p.strip()]
        d["seeds_v"] = [float(p) for p in seeds] if len(seeds) >= 2 else None
        d["method"] = (r["sampler"], r["filter"], d["radius"], r["filter_params"], r["reconstruction"], d["prefilter"])
        out.append(d)
    return out


def primary(rows):
    ts = []
    for r in rows:
        if r["target"] not in ts:
            ts.append(r["target"])
    return "box:0.5" if "box:0.5" in ts else ts[0]


def diff_se(a, b):
    if (a["sampler"], a["prefilter"]) == (b["sampler"], b["prefilter"]) and a["seeds_v"] and b["seeds_v"] \
            and len(a["seeds_v"]) == len(b["seeds_v"]):
        d = np.array(a["seeds_v"]) - np.array(b["seeds_v"])
        return float(np.std(d, ddof=1) / math.sqrt(len(d)))
    return math.sqrt(a["se"] ** 2 + b["se"] ** 2)


def measured(r):
    return r["err"] > Z * r["se"] if math.isfinite(r["se"]) else r["err"] > 0


def top_group(cell):
    """{id(row): (top, undetermined)} and the best row, for the rankable rows of one cell."""
    meas = [r for r in cell if measured(r)]
    pool = meas if meas else cell
    b = min(pool, key=lambda r: r["err"])
    upper_b = b["err"] + Z * (b["se"] if math.isfinite(b["se"]) else 0)
    out = {}
    for r in cell:
        gap = r["err"] - b["err"]
        s = 0.0 if r is b else diff_se(r, b)
        tied = gap <= Z * s if math.isfinite(s) else gap <= 0
        accurate = r["err"] + Z * (r["se"] if math.isfinite(r["se"]) else 0) <= upper_b
        top = tied and (measured(r) or accurate)
        out[id(r)] = (top, not measured(r) and not top)
    return out, b


def cells(rows, target):
    by = {}
    for r in rows:
        if r["target"] == target and math.isfinite(r["err"]) and not r["det"]:
            by.setdefault((r["scene"], r["spp"]), []).append(r)
    return by


CACHE = {}


def records(rows, target):
    """{(spp, method): dict(scenes, in_top, flagged, undetermined, ratios)} with ratios in scene order
    (cached per rows list and target)."""
    key = (id(rows), target)
    if key not in CACHE:
        CACHE[key] = records_uncached(rows, target)
    return CACHE[key]


def records_uncached(rows, target):
    out = {}
    for (scene, spp), cell in sorted(cells(rows, target).items()):
        groups, _ = top_group(cell)
        base = [r["err"] for r in cell if r["flagged"] == 0 and measured(r) and r["err"] > 0]
        base = min(base) if base else math.nan
        for r in cell:
            rec = out.setdefault((spp, r["method"]), dict(in_top=0, flagged=0, undetermined=0, ratios=[]))
            top, und = groups[id(r)]
            rec["in_top"] += top
            rec["undetermined"] += und
            rec["flagged"] += r["flagged"] == 1
            ratio = r["err"] / base
            if math.isfinite(ratio):
                rec["ratios"].append(ratio)
    for rec in out.values():
        v = np.array(rec["ratios"])
        rec["scenes"] = len(v)
        rec["median_ratio"] = float(np.median(v)) if len(v) else math.nan
        if len(v) == 1:
            rec["ci_low"] = rec["ci_high"] = float(v[0])
        elif len(v):
            idx = np.random.default_rng(29).integers(0, len(v), size=(2000, len(v)))
            med = np.median(v[idx], axis=1)
            rec["ci_low"], rec["ci_high"] = float(np.quantile(med, 0.025)), float(np.quantile(med, 0.975))
    return out


def answer(rows, target, spp):
    scenes = len(set(r["scene"] for r in rows))
    rec = {m: x for (s, m), x in records(rows, target).items() if s == spp}
    need = (scenes + 1) // 2
    pick = [m for m, x in rec.items() if x["in_top"] >= need]
    if not pick and rec:
        best = max(x["in_top"] for x in rec.values())
        pick = [m for m, x in rec.items() if x["in_top"] == best]
    return pick


def points(rows, target):
    """{(spp, method): (median, ci_low, ci_high, cost, cost_se)} over scenes."""
    rec = records(rows, target)
    costs = {}
    for r in rows:
        if r["target"] == target and math.isfinite(r["err"]) and not r["det"]:
            costs.setdefault((r["spp"], r["method"]), []).append((r["cost"], r["cost_se"]))
    out = {}
    for k, x in rec.items():
        c = costs[k]
        mean = sum(a for a, _ in c) / len(c)
        se = math.sqrt(sum(b * b for _, b in c if math.isfinite(b))) / len(c)
        out[k] = (x["median_ratio"], x.get("ci_low", math.nan), x.get("ci_high", math.nan), mean, se)
    return out


def front(rows, target):
    key = ("front", id(rows), target)
    if key not in CACHE:
        CACHE[key] = front_uncached(rows, target)
    return CACHE[key]


def front_uncached(rows, target):
    """Points not beaten: a point j not significantly slower, with a lower median (the 10 lowest tested),
    whose paired bootstrap over scenes of the median of log(ratio_i / ratio_j) has its 2.5 % quantile > 0."""
    pts = points(rows, target)
    scenes = sorted(set(r["scene"] for r in rows if r["target"] == target and math.isfinite(r["err"])))
    logs = {}
    for (scene, spp), cell in cells(rows, target).items():
        base = [r["err"] for r in cell if r["flagged"] == 0 and measured(r) and r["err"] > 0]
        for r in cell:
            ratio = r["err"] / min(base) if base else math.nan
            logs.setdefault((spp, r["method"]), {})[scene] = math.log(ratio) if ratio > 0 else math.nan
    boot = np.random.default_rng(29).integers(0, len(scenes), size=(2000, len(scenes)))
    keys = [k for k, p in pts.items() if math.isfinite(p[0]) and math.isfinite(p[3])]
    on = []
    for i in keys:
        pi = pts[i]
        cands = sorted((pts[j][0], pts[j][3], n, j) for n, j in enumerate(keys)
                       if pts[j][0] < pi[0] and pts[j][3] - pi[3] <= Z * math.sqrt(pi[4] ** 2 + pts[j][4] ** 2))
        beaten = False
        for _, _, _, j in cands[:10]:
            d = np.array([logs[i].get(s, math.nan) - logs[j].get(s, math.nan) for s in scenes])
            resampled = np.ma.masked_invalid(d[boot])            # (2000, scenes), NaN masked
            meds = np.ma.median(resampled, axis=1).filled(np.nan)
            meds = meds[np.isfinite(meds)]
            if len(meds) and np.quantile(meds, 0.025) > 0:
                beaten = True
                break
        if not beaten:
            on.append(i)
    return on, pts


def equal_time_counts(rows, target, budget_spp):
    """{(method, spp): scenes where it is in the top group at the budget of budget_spp} (cached)."""
    key = ("eq", id(rows), target, budget_spp)
    if key not in CACHE:
        CACHE[key] = equal_time_uncached(rows, target, budget_spp)
    return CACHE[key]


def equal_time_uncached(rows, target, budget_spp):
    counts = {}
    by_scene = {}
    for r in rows:
        if r["target"] == target and math.isfinite(r["err"]) and not r["det"]:
            by_scene.setdefault(r["scene"], []).append(r)
    for scene, rs in by_scene.items():
        b = float(np.median([r["cost"] for r in rs if r["spp"] == budget_spp]))
        cand = [r for r in rs if r["cost"] - b <= Z * (r["cost_se"] if math.isfinite(r["cost_se"]) else 0)]
        groups, _ = top_group(cand)
        for r in cand:
            if groups[id(r)][0]:
                counts.setdefault((r["method"], r["spp"]), set()).add(scene)
    return {k: len(v) for k, v in counts.items()}


def box_error(rows, target, sampler, spp):
    out = {}
    for r in rows:
        if r["target"] == target and r["sampler"] == sampler and r["spp"] == spp and r["prefilter"] == "none" \
                and r["filter"] == "box" and r["radius"] == 0.5 and math.isfinite(r["err"]):
            out[r["scene"]] = r["err"]
    return out
