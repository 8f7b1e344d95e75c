"""The grid (issue 29 item 5) and the samplers against random: the fixed grid is deterministic (the same
image for every seed) and not ranked; the shifted grid ranks in its place. Ratios here are medians over
scenes of per-scene ratios (never ratios of medians), against the primary target, with the target's own
filter when the study has it (box r = 0.5), else each sampler's lowest error."""
import numpy as np

from .study import Finding, fmt

SHIFTED = "uniform-shifted"


def grid(s):
    det = s.rows()[s.rows()["deterministic"]]
    if det.empty:
        return None
    samplers = ", ".join(f"`{x}`" for x in sorted(det["sampler"].unique()))
    text = (f"The fixed grid ({samplers}) gives the same image for every seed: its error is shown as "
            "`deterministic` (no standard error), one alignment of the grid with the scene, lucky or not; it is "
            "shown on the charts but not ranked. ")
    claims = [dict(kind="deterministic_rows", value=len(det))]
    if (s.df["sampler"] == SHIFTED).any():
        text += (f"Rankings use `{SHIFTED}` instead: one seeded offset of the whole grid per seed, so its error and "
                 "standard error are the expectation over alignments. Its structured error then changes from seed "
                 "to seed and the decomposition counts it as noise; the error spectrum still shows it as structure.")
        ratios = []
        for spp in s.levels:
            v = sampler_ratio(s, "uniform", SHIFTED, spp)
            if v is not None:
                ratios.append((spp, v))
                claims.append(dict(kind="fixed_over_shifted", spp=spp, value=v[0], scenes=v[1]))
        if ratios:
            text += (" Fixed over shifted (median of per-scene ratios): "
                     + ", ".join(f"{fmt(v[0])} at {spp} spp ({v[1]} scenes)" for spp, v in ratios) + ".")
    else:
        text += f"This study has no `{SHIFTED}` rows, so the grid is not ranked at all."
    return Finding("grid", "The grid", text, claims)


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
