"""Which configurations the viewer shows (a chosen subset: images of every configuration would be far too large
to commit), chosen from the study CSV alone:

  A  every sampler at every spp with one good filter: the (filter, radius) with the lowest median over targets of
     the median mse_target at the middle spp level (computed over every scene and sampler; deterministic rows out),
     seed 0, and at the lowest spp seeds 0 and 1 (the flip-book; --flip-seeds);
  B  every filter x radius with one sampler (jittered when the study has it) at the middle spp, seed 0;
  C  the teaching trio (uniform, jittered, sobol: those present) at the lowest spp with the box r = 0.5, seeds 0 and 1.

A configuration is (scene, sampler, spp, filter, radius) in weighted reconstruction without pre-filtering; the
rows of other modes are not shown."""
import numpy as np

TEACHING_SAMPLERS = ("uniform", "jittered", "sobol")


def shown_rows(df):
    """The weighted, un-prefiltered rows (the viewer's configurations)."""
    keep = (df["reconstruction"].astype(str) == "weighted") & (df["prefilter"].astype(str).isin(["none", ""]))
    return df[keep]


def levels(df):
    return sorted(int(s) for s in df["spp"].unique())


def good_filter(df):
    """(filter, radius): lowest median over targets of the median mse_target at the middle spp."""
    rows = shown_rows(df)
    spp = levels(rows)[len(levels(rows)) // 2]
    rows = rows[(rows["spp"] == spp) & (rows["deterministic"].astype(int) == 0)] if "deterministic" in rows else \
        rows[rows["spp"] == spp]
    med = rows.groupby(["target", "filter_name", "radius"])["mse_target"].median().reset_index()
    score = med.groupby(["filter_name", "radius"])["mse_target"].median().sort_values(kind="mergesort")
    f, r = score.index[0]
    return str(f), float(r)


def pick_sampler(samplers, preferred=("jittered", "sobol", "random")):
    for s in preferred:
        if s in samplers:
            return s
    return sorted(samplers)[0]


class Plan:
    """The configurations of one study shown by the viewer: configs[scene] = list of dicts
    {sampler, spp, filter, radius, seeds (list of seed numbers rendered), sets (which of A, B, C)}."""

    def __init__(self, df, flip_seeds=2):
        rows = shown_rows(df)
        self.filter, self.radius = good_filter(df)
        self.levels = levels(rows)
        self.middle = self.levels[len(self.levels) // 2]
        samplers = sorted(rows["sampler"].unique())
        self.b_sampler = pick_sampler(samplers)
        self.teaching = [s for s in TEACHING_SAMPLERS if s in samplers]
        self.seeds = int(rows["seeds"].max())
        self.flip = min(self.seeds, flip_seeds)
        self.configs = {}
        for scene, sd in rows.groupby("scene", sort=True):
            have = {(str(r.sampler), int(r.spp), str(r.filter_name), float(r.radius))
                    for r in sd[["sampler", "spp", "filter_name", "radius"]].drop_duplicates().itertuples()}
            want = {}

            def add(key, seeds, tag):
                if key not in have:
                    return
                c = want.setdefault(key, {"sampler": key[0], "spp": key[1], "filter": key[2], "radius": key[3],
                                          "seeds": set(), "sets": set()})
                c["seeds"].update(seeds)
                c["sets"].add(tag)
            everyone = range(min(self.seeds, flip_seeds))
            for s in samplers:
                for spp in self.levels:
                    add((s, spp, self.filter, self.radius), everyone if spp == self.levels[0] else [0], "A")
            for (f, r) in sd[["filter_name", "radius"]].drop_duplicates().itertuples(index=False):
                add((self.b_sampler, self.middle, str(f), float(r)), [0], "B")
            for s in self.teaching:
                add((s, self.levels[0], "box", 0.5), everyone, "C")
            self.configs[str(scene)] = [dict(c, seeds=sorted(c["seeds"]), sets=sorted(c["sets"]))
                                        for _, c in sorted(want.items())]

    def describe(self):
        return (f"A: every sampler at spp {', '.join(map(str, self.levels))} with {self.filter} r={self.radius:g} "
                f"(the lowest median over targets of the median mse_target at {self.middle} spp), seed 0, "
                f"at {self.levels[0]} spp seeds 0-{self.flip - 1} of {self.seeds}; B: every filter x radius with {self.b_sampler} at {self.middle} spp, seed 0; "
                f"C: {', '.join(self.teaching)} at {self.levels[0]} spp with box r=0.5, seeds 0-{self.flip - 1}")


def image_stem(c, seed):
    return f"{c['sampler']}-spp{c['spp']}-{c['filter']}-r{c['radius']:g}-seed{seed}"


def crop_window(stack, size, step=4):
    """(x, y) of the size x size window with the largest sum over its pixels of the variance across `stack`
    (configurations x height x width: where the methods differ most)."""
    var = np.var(stack, axis=0)
    h, w = var.shape
    integral = np.pad(var.cumsum(0).cumsum(1), ((1, 0), (1, 0)))
    best, at = -1.0, (0, 0)
    for y in range(0, h - size + 1, step):
        for x in range(0, w - size + 1, step):
            s = integral[y + size, x + size] - integral[y, x + size] - integral[y + size, x] + integral[y, x]
            if s > best:
                best, at = s, (x, y)
    return at
