"""Pre-filtering against plain sampling (when the study has pre-filtered rows): the best pre-filtered method
per scene at the lowest spp against the best plain method per scene at each spp, as medians over scenes of
per-scene ratios of error (against the primary target) and of wall time (time_ms). Every finite row takes
part, the fixed grid included (the comparison is of images, not a ranking)."""
import numpy as np

from .study import Finding, fmt


def best_per_scene(rows):
    """{scene: (error, time_ms)} of each scene's lowest-error row."""
    out = {}
    for scene, g in rows.groupby("scene", sort=True):
        r = g.loc[g["error"].idxmin()]
        out[scene] = (float(r["error"]), float(r["time_ms"]))
    return out


def prefilter(s):
    rows = s.rows()
    rows = rows[np.isfinite(rows["error"].to_numpy(dtype=float))]
    if not (rows["prefilter"] != "none").any():
        return None
    low = int(rows["spp"].min())
    pre = best_per_scene(rows[(rows["prefilter"] != "none") & (rows["spp"] == low)])
    if not pre:
        return None
    parts, claims = [], []
    for spp in s.levels:
        plain = best_per_scene(rows[(rows["prefilter"] == "none") & (rows["spp"] == spp)])
        common = [k for k in pre if k in plain]
        if not common:
            continue
        er = float(np.median([pre[k][0] / plain[k][0] for k in common]))
        tr = float(np.median([pre[k][1] / plain[k][1] for k in common]))
        parts.append(f"plain {spp} spp: error x{fmt(er)}, time x{fmt(tr)} ({len(common)} scenes)")
        claims += [dict(kind="prefilter_error", spp=spp, value=er), dict(kind="prefilter_time", spp=spp, value=tr)]
    text = (f"Pre-filtered at {low} spp (the best pre-filtered method per scene) against the best plain sampling "
            "per scene: " + "; ".join(parts) + " (medians over scenes of per-scene ratios; below 1: the pre-filtered "
            "image is better or faster).")
    return Finding("prefilter", "Pre-filtering", text, claims)


def findings(s):
    return [prefilter(s)]
