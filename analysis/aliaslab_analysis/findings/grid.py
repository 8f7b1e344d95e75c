"""The grid (docs/science.md "The grid and alignment") and the samplers against random, against the primary
target. The fixed grid (`uniform`, deterministic) is ranked like any method: its interval holds the references'
error only. Its alignment, when the CSV has it (align_* columns on the fixed grid's rows: the mean error over K
seeded sub-pixel camera offsets with references moved with the camera, and its spread), is stated beside it:
per spp, at the grid's representative configuration, the medians over scenes of align_mse_target / mse_target
(the mean over alignments against the centred one) and of align_mse_target / the scene's best. The shifted grid
is a randomised (Cranley-Patterson rotated) lattice, a sampler of its own. Ratios against random are medians
over scenes of per-scene ratios (never ratios of medians), box r = 0.5 when the study has it, else each
sampler's lowest error."""
import numpy as np

from .answer import config, record
from .study import Finding, fmt

FIXED, SHIFTED = "uniform", "uniform-shifted"
ALIGN = ["align_offsets", "align_mse_target", "align_mse_target_sd", "align_mse_target_se"]


def alignment(s, spp):
    """(median of align / centred, median of align / best, median sd / mean, scenes, K) at the grid's pick, or
    None when the CSV has no alignment columns there."""
    if not all(c in s.df.columns for c in ALIGN):
        return None
    p = s.pick(s.primary, spp, FIXED)
    if p is None:
        return None
    r = s.ranked
    r = r[(r["target"].astype(str) == s.primary) & (r["spp"] == spp) & (r["sampler"] == FIXED)
          & (r["filter_name"] == p["filter_name"]) & (r["radius"] == p["radius"])
          & (r["filter_params"] == p["filter_params"])]
    r = r[np.isfinite(r["align_mse_target"].to_numpy(dtype=float))]
    if r.empty:
        return None
    a = r["align_mse_target"].to_numpy(dtype=float)
    best = r["error"].to_numpy(dtype=float) / r["ratio"].to_numpy(dtype=float)
    return (float(np.median(a / r["error"].to_numpy(dtype=float))), float(np.nanmedian(a / best)),
            float(np.median(r["align_mse_target_sd"].to_numpy(dtype=float) / a)), len(r),
            int(r["align_offsets"].max()))


def grid(s):
    det = s.rows()[s.rows()["deterministic"]]
    claims = [dict(kind="deterministic_rows", value=len(det))]
    parts = []
    if len(det):
        parts.append(f"The fixed grid (`{FIXED}`) gives the same image for every seed: it is ranked like any method, "
                     "as deterministic (its interval holds the references' error only). With the box filter it is the "
                     "midpoint rule: on content smooth within a pixel its error is second order, a property of the "
                     "method; what it depends on is where the scene's features fall against the pixels.")
        per = []
        for spp in s.levels:
            p = s.pick(s.primary, spp, FIXED)
            if p is None:
                continue
            text = f"at {spp} spp {config(p)} ({record(p, len(s.scenes))})"
            claims += [dict(kind="pick_median_ratio", target=s.primary, spp=spp, sampler=FIXED, value=float(p["median_ratio"])),
                       dict(kind="pick_equivalent", target=s.primary, spp=spp, sampler=FIXED, value=float(p["equivalent"]))]
            a = alignment(s, spp)
            if a is not None:
                text += (f"; over {a[4]} camera offsets (references moved with the camera) its mean error is "
                         f"{fmt(a[0])}x the centred one and {fmt(a[1])}x the best, spread {fmt(100 * a[2], 2)} % "
                         f"(medians over {a[3]} scenes)")
                claims += [dict(kind="align_over_centred", spp=spp, value=a[0]),
                           dict(kind="align_over_best", spp=spp, value=a[1])]
            per.append(text)
        if per:
            parts.append(f"Against `{s.primary}`: " + "; ".join(per) + ".")
        if not all(c in s.df.columns for c in ALIGN):
            parts.append("This CSV has no alignment columns (align_mse_target: the grid's mean over sub-pixel camera "
                         "offsets), so its spread over alignments is not measured here.")
    if (s.df["sampler"] == SHIFTED).any():
        parts.append(f"`{SHIFTED}` is not the grid's expectation over alignments: it moves every cell's point by one "
                     "random offset per image (a Cranley-Patterson rotation), a randomised lattice, unbiased but "
                     "without the midpoint rule's symmetry, so on smooth content its variance falls only as 1/N. "
                     "It is ranked as a sampler of its own.")
    if not parts:
        return None
    return Finding("grid", "The grid", " ".join(parts), claims)


def per_scene_error(s, sampler, spp):
    """{scene: error} of `sampler` at spp: box r = 0.5 when present, else its lowest error."""
    r = s.rows()
    r = r[(r["sampler"] == sampler) & (r["spp"] == spp) & (r["prefilter"] == "none")]
    box = r[(r["filter_name"] == "box") & (r["radius"] == 0.5)]
    use = box if len(box) else r
    out = {}
    for scene, g in use.groupby("scene"):
        v = g["error"].to_numpy(dtype=float)
        if np.isfinite(v).any():
            out[scene] = float(np.nanmin(v))
    return out


def sampler_ratio(s, a, b, spp):
    """(median over scenes of error_a / error_b, scenes) or None."""
    ea, eb = per_scene_error(s, a, spp), per_scene_error(s, b, spp)
    common = [k for k in ea if k in eb and eb[k] > 0]
    if not common:
        return None
    return float(np.median([ea[k] / eb[k] for k in common])), len(common)


def against_random(s):
    samplers = [x for x in sorted(s.df["sampler"].unique()) if x != "random"]
    if "random" not in set(s.df["sampler"]) or not samplers:
        return None
    parts, claims = [], []
    for x in samplers:
        vals = []
        for spp in s.levels:
            v = sampler_ratio(s, x, "random", spp)
            vals.append(fmt(v[0], 2) if v else "n/a")
            if v:
                claims.append(dict(kind="against_random", sampler=x, spp=spp, value=v[0], scenes=v[1]))
        parts.append(f"{x} {' / '.join(vals)}")
    text = ("Samplers against random (median over scenes of the per-scene ratio of errors against the target, "
            f"box r = 0.5 where the study has it; {' / '.join(map(str, s.levels))} spp): " + "; ".join(parts) + ".")
    return Finding("samplers", "Samplers against random", text, claims)


def findings(s):
    return [grid(s), against_random(s)]
