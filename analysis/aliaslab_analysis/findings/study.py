"""Study: what every finding shares, computed once; Finding; and the finding that says what study this is.

A study is *quick* when it is smaller than 256 px on the larger side or its references have fewer than
64 x its highest spp (the issue's bar for a study meant to be read); the page says so.
"""
from dataclasses import dataclass, field

import numpy as np

from ..io import study_rows
from ..stats import effect, equivalence, factors, fronts, rankings

TRUSTED_SIZE = 256
TRUSTED_REF_FACTOR = 64


@dataclass
class Finding:
    key: str
    title: str
    text: str
    claims: list = field(default_factory=list)


def method_name(r):
    return rankings.method_label(r, show_recon=False)


def method_key(r):
    return tuple(r[c] for c in rankings.METHOD)


def plural(n, word):
    return f"{n} {word}" + ("" if n == 1 else "s")


def fmt(v, digits=3):
    return f"{v:.{digits}g}"


class Study:
    """What every finding shares, computed once: the rows with their ratio to each scene's best, interval and
    verdict at the margin (stats/equivalence.per_scene), the across-scene records (`summary`), each sampler's
    representative (`picks`), the leading samplers per (target, spp) (`leaders`) and answer.csv (`answer`)."""

    def __init__(self, df, notes, margin=effect.MARGIN):
        self.df = df
        self.notes = notes
        self.margin = float(margin)
        self.targets = study_rows.targets(df)
        self.primary = self.targets[0]
        self.scenes = sorted(df["scene"].unique())
        self.levels = sorted(int(s) for s in df["spp"].unique())
        self.ranked = equivalence.per_scene(df, self.margin)
        self.summary = equivalence.across(self.ranked, self.margin)
        self.picks = factors.sampler_picks(self.summary)
        self.leaders = factors.leaders(self.picks, len(self.scenes))
        self.answer = equivalence.table(self.ranked, self.summary, self.margin)
        self._points = None

    def points(self):
        """The (method, spp) points across scenes against the primary target (stats/fronts.summary_points),
        computed once."""
        if self._points is None:
            self._points = fronts.summary_points(self.ranked, self.summary, self.primary, rankings.METHOD)
        return self._points

    def rows(self, target=None):
        """The rows against one target (the primary by default): the target-independent columns once."""
        return self.df[self.df["target"].astype(str) == (target or self.primary)]

    def pick(self, target, spp, sampler):
        """The representative record of `sampler` at (target, spp) (stats/factors.sampler_picks), or None."""
        p = self.picks
        p = p[(p["target"] == target) & (p["spp"] == spp) & (p["sampler"] == sampler)]
        return p.iloc[0] if len(p) else None


def facts(df):
    """The study's size, spp, seeds, references and targets, read from the rows."""
    side = np.maximum(df["width"].to_numpy(dtype=int), df["height"].to_numpy(dtype=int))
    return dict(scenes=int(df["scene"].nunique()), size=int(side.max()), smallest=int(side.min()),
                spp=sorted(int(s) for s in df["spp"].unique()),
                seeds=sorted(int(k) for k in df["seeds"].unique()),
                ref_spp=sorted(int(r) for r in df["ref_spp"].unique()),
                targets=study_rows.targets(df), rows=int(len(df)),
                samplers=sorted(df["sampler"].unique()), filters=sorted(df["filter_name"].unique()),
                radii=sorted(float(r) for r in df["radius"].unique()))


def is_quick(f):
    return f["size"] < TRUSTED_SIZE or min(f["ref_spp"]) < TRUSTED_REF_FACTOR * max(f["spp"])


def describe(s):
    f = facts(s.df)
    configs = f["rows"] // max(1, len(f["targets"]))
    size = f"{f['size']} px on the larger side" + (f" (the smallest scene {f['smallest']} px)"
                                                     if f["smallest"] != f["size"] else "")
    ref = ", ".join(map(str, f["ref_spp"]))
    factor = min(f["ref_spp"]) / max(f["spp"])
    text = (f"This study: {plural(f['scenes'], 'scene')} at {size}; {len(f['samplers'])} samplers, {len(f['filters'])} "
            f"filters at radii {', '.join(f'{r:g}' for r in f['radii'])}; spp {', '.join(map(str, f['spp']))}; "
            f"{', '.join(map(str, f['seeds']))} seeds; references at {ref} spp ({factor:g}x the highest spp); "
            f"targets {', '.join('`' + t + '`' for t in f['targets'])} ({f['rows']} rows: {configs} configurations "
            f"x {plural(len(f['targets']), 'target')}).")
    if is_quick(f):
        text += (f" **This is a quick study** (below {TRUSTED_SIZE} px or references below {TRUSTED_REF_FACTOR}x "
                 "the highest spp): it checks that the tool runs end to end; its answer is not the one to trust.")
    claims = [dict(kind="n_scenes", value=f["scenes"]), dict(kind="size", value=f["size"]),
              dict(kind="rows", value=f["rows"]), dict(kind="ref_spp_min", value=min(f["ref_spp"]))]
    return Finding("study", "What study this is", text, claims)
