"""Two studies of the same scenes at two image sizes, reconciled: the quick study (48 px)
against the presented one (256 px).

Only what both hold is compared: the scenes, spp levels and targets of both, and in each of those cells the
methods (rankings.METHOD: sampler, filter, radius, parameters, reconstruction, pre-filter) of both. Each study's
shared rows are ranked as answer.csv ranks rows (stats/equivalence.per_scene, across; factors.sampler_picks,
leaders), so a ratio here is to the best *shared* method of the scene (the best of a whole study may be a method
the other lacks) and the leaders are counted over the shared scenes.

compare(small, large, margin) returns a Comparison:
  missing   [(what, only in the small study, only in the large one)] of scenes, spp, targets, samplers,
            filters, radii: what cannot be compared
  answers   per (target, spp): each study's leading samplers (factors.leaders) with their status and the filter
            and radius of each leader's representative; `same_samplers` / `same_filters` when the sets are equal,
            `overlap` when the two sets of leading samplers share one
  ranks     per (target, spp, scene): Spearman's rank correlation of the shared methods' ratio to the best
            (rows with a finite ratio in both; the Pearson correlation of the average ranks), and `n` methods
  moves     per row of both: ratio_small, ratio_large and factor = ratio_large / ratio_small
  moves     per row ranked in both: ratio_small, ratio_large, factor = ratio_large / ratio_small (NaN unless
            the row's error is told from zero in both), noise share noise / error and `aliased` (aliasing told
            from zero: above 2 se) in each study
  shares    per (scene, spp) at the first target: each study's median noise share over the shared methods and
            the fraction of the randomised ones (not deterministic) with aliasing told from zero
  grid      per (scene, spp) at the first target: the fixed grid's (deterministic rows) lowest ratio among its
            rows told from zero, each study (NaN when none is)
"""
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..io import study_rows
from . import effect, equivalence, factors
from .rankings import CELL, METHOD

KEY = CELL + METHOD
SIDES = ("small", "large")


@dataclass
class Comparison:
    missing: list
    scenes: list
    targets: list
    levels: list
    samplers: list
    answers: pd.DataFrame
    ranks: pd.DataFrame
    moves: pd.DataFrame
    shares: pd.DataFrame
    grid: pd.DataFrame


def _values(df, col):
    v = df[col].unique()
    return sorted(float(x) for x in v) if col == "radius" else sorted(str(x) for x in v) if col != "spp" else \
        sorted(int(x) for x in v)


def missing(small, large):
    """[(what, only in small, only in large)] for each factor where the studies differ."""
    out = []
    for what, col in (("scenes", "scene"), ("spp", "spp"), ("targets", "target"), ("samplers", "sampler"),
                      ("filters", "filter_name"), ("radii", "radius")):
        a, b = _values(small, col), _values(large, col)
        if a != b:
            out.append((what, [x for x in a if x not in b], [x for x in b if x not in a]))
    return out


def shared(small, large):
    """The rows of each study whose (cell, method) the other holds too, with target as text."""
    a = small.assign(target=small["target"].astype(str))
    b = large.assign(target=large["target"].astype(str))
    ka, kb = (list(map(tuple, d[KEY].astype(str).to_numpy())) for d in (a, b))
    both = set(ka) & set(kb)
    return a[[k in both for k in ka]], b[[k in both for k in kb]]


def leaders(per, n_scenes, margin):
    """{(target, spp): (status, rows)} of the shared rows (as the answer table ranks them)."""
    summary = equivalence.across(per, margin)
    return factors.leaders(factors.sampler_picks(summary), n_scenes)


def config(r):
    return f"{r['filter_name']} r={r['radius']:g}"


def answers(lead_small, lead_large):
    out = []
    for key in sorted(set(lead_small) | set(lead_large)):
        rec = dict(target=key[0], spp=key[1])
        for side, lead in zip(SIDES, (lead_small, lead_large)):
            status, rows = lead.get(key, (factors.NONE, pd.DataFrame(columns=["sampler", "filter_name", "radius"])))
            rec[f"status_{side}"] = status
            rec[f"samplers_{side}"] = tuple(sorted(rows["sampler"]))
            rec[f"configs_{side}"] = tuple(sorted({config(r) for _, r in rows.iterrows()}))
        rec["same_samplers"] = rec["samplers_small"] == rec["samplers_large"]
        rec["same_filters"] = rec["configs_small"] == rec["configs_large"]
        rec["overlap"] = bool(set(rec["samplers_small"]) & set(rec["samplers_large"]))
        out.append(rec)
    return pd.DataFrame(out)


def spearman(x, y):
    """Spearman's rank correlation of two equal-length arrays (average ranks); NaN below 3 values or when
    one side is constant."""
    rx, ry = pd.Series(x).rank().to_numpy(), pd.Series(y).rank().to_numpy()
    if len(rx) < 3 or rx.std() == 0 or ry.std() == 0:
        return np.nan
    return float(np.corrcoef(rx, ry)[0, 1])


def pairs(per_small, per_large):
    """The rows ranked in both, side by side: ratio_small, ratio_large, aliasing shares, deterministic."""
    def prep(per):
        se = per["aliasing_se"] if "aliasing_se" in per.columns else np.nan
        ok = per["measured"].astype(bool) & (per["ratio"] > 0)
        return per.assign(aliased=per["aliasing"] > 2 * se, noise_share=per["noise"] / per["error"],
                          told=ok)
    cols = KEY + ["ratio", "told", "noise_share", "aliased", "deterministic"]
    m = prep(per_small)[cols].merge(prep(per_large)[cols], on=KEY, suffixes=("_small", "_large"))
    told = m["told_small"] & m["told_large"]
    m["factor"] = np.where(told, m["ratio_large"] / m["ratio_small"], np.nan)
    return m


def ranks(m):
    out = []
    for k, g in m.groupby(CELL, sort=True):
        ok = g[np.isfinite(g["ratio_small"]) & np.isfinite(g["ratio_large"])]
        out.append(dict(zip(CELL, k), n=len(ok), rho=spearman(ok["ratio_small"], ok["ratio_large"])))
    return pd.DataFrame(out, columns=CELL + ["n", "rho"])


def shares(m, target):
    g = m[m["target"] == target].groupby(["scene", "spp"], sort=True)
    out = g[["noise_share_small", "noise_share_large"]].median()
    r = m[(m["target"] == target) & ~m["deterministic_small"].astype(bool)].groupby(["scene", "spp"], sort=True)
    for side in SIDES:
        out[f"aliased_{side}"] = r[f"aliased_{side}"].mean()
    return out.reset_index()


def grid(m, target):
    d = m[(m["target"] == target) & m["deterministic_small"].astype(bool)]
    out = []
    for (scene, spp), g in d.groupby(["scene", "spp"], sort=True):
        rec = dict(scene=scene, spp=spp)
        for side in SIDES:
            r = g.loc[g[f"told_{side}"].astype(bool), f"ratio_{side}"]
            rec[f"ratio_{side}"] = float(r.min()) if len(r) else np.nan
        out.append(rec)
    return pd.DataFrame(out, columns=["scene", "spp", "ratio_small", "ratio_large"])


def compare(small, large, margin=effect.MARGIN):
    """The Comparison of two loaded studies (study_csv.load_study), small the smaller image size (module doc)."""
    a, b = shared(small, large)
    scenes = sorted(a["scene"].unique())
    targets = [t for t in study_rows.targets(large) if t in set(a["target"])]
    per_a, per_b = equivalence.per_scene(a, margin), equivalence.per_scene(b, margin)
    m = pairs(per_a, per_b)
    first = targets[0] if targets else ""
    return Comparison(missing(small, large), scenes, targets, sorted(int(s) for s in a["spp"].unique()),
                      sorted(a["sampler"].unique()),
                      answers(leaders(per_a, len(scenes), margin), leaders(per_b, len(scenes), margin)),
                      ranks(m), m, shares(m, first), grid(m, first))
