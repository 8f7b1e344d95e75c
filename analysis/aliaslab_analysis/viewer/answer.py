"""The methods the answer names, for the viewer: computed from the study CSV by the same code as
answer.csv and the findings (findings/study.Study: stats/equivalence, stats/factors), so the viewer holds what
the page names without reading a file the report writes later.

Per scene, the configurations (sampler, spp, filter, radius) of weighted reconstruction without pre-filtering:
  E  every method answer.csv calls equivalent to the best (verdict "equivalent") in that scene or across scenes,
     under every target and at every spp;
  P  the best of each sampler (stats/factors.sampler_picks: its lowest median ratio over scenes) under every
     target and at every spp: the findings' leaders, their runners-up and the named losers (jittered, random
     "at their own best", the fixed grid) are among them.
Each configuration carries why it is there, in words ("equivalent to the best, box:0.5, 4 spp, this scene").

default_view(...) is the view the viewer opens on: the primary target's leading method at the lowest spp (the
first of factors.leaders: the lowest median ratio), the best of the runner-up family (the next sampler by
median ratio outside the leader's family), and jittered at its own best."""
from ..findings.study import Study
from ..stats import factors

SHOWN = ("weighted", "none")  # the (reconstruction, prefilter) the viewer renders


def key_of(r, filt="filter_name"):
    return (str(r["sampler"]), int(r["spp"]), str(r[filt]), float(r["radius"]))


def plain(t):
    return t[(t["reconstruction"].astype(str) == SHOWN[0]) & (t["prefilter"].astype(str).isin([SHOWN[1], ""]))]


class Answer:
    """wanted[scene] = {config key: [reasons]}; sets[scene] = {config key: set of "E"/"P"}; headline[scene] = the
    keys equivalent to the best against the primary target at the lowest spp (the page's first answer); s: the Study."""

    def __init__(self, df, notes=None):
        self.s = Study(df, notes or [])
        self.wanted, self.sets, self.headline = {}, {}, {}
        ans = plain(self.s.answer)
        eq = ans[ans["verdict"] == factors.EQUIVALENT]
        picks = plain(self.s.picks)
        for scene in self.s.scenes:
            w, sets = self.wanted.setdefault(scene, {}), self.sets.setdefault(scene, {})

            def add(key, why, tag):
                w.setdefault(key, [])
                if why not in w[key]:
                    w[key].append(why)
                sets.setdefault(key, set()).add(tag)
            for _, r in eq[(eq["scope"] == scene) | (eq["scope"] == "all")].iterrows():
                where = "across scenes" if r["scope"] == "all" else "in this scene"
                add(key_of(r, "filter"), f"equivalent to the best {where} against {r['target']} at {int(r['spp'])} spp", "E")
                if r["target"] == self.s.primary and int(r["spp"]) == self.s.levels[0]:
                    self.headline.setdefault(scene, set()).add(key_of(r, "filter"))
            for _, r in picks.iterrows():
                add(key_of(r), f"best of {r['sampler']} against {r['target']} at {int(r['spp'])} spp "
                               f"(median {r['median_ratio']:.3g}x the best)", "P")

    def default_view(self):
        """{"cfg": key, "pins": [keys], "why": words} for the primary target at the lowest spp (module doc)."""
        s = self.s
        t, spp = s.primary, s.levels[0]
        picks = plain(s.picks)
        picks = factors._rank(picks[(picks["target"] == t) & (picks["spp"] == spp)])
        if not len(picks):
            return None
        lead = s.leaders.get((t, spp), (None, picks.head(1)))[1]
        first = lead.iloc[0]
        present = sorted(s.df["sampler"].unique())
        family = next((m for _, m in factors.family_names(list(picks["sampler"]), present)
                       if first["sampler"] in m), (first["sampler"],))
        others = [r for _, r in picks.iterrows() if r["sampler"] not in family and r["sampler"] != "jittered"]
        fam_of = lambda x: next((m for m in factors.FAMILIES.values() if x in m), (x,))  # noqa: E731
        runner = next((r for r in others if not set(fam_of(r["sampler"])) & set(fam_of(first["sampler"]))),
                      others[0] if others else None)
        jit = picks[picks["sampler"] == "jittered"]
        pins = [key_of(r) for r in ([runner] if runner is not None else []) + [jit.iloc[0] if len(jit) else None]
                if r is not None]
        pins = [p for i, p in enumerate(pins) if p != key_of(first) and p not in pins[:i]]
        why = (f"the leading method against {t} at {spp} spp ({first['sampler']}, {first['median_ratio']:.3g}x the "
               "best)" + (f", the runner-up family's best ({runner['sampler']}, {runner['median_ratio']:.3g}x)"
                          if runner is not None else "") +
               (f", jittered at its own best ({jit.iloc[0]['median_ratio']:.3g}x)" if len(jit) else ""))
        return {"cfg": key_of(first), "pins": pins, "why": why, "target": t, "spp": spp}
