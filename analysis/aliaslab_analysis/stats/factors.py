"""The answer by factor, from the across-scene records (equivalence.across): which samplers, each at its best
filter and radius; which filter and radius with them; sampler families named as such.

sampler_picks(summary)  per (target, spp, sampler): the sampler's representative, the method (filter, radius,
                        parameters, reconstruction) with the lowest median ratio over scenes (ties: more scenes
                        equivalent), plain sampling only (prefilter none). A practitioner sets one configuration,
                        so a sampler is judged at one filter and radius, not at each scene's own best.
leaders(picks, n)       per (target, spp): the samplers whose representative is equivalent across scenes or
                        equivalent to the best in at least half of the n scenes (status EQUIVALENT when one of
                        them is equivalent across scenes, else HALF); when none is, those equivalent in the most
                        scenes (MOST, at least one); when no sampler is equivalent in any scene, the lowest
                        median (NONE).
filter_picks(summary, samplers)  per (target, spp, filter): the filter's best radius with the given samplers
                        (the lowest median over them), with its record.
family_names(samplers, present)  the samplers with every family (FAMILIES) whose members in the study are all
                        among them named as the family.
"""
import numpy as np
import pandas as pd

from .rankings import METHOD

EQUIVALENT, HALF, MOST, NONE = "equivalent", "half", "most scenes", "none"
# Families: samplers that share the property the literature credits them with. "multi-stratified": stratified
# at once in the 2-D cells and in both 1-D projections at these spp (multi-jittered, correlated multi-jittered,
# and the (0,2) nets: PMJ02, Owen-scrambled Sobol' and its Morton-ordered ZSobol, Hammersley); the two grids
# are different estimators (docs/science.md "The grid and alignment") and are never one family.
FAMILIES = {"multi-stratified": ("multijittered", "cmj", "pmj02", "sobol", "zsobol", "hammersley")}


def _plain(summary):
    return summary[summary["prefilter"].astype(str) == "none"]


def _rank(g):
    return g.assign(_neg=-g["equivalent"]).sort_values(["median_ratio", "_neg"], kind="stable").drop(columns="_neg")


def sampler_picks(summary):
    """One row per (target, spp, sampler): its representative method's record (module doc)."""
    parts = [_rank(g).head(1) for _, g in _plain(summary).groupby(["target", "spp", "sampler"], sort=True)]
    if not parts:
        return summary.iloc[0:0]
    out = pd.concat(parts)
    return out[np.isfinite(out["median_ratio"].to_numpy(dtype=float))].reset_index(drop=True)


def half(n_scenes):
    """The number of scenes that is at least half of n_scenes."""
    return (int(n_scenes) + 1) // 2


def leaders(picks, n_scenes):
    """{(target, spp): (status, rows)} (module doc); rows sorted by median ratio."""
    out = {}
    for (t, spp), g in picks.groupby(["target", "spp"], sort=True):
        g = _rank(g)
        lead = g[(g["verdict"] == EQUIVALENT) | (g["equivalent"] >= half(n_scenes))]
        if len(lead):
            status = EQUIVALENT if (lead["verdict"] == EQUIVALENT).any() else HALF
            out[(t, int(spp))] = (status, lead)
        elif g["equivalent"].max() > 0:
            out[(t, int(spp))] = (MOST, g[g["equivalent"] == g["equivalent"].max()])
        else:
            out[(t, int(spp))] = (NONE, g.head(1))
    return out


def filter_picks(summary, target, spp, samplers):
    """Per filter: its best (lowest median) method among `samplers` at (target, spp), sorted by median."""
    s = _plain(summary)
    s = s[(s["target"] == target) & (s["spp"] == spp) & s["sampler"].isin(list(samplers))]
    parts = [_rank(g).head(1) for _, g in s.groupby("filter_name", sort=True)]
    return _rank(pd.concat(parts)) if parts else s


def family_names(samplers, present):
    """[(name, members)]: each family all of whose members in `present` are in `samplers` (and at least two
    are) as (family, its members), then the other samplers one by one as (sampler, ())."""
    chosen = set(samplers)
    out = []
    for fam, members in FAMILIES.items():
        here = [m for m in members if m in set(present)]
        if len(here) >= 2 and set(here) <= chosen:
            out.append((fam, tuple(sorted(here))))
            chosen -= set(here)
    return out + [(s, ()) for s in samplers if s in chosen]


def method_of(row):
    return tuple(row[c] for c in METHOD)
