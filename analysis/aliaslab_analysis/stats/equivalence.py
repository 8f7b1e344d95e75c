"""Equivalence per scene and across scenes: the numbers behind answer.csv (docs/science.md "Answers a
practitioner can act on").

per_scene(df, margin) applies effect.cell_effects to every (target, scene, spp) cell of the rows with a
finite error (the fixed grid included: it is ranked like any method, as deterministic): each row's ratio to
its scene's best, its 95 % interval, heavy_tailed and its verdict.

across(per, margin) gives per (target, spp, method): `scenes` (scenes with a ratio), `equivalent`, `worse`,
`undetermined` and `heavy` (scenes with that verdict or flag), the median ratio over the scenes and its 95 %
percentile bootstrap interval over scenes (bootstrap.py: 2000 resamples, seed 29), and a verdict by the same
rule as in one scene applied to that interval, with two more conditions for *equivalent*: the method is
equivalent in at least half of its scenes (the bootstrap sees only the spread between scenes, not each
scene's own interval, so a median inside the margin made of undetermined scenes is not enough) and it is
heavy-tailed in none.

table(per, summary, margin) is answer.csv: one row per target x spp x scope (a scene, or "all") x method.
"""
import numpy as np
import pandas as pd

from . import bootstrap, effect
from .rankings import METHOD

CELL = ["target", "scene", "spp"]
ALL = "all"
COLUMNS = (["target", "spp", "scope", "sampler", "filter", "radius", "filter_params", "reconstruction", "prefilter",
            "deterministic", "ratio", "ci_low", "ci_high", "verdict", "heavy_tailed", "margin", "interval", "best",
            "error", "error_se", "scenes", "equivalent_scenes"])


def per_scene(df, margin=effect.MARGIN):
    """Every row with a finite error, with the columns of effect.cell_effects."""
    ok = df[np.isfinite(df["error"].to_numpy(dtype=float))]
    parts = [effect.cell_effects(cell, margin) for _, cell in ok.groupby(CELL, sort=True)]
    if not parts:
        return ok.assign(ratio=np.nan, ci_low=np.nan, ci_high=np.nan, interval="none", best=False,
                         heavy_tailed=False, measured=False, verdict=effect.UNDETERMINED)
    return pd.concat(parts)


def verdict(low, high, margin, heavy, equivalent, scenes):
    """The across-scene verdict (module doc)."""
    v = effect.verdict(low, high, margin, heavy > 0)
    if v == effect.EQUIVALENT and 2 * equivalent < scenes:
        return effect.UNDETERMINED
    return v


def across(per, margin=effect.MARGIN, seed=bootstrap.SEED, n_boot=bootstrap.N_BOOT):
    """Per (target, spp, method): the across-scene record (module doc)."""
    out = []
    key = ["target", "spp"] + METHOD
    for k, g in per.groupby(key, sort=True, dropna=False):
        r = g["ratio"].to_numpy(dtype=float)
        fin = np.isfinite(r)
        lo, hi = bootstrap.interval(r[fin], seed, n_boot)
        heavy = int(g["heavy_tailed"].sum())
        v = g["verdict"]
        med = float(np.median(r[fin])) if fin.any() else np.nan
        out.append(dict(zip(key, k), deterministic=bool(g["deterministic"].astype(bool).any()),
                        scenes=int(fin.sum()), equivalent=int((v == effect.EQUIVALENT).sum()),
                        worse=int((v == effect.WORSE).sum()), undetermined=int((v == effect.UNDETERMINED).sum()),
                        heavy=heavy, median_ratio=med, ci_low=lo, ci_high=hi,
                        verdict=verdict(lo, hi, margin, heavy, int((v == effect.EQUIVALENT).sum()), int(fin.sum()))))
    cols = key + ["deterministic", "scenes", "equivalent", "worse", "undetermined", "heavy", "median_ratio",
                  "ci_low", "ci_high", "verdict"]
    t = pd.DataFrame(out, columns=cols)
    return t.sort_values(["target", "spp", "median_ratio"], kind="stable").reset_index(drop=True)


def table(per, summary, margin=effect.MARGIN):
    """answer.csv as a DataFrame (COLUMNS): the scenes' rows, then the across-scene ones (scope "all")."""
    scenes = per.rename(columns={"filter_name": "filter", "scene": "scope"}).assign(
        margin=margin, scenes=1, equivalent_scenes=lambda d: (d["verdict"] == effect.EQUIVALENT).astype(int))
    scenes["deterministic"] = scenes["deterministic"].astype(bool)
    alls = summary.rename(columns={"filter_name": "filter", "median_ratio": "ratio",
                                   "equivalent": "equivalent_scenes"}).assign(
        scope=ALL, margin=margin, interval="bootstrap-scenes", best=False, error=np.nan, error_se=np.nan)
    alls["heavy_tailed"] = alls["heavy"] > 0
    out = pd.concat([alls[COLUMNS], scenes[COLUMNS]], ignore_index=True)
    order = (out["scope"] != ALL).astype(int)
    out = out.assign(_o=order).sort_values(["target", "spp", "_o", "scope", "ratio"], kind="stable")
    return out.drop(columns="_o").reset_index(drop=True)

