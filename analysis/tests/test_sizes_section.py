"""The quick study against the presented one (report/sizes.py, stats/sizes.py), on a synthetic pair of studies
whose answer is known by construction, every number of the section recomputed by another path (plain pandas).

The pair: scenes a, b, c at 48 px and 256 px (plus scene d at 48 px only, sampler halton at 48 px only, cmj at
256 px only, 64 spp at 48 px only: what cannot be compared), target box:0.5, samplers random, jittered, sobol and
the fixed grid (uniform, deterministic), filters box r=0.5 and tent r=1, 8 seeds with a 0.1 % spread (tight
intervals). At 4 spp sobol with box r=0.5 is the best in every scene at both sizes: the same answer. At 16 spp
it is the best in every scene at 48 px, but at 256 px jittered with tent r=1 is the best in scenes b and c (2 of
3: the leader), sobol in a only: another answer. The grid is 1.5x the best at 48 px and 2.5x at 256 px; the
noise share of a row is 70 % (random), 50 % (jittered), 30 % (sobol) and 0 (the grid), halved in scene b at
256 px."""
import html
import os
import re
import tempfile
import unittest

import numpy as np
import pandas as pd

from ..aliaslab_analysis.io import study_csv
from ..aliaslab_analysis.report import sizes as section

SEEDS = 8
SCENES = ["a", "b", "c"]
# (sampler, filter, radius) -> error in scenes where sobol box leads; the methods' order is sobol < jittered
# < random within a filter, box r=0.5 < tent r=1 by a factor 1.3.
BASE = {"sobol": 1.0, "jittered": 2.0, "random": 5.0, "halton": 1.1, "cmj": 1.05}
FILTERS = [("box", 0.5, 1.0), ("tent", 1.0, 1.3)]
NOISE = {"random": 0.7, "jittered": 0.5, "sobol": 0.3, "uniform": 0.0}  # noise / error


def error(size, scene, sampler, filt, spp):
    k = dict((f, k) for f, _, k in FILTERS)[filt]
    if sampler == "uniform":
        return (1.5 if size == 48 else 2.5) * k  # the grid's ratio to the best (sobol box = 1.0), with box
    e = BASE[sampler] * k
    if size == 256 and spp == 16 and scene in ("b", "c") and sampler == "jittered" and filt == "tent":
        e = 0.5  # jittered tent r=1 becomes the best
    if size == 256 and scene == "c" and sampler == "random":
        e = {"box": 12.0, "tent": 0.9}[filt]  # moves the order in scene c (rank agreement below 1)
    return e


def rows(size):
    scenes = SCENES + (["d"] if size == 48 else [])
    samplers = ["random", "jittered", "sobol", "uniform"] + (["halton"] if size == 48 else ["cmj"])
    for scene in scenes:
        for spp in ([4, 16, 64] if size == 48 else [4, 16]):
            for sampler in samplers:
                for filt, radius, _ in FILTERS:
                    e = error(size, scene, sampler, filt, spp)
                    det = sampler == "uniform"
                    seeds = [e] * SEEDS if det else [e * (1 + 0.001 * (k - 3.5)) for k in range(SEEDS)]
                    noise = e * NOISE.get(sampler, 0.5) * (0.5 if (size == 256 and scene == "b") else 1.0)
                    se = 1e-6 if det else float(np.std(seeds, ddof=1) / np.sqrt(SEEDS))
                    yield dict(scene=scene, width=size, height=size, sampler=sampler, spp=spp, filter=filt,
                               radius=radius, filter_params=f"{filt} r={radius:g}", reconstruction="weighted",
                               seeds=SEEDS, mse=e, aliasing=0.0 if not det else e, noise=noise, mse_area=e,
                               psnr=10.0, ref_spp=4096, ref_error=1e-9, flagged=0, nan_pixels=0,
                               negative_pixels=0, undefined_pixels=0, trace_ms=spp, reconstruct_ms=1.0, threads=2,
                               target="box:0.5", mse_target=e, mse_target_se=se, aliasing_se=se,
                               blur=e - noise, cross=0.0, deterministic=int(det),
                               mse_target_seeds=";".join(f"{x:.9g}" for x in seeds))


def text(h):
    """The section's text: tags out, white space collapsed."""
    return " ".join(html.unescape(re.sub(r"<[^>]+>", " ", re.sub(r"</?(b|small)>", "", h))).split())


def table_rows(h, n):
    """The cells (as text) of the n-th table of the section."""
    t = re.findall(r"<table.*?</table>", h, re.S)[n]
    return [[text(c).strip() for c in re.findall(r"<td>(.*?)</td>", r, re.S)] for r in re.findall(r"<tr>(.*?)</tr>", t, re.S)
            if "<td>" in r]


class SizesSection(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.small = os.path.join(cls.tmp.name, "quick.csv")
        cls.large = os.path.join(cls.tmp.name, "presented.csv")
        pd.DataFrame(rows(48)).to_csv(cls.small, index=False)
        pd.DataFrame(rows(256)).to_csv(cls.large, index=False)
        large, _ = study_csv.load_study(cls.large)
        cls.html = section.section(large, cls.small, 0.10)
        cls.raw = {s: pd.read_csv(p) for s, p in ((48, cls.small), (256, cls.large))}

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def shared(self):
        """The raw rows of both on the shared scenes, spp and methods, side by side (plain pandas)."""
        key = ["scene", "spp", "target", "sampler", "filter", "radius"]
        return self.raw[48].merge(self.raw[256], on=key, suffixes=("_s", "_l"))

    def test_the_answer_is_the_same_at_4_spp_and_not_at_16(self):
        t = table_rows(self.html, 0)
        by_spp = {int(r[1]): r for r in t}
        self.assertEqual(sorted(by_spp), [4, 16])  # 64 spp is at 48 px only
        self.assertIn("sobol", by_spp[4][2])
        self.assertIn("sobol", by_spp[4][3])
        self.assertIn("box r=0.5", by_spp[4][3])
        self.assertEqual(by_spp[4][4], "same samplers, same filter")
        self.assertIn("sobol", by_spp[16][2])
        self.assertIn("jittered", by_spp[16][3])
        self.assertNotIn("sobol", by_spp[16][3])
        self.assertIn("tent r=1", by_spp[16][3])
        self.assertEqual(by_spp[16][4], "other samplers, other filter")
        self.assertIn("the leading samplers are the same at both sizes in 1 of 2 (they share at least one in 1), "
                      "the filter and radius in 1, both in 1", text(self.html))

    def test_rank_agreement_recomputed_with_pandas(self):
        m = self.shared()
        rho = {k: g[["mse_target_s", "mse_target_l"]].corr(method="spearman").iloc[0, 1]
               for k, g in m.groupby(["spp", "scene"])}
        for r in table_rows(self.html, 0):
            v = np.array([rho[(int(r[1]), s)] for s in SCENES])
            self.assertEqual(r[5], f"{np.median(v):.2f} [{v.min():.2f}–{v.max():.2f}]")
        s = pd.Series(rho)
        per_scene = s.groupby(level=1).median()
        self.assertLess(per_scene["c"], 1.0)  # the construction moves scene c's order
        self.assertIn(f"median ρ = {s.median():.2f} (range {s.min():.2f} to {s.max():.2f}); most in "
                      f"{per_scene.idxmax()}", text(self.html))

    def test_scene_table_recomputed_with_pandas(self):
        m = self.shared()
        t = {r[0]: r for r in table_rows(self.html, 1)}
        self.assertEqual(sorted(t), SCENES)  # scene d is at 48 px only
        best_s = m.groupby(["scene", "spp"])["mse_target_s"].transform("min")
        best_l = m.groupby(["scene", "spp"])["mse_target_l"].transform("min")
        grid = m[m["sampler"] == "uniform"].assign(rs=lambda d: d["mse_target_s"] / best_s[d.index],
                                                   rl=lambda d: d["mse_target_l"] / best_l[d.index])
        share = m.assign(ns=m["noise_s"] / m["mse_target_s"], nl=m["noise_l"] / m["mse_target_l"])
        for scene in SCENES:
            g = grid[(grid["scene"] == scene) & (grid["spp"] == 16)]
            self.assertIn(f"{g['rs'].min():.3g}x → {g['rl'].min():.3g}x", t[scene][3])
            for spp in (4, 16):
                q = share[(share["scene"] == scene) & (share["spp"] == spp)]
                self.assertIn(f"{spp}: {100 * q['ns'].median():.0f} % → {100 * q['nl'].median():.0f} %", t[scene][2])
        self.assertIn("1.5x → 2.5x", t["a"][3])  # the construction's grid
        self.assertIn("40 % → 20 %", t["b"][2])  # the median of 0.7, 0.5, 0.3 and 0 (twice each), halved

    def test_what_cannot_be_compared_is_named(self):
        s = text(self.html)
        for what in ("scenes (only at 48 px: d)", "spp (only at 48 px: 64)", "only at 48 px: halton",
                     "only at 256 px: cmj"):
            self.assertIn(what, s)

    def test_movers_recomputed_with_pandas(self):
        m = self.shared()
        for side in ("s", "l"):
            m[f"r{side}"] = m[f"mse_target_{side}"] / m.groupby(["scene", "spp"])[f"mse_target_{side}"].transform("min")
        f = (m["rl"] / m["rs"]).groupby(m["sampler"]).median()
        g = re.search(r"by sampler from (\S+) \((\S+), \d+ rows\) to (\S+) \((\S+), \d+ rows\)", text(self.html))
        hi, lo = g.group(1, 2), g.group(3, 4)
        self.assertEqual(hi, (f"{f.max():.3g}", f.idxmax()))  # the grid: 2.5 / 1.5 in a, more in b and c
        self.assertEqual(lo[0], f"{f.min():.3g}")
        self.assertEqual(f"{f[lo[1]]:.3g}", lo[0])  # a group with the smallest median (several tie at 1)

    def test_the_page_finds_the_quick_study_beside_it(self):
        results = os.path.join(self.tmp.name, "results")
        os.makedirs(os.path.join(results, "study"), exist_ok=True)
        quick = os.path.join(results, "study", "study.csv")
        pd.DataFrame(rows(48)).to_csv(quick, index=False)
        self.assertEqual(section.quick_csv(results, self.large), quick)
        self.assertIsNone(section.quick_csv(results, quick))  # the quick study's own page
        self.assertIsNone(section.quick_csv(self.tmp.name, self.large))  # none beside it

    def test_no_section_when_the_quick_study_is_not_smaller(self):
        small, _ = study_csv.load_study(self.small)
        self.assertEqual(section.section(small, self.large, 0.10), "")  # the page of the 48-px study
        self.assertEqual(section.section(small, self.small, 0.10), "")


if __name__ == "__main__":
    unittest.main()
