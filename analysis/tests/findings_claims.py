"""The answer's claims (findings/answer.py, factors.py, grid.py) recomputed from recompute_answer.py's
independent path, for test_findings.py: the leading samplers and their records, the filters with them, what
holds under every target, the fixed grid's alignment figures."""
import math

import numpy as np

from . import recompute as rc, recompute_answer as ra

ANSWER_KINDS = {"leaders", "pick", "pick_median_ratio", "pick_ci_low", "pick_ci_high", "pick_equivalent",
                "filters", "filter_median_ratio", "common_samplers", "leader_configs", "align_over_centred",
                "align_over_best"}
FIELD = {"pick_median_ratio": 0, "pick_ci_low": 1, "pick_ci_high": 2, "pick_equivalent": 6}


def config(k):
    return f"{k[1]} r={k[2]:g}"


def filter_picks(summary, target, spp, samplers):
    """{filter: (key, record)}: each filter's lowest median among the samplers' plain methods."""
    out = {}
    for (t, s, k), rec in summary.items():
        if t == target and s == spp and k[0] in samplers and k[5] == "none" and math.isfinite(rec[0]):
            if k[1] not in out or (rec[0], -rec[6]) < (out[k[1]][1][0], -out[k[1]][1][6]):
                out[k[1]] = (k, rec)
    return out


def answer_claim(rows, claim):
    k = claim["kind"]
    _, summary = ra.study(rows)
    n = len(set(r["scene"] for r in rows))
    tgt = claim.get("target", rc.primary(rows))
    spp = claim.get("spp")
    if k == "leaders":
        return ra.leaders(summary, tgt, spp, n)
    if k == "pick":
        return config(ra.picks(summary, tgt, spp)[claim["sampler"]][0])
    if k in FIELD:
        return ra.picks(summary, tgt, spp)[claim["sampler"]][1][FIELD[k]]
    if k in ("filters", "filter_median_ratio"):
        fp = filter_picks(summary, tgt, spp, set(ra.leaders(summary, tgt, spp, n)))
        if k == "filter_median_ratio":
            return fp[claim["filter"]][1][0]
        good = [v for v in fp.values() if v[1][3] == "equivalent" or v[1][6] >= (n + 1) // 2]
        if not good:
            good = [min(fp.values(), key=lambda v: (v[1][0], -v[1][6]))]
        return sorted(config(v[0]) for v in good)
    if k == "common_samplers":
        targets = sorted(set(r["target"] for r in rows))
        return sorted(set.intersection(*[set(ra.leaders(summary, t, spp, n)) for t in targets]))
    if k == "leader_configs":
        p = ra.picks(summary, tgt, spp)
        return sorted({config(p[s][0]) for s in ra.leaders(summary, tgt, spp, n)})
    if k in ("align_over_centred", "align_over_best"):
        key = ra.picks(summary, tgt, spp)["uniform"][0]
        best = ra.best_rows(rows)
        vals = []
        for r in rows:
            a = rc.num(r.get("align_mse_target"))
            if r["target"] == tgt and r["spp"] == spp and ra.key(r) == key and math.isfinite(a):
                vals.append(a / (r["err"] if k == "align_over_centred" else best[(tgt, r["scene"], spp)]["err"]))
        return float(np.median(vals))
    return None
