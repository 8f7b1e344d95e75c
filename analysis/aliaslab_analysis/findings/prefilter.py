"""Pre-filtering against plain sampling (when the study has pre-filtered rows): the best pre-filtered method
per scene at the lowest spp against the best plain method per scene at each spp, as medians over scenes of
per-scene ratios of error (against the primary target) and of cost (cpu_ms; the wall time only for a CSV
without it). The main page's rules pick the best: the lowest error among the rows whose error is told from
zero, not flagged and not heavy-tailed (stats/effect.py), the fixed grid ranked like any method."""
import numpy as np

from .study import Finding, fmt


def best_per_scene(rows):
    """{scene: (error, cost)} of each scene's best row (module doc)."""
    out = {}
    ok = rows[rows["measured"].astype(bool) & (rows["flagged"] != 1) & ~rows["heavy_tailed"].astype(bool)
              & (rows["error"] > 0)]
    for scene, g in ok.groupby("scene", sort=True):
        r = g.loc[g["error"].idxmin()]
        out[scene] = (float(r["error"]), float(r["cost"]))
    return out


def prefilter(s):
    rows = s.ranked[s.ranked["target"].astype(str) == s.primary]
    if not (rows["prefilter"] != "none").any():
        return None
    low = int(rows["spp"].min())
    pre = best_per_scene(rows[(rows["prefilter"] != "none") & (rows["spp"] == low)])
    if not pre:
        return None
    parts, claims = [], []
    what = "cpu time" if "cpu_ms" in s.df.columns else "wall time"
    for spp in s.levels:
        plain = best_per_scene(rows[(rows["prefilter"] == "none") & (rows["spp"] == spp)])
        common = [k for k in pre if k in plain]
        if not common:
            continue
        er = float(np.median([pre[k][0] / plain[k][0] for k in common]))
        tr = float(np.median([pre[k][1] / plain[k][1] for k in common]))
        parts.append(f"plain {spp} spp: error x{fmt(er)}, {what} x{fmt(tr)} ({len(common)} scenes)")
        claims += [dict(kind="prefilter_error", spp=spp, value=er), dict(kind="prefilter_time", spp=spp, value=tr)]
    text = (f"Pre-filtered at {low} spp (the best pre-filtered method per scene) against the best plain sampling "
            "per scene: " + "; ".join(parts) + " (medians over scenes of per-scene ratios; below 1: the pre-filtered "
            "image is better or faster).")
    return Finding("prefilter", "Pre-filtering", text, claims)


def findings(s):
    return [prefilter(s)]
