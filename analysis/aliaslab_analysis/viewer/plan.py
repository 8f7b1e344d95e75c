"""Which configurations the viewer shows (a chosen subset: images of every configuration would be far too large
to commit), chosen from the study CSV alone (answer.py computes the answer from it as answer.csv does):

  E  every method answer.csv calls equivalent to the best (in the scene or across scenes), every target and spp;
  P  the best of each sampler (its representative filter and radius) under every target at every spp: the
     leaders, the runners-up and the named losers of the findings;
  C  the teaching trio (uniform, jittered, sobol: those present) at the lowest spp with the box r = 0.5.
Seed 0 of each; at the lowest spp seeds 0 .. flip_seeds - 1 (the flip-book), for the default view's methods
0 .. CROP_SEEDS - 1 (their noise, which the crop is judged by).

A configuration is (scene, sampler, spp, filter, radius) in weighted reconstruction without pre-filtering; the
rows of other modes are not shown."""
import numpy as np

from .answer import Answer

TEACHING_SAMPLERS = ("uniform", "jittered", "sobol")
CROP_SEEDS = 4  # seeds rendered for the default view's methods (their mean images and noise choose the crop)

WHOLE = {"all": "every configuration shown", "answer": "the methods equivalent to the best (set E) and the default "
         "view", "headline": "the default view's methods and those equivalent to the best against the primary target at "
         "the lowest spp (the page's first answer)", "view": "the default view's methods"}  # --whole: whose whole image and whole FLIP maps are held


def shown_rows(df):
    """The weighted, un-prefiltered rows (the viewer's configurations)."""
    keep = (df["reconstruction"].astype(str) == "weighted") & (df["prefilter"].astype(str).isin(["none", ""]))
    return df[keep]


def levels(df):
    return sorted(int(s) for s in df["spp"].unique())


class Plan:
    """The configurations of one study shown by the viewer: configs[scene] = list of dicts
    {sampler, spp, filter, radius, seeds (list of seed numbers rendered), sets (which of E, P, C), why (the
    answer's reasons)}; default: answer.Answer.default_view() (keys as tuples)."""

    def __init__(self, df, flip_seeds=2, notes=None):
        rows = shown_rows(df)
        self.levels = levels(rows)
        samplers = sorted(rows["sampler"].unique())
        self.teaching = [s for s in TEACHING_SAMPLERS if s in samplers]
        self.seeds = int(rows["seeds"].max())
        self.flip = min(self.seeds, flip_seeds)
        self.whole = "answer"  # whose whole images are stored (a key of WHOLE; cli.py's --whole)
        answer = Answer(df, notes)
        self.default = answer.default_view()
        self.configs = {}
        for scene, sd in rows.groupby("scene", sort=True):
            have = {(str(r.sampler), int(r.spp), str(r.filter_name), float(r.radius))
                    for r in sd[["sampler", "spp", "filter_name", "radius"]].drop_duplicates().itertuples()}
            want = {}
            everyone = range(self.flip)

            def add(key, tag, why=()):
                if key not in have:
                    return
                c = want.setdefault(key, {"sampler": key[0], "spp": key[1], "filter": key[2], "radius": key[3],
                                          "seeds": set(), "sets": set(), "why": []})
                c["seeds"].update(everyone if key[1] == self.levels[0] else [0])
                c["sets"].add(tag)
                c["why"] += [w for w in why if w not in c["why"]]
            for key, why in answer.wanted.get(str(scene), {}).items():
                for tag in sorted(answer.sets[str(scene)][key]):
                    add(key, tag, why)
            for s in self.teaching:
                add((s, self.levels[0], "box", 0.5), "C", ["teaching: box r=0.5 at the lowest spp"])
            for key in ([self.default["cfg"]] + self.default["pins"]) if self.default else []:
                if key in want:  # the default view's noise, which the crop is judged by, from more seeds
                    want[key]["seeds"].update(range(min(self.seeds, max(self.flip, CROP_SEEDS))))
            first = answer.headline.get(str(scene), set())
            self.configs[str(scene)] = [dict(c, seeds=sorted(c["seeds"]), sets=sorted(c["sets"]), headline=k in first)
                                        for k, c in sorted(want.items())]

    def describe(self):
        return (f"E: every method the answer calls equivalent to the best (in the scene or across scenes, every "
                f"target, spp {', '.join(map(str, self.levels))}); P: the best of each sampler (its filter and "
                f"radius with the lowest median ratio to the best over scenes) under every target at every spp; "
                f"C: {', '.join(self.teaching)} at {self.levels[0]} spp with box r=0.5. Seed 0 of each, at "
                f"{self.levels[0]} spp seeds 0-{self.flip - 1} of {self.seeds}. Whole images and whole FLIP maps: "
                f"{WHOLE[self.whole]} (the crops of all)")


def image_stem(c, seed):
    return f"{c['sampler']}-spp{c['spp']}-{c['filter']}-r{c['radius']:g}-seed{seed}"


def window_sums(a, size, step):
    """{(x, y): the sum of a over the size x size window at (x, y)} for x, y multiples of step."""
    h, w = a.shape
    integral = np.pad(a.cumsum(0).cumsum(1), ((1, 0), (1, 0)))
    return {(x, y): integral[y + size, x + size] - integral[y, x + size] - integral[y + size, x] + integral[y, x]
            for y in range(0, h - size + 1, step) for x in range(0, w - size + 1, step)}


def crop_window(stack, size, step=4, noise=None):
    """(x, y) of the size x size window where the methods differ most: the largest sum over its pixels of the
    variance across `stack` (methods x height x width: their mean images), divided, when `noise` (methods x
    height x width: each mean image's variance, the seeds' sample variance over their number) is given, by the
    window's summed noise (the mean over the methods) plus the image's average noise over a window (a prior, so
    a noiseless flat window does not win by dividing by nothing). With noise, a window where the methods differ
    only by their noise scores about 1 and one where their mean images differ in structure scores more."""
    between = window_sums(np.var(stack, axis=0), size, step)
    if noise is None:
        score = between
    else:
        n = np.mean(noise, axis=0)
        prior = float(n.mean()) * size * size + 1e-30
        within = window_sums(n, size, step)
        score = {k: v / (within[k] + prior) for k, v in between.items()}
    return max(sorted(score), key=lambda k: (score[k], -k[1], -k[0]))
