"""x-t slices (xt_slice.py, report/motion_xt.py).

- Registration, through the raytracer (`-frames -motion -register`): a point-sampled grating below Nyquist
  (0.375 cycles/pixel, band-limited) moving 0.25 px per frame gives a slice whose rows equal each other away from
  the margin, also blurred by a Gaussian (blur moves with the content); unregistered, or above Nyquist (0.9), the
  rows differ by far more;
- the slice's pixels are the frames' pixels at that row, and the PNG's slice panel shows them frame by frame;
- the rows chosen from the committed motion study, recomputed with the csv module; the motion page's x-t
  captions carry each shown row's shimmer as the CSV's text has it."""
import csv
import os
import shutil
import tempfile
import unittest

import numpy as np

from ..aliaslab_analysis.viewer import xt_slice
from ..aliaslab_analysis.charts.motion_loop import display
from ..aliaslab_analysis.io.study_csv import load_study
from ..aliaslab_analysis.io.exr import read_exr, read_exrs

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RAYTRACER = os.path.join(REPO, "build", "bin", "raytracer")
STUDY = os.path.join(REPO, "results", "motion", "study", "study.csv")
XT = os.path.join(REPO, "results", "motion", "study", "xt", "xt.csv")
PAGE = os.path.join(REPO, "results", "motion", "index.html")
MANIFEST = {"tracing": "-bounces 0 -weight 0"}
FRAMES, MOTION, SIZE, ROW = 8, (0.25, 0.0), (128, 128), 64


def config(sampler, spp, name, radius):
    return {"sampler": sampler, "spp": spp, "filter": name, "radius": radius}


@unittest.skipUnless(os.access(RAYTRACER, os.X_OK) and shutil.which("oiiotool"), "needs build/bin/raytracer, oiiotool")
class RegisteredSlices(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()

        def frames(scene, cfg, name, register=True):
            m = dict(MANIFEST, scene_path=os.path.join(REPO, "scenes", "motion", scene))
            return xt_slice.render_frames(RAYTRACER, m, SIZE, cfg, 0, FRAMES, MOTION,
                                          os.path.join(cls.tmp.name, name + ".exr"), register)
        point = config("uniform", 1, "box", 0.5)
        cls.paths = {"below": frames("grating128.txt", point, "below"),
                     "gauss": frames("grating128.txt", config("uniform", 1, "gaussian", 1.5), "gauss"),
                     "moving": frames("grating128.txt", point, "moving", register=False),
                     "above": frames("grating_above128.txt", point, "above")}
        cls.slices = {k: xt_slice.slice_rows(read_exrs(p), ROW) for k, p in cls.paths.items()}
        cls.m = xt_slice.margin(FRAMES, *MOTION)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def change(self, key):
        """Mean square and largest difference of each interior row from frame 0's."""
        s = self.slices[key][:, self.m:SIZE[0] - self.m, :3]
        d = s - s[0]
        return float(np.mean(d ** 2)), float(np.abs(d).max())

    def test_margin_is_the_motion_over_the_frames_plus_the_guard(self):
        self.assertEqual(self.m, 2 + 8)  # ceil(7 x 0.25) + 8
        self.assertEqual(xt_slice.margin(2, -1.5, 0.5), 2 + 8)

    def test_below_nyquist_rows_equal_each_other(self):
        for key in ("below", "gauss"):
            ms, worst = self.change(key)
            self.assertLess(ms, 1e-5, key)
            self.assertLess(worst, 1e-2, key)
        self.assertGreater(float(self.slices["below"].std()), 0.3)  # a full-contrast grating, not a flat row

    def test_unregistered_and_above_nyquist_rows_differ(self):
        for key in ("moving", "above"):
            self.assertGreater(self.change(key)[0], 1e-2, key)

    def test_slice_pixels_are_the_frames_pixels(self):
        s = self.slices["above"]
        self.assertEqual(s.shape[:2], (FRAMES, SIZE[0]))
        for t, p in enumerate(self.paths["above"]):
            np.testing.assert_array_equal(s[t], read_exr(p)[ROW])

    def test_png_panel_shows_each_frames_row(self):
        from PIL import Image
        keep = (self.m, SIZE[0] - self.m)
        slices = [self.slices["below"][..., :3], self.slices["above"][..., :3]]
        png = os.path.join(self.tmp.name, "xt.png")
        xt_slice.compose(slices, [("a", "why"), ("b", "why")], keep).save(png)
        img = np.asarray(Image.open(png).convert("RGB"))
        x0, y0 = xt_slice.panel_origin(1, keep[1] - keep[0], FRAMES, 2)
        sx, sy = xt_slice.scales(keep[1] - keep[0], FRAMES)
        self.assertEqual((sx, sy), (2, 6))  # 108 columns x 2 >= 160 px; 8 frames x 6 >= 48 px
        for t in range(FRAMES):
            y = y0 + t * sy + sy // 2
            shown = img[y, x0:x0 + (keep[1] - keep[0]) * sx:sx]
            np.testing.assert_array_equal(shown, display(slices[1][t, keep[0]:keep[1]]))


@unittest.skipUnless(os.path.isfile(STUDY), "needs results/motion/study/study.csv")
class Choice(unittest.TestCase):
    def test_rows_chosen_from_the_csv(self):
        """Per scene: the target, the grid and jittered at the lowest spp with the box r 0.5, and in the grid's
        lowest-spp cell where they differ, the still-best (lowest mse_target) and the steadiest (lowest shimmer)."""
        with open(STUDY, newline="") as f:
            rows = [r for r in csv.DictReader(f) if r["target"] == "box:0.5" and float(r["frames"]) > 1
                    and r["reconstruction"] == "weighted"]
        chosen = xt_slice.choose(load_study(STUDY)[0], "box:0.5")
        for scene in sorted({r["scene"] for r in rows}):
            sr = [r for r in rows if r["scene"] == scene]
            low = min(int(r["spp"]) for r in sr)

            def lowest(cell, col):
                r = min((r for r in cell if np.isfinite(float(r[col]))), key=lambda r: float(r[col]))
                return ("uniform", int(r["spp"]), r["filter"], float(r["radius"]))
            want = [(None, None, "box", 0.5), ("uniform", low, "box", 0.5), ("jittered", low, "box", 0.5)]
            for spp in sorted({int(r["spp"]) for r in sr}):
                cell = [r for r in sr if r["sampler"] == "uniform" and int(r["spp"]) == spp]
                if lowest(cell, "mse_target") != lowest(cell, "shimmer"):
                    break
            want += [k for k in (lowest(cell, "mse_target"), lowest(cell, "shimmer")) if k not in want]
            self.assertEqual([tuple(p[2:]) for p in chosen[scene]], want, scene)


@unittest.skipUnless(os.path.isfile(XT) and os.path.isfile(PAGE), "needs results/motion/study/xt/xt.csv, the page")
class Page(unittest.TestCase):
    def test_captions_carry_the_csvs_shimmer(self):
        with open(STUDY, newline="") as f:
            rows = [r for r in csv.DictReader(f) if r["target"] == "box:0.5" and r["reconstruction"] == "weighted"]
        with open(XT, newline="") as f:
            panels = [p for p in csv.DictReader(f) if p["panel"] != "0"]
        with open(PAGE, encoding="utf-8") as f:
            page = f.read()
        self.assertTrue(panels)
        for p in panels:
            r = next(r for r in rows if (r["scene"], r["sampler"], r["spp"], r["filter"]) ==
                     (p["scene"], p["sampler"], p["spp"], p["filter"]) and float(r["radius"]) == float(p["radius"]))
            se = float(r["shimmer_se"])
            text = f"shimmer {float(r['shimmer']):.2g}" + (f" ± {se:.1g}" if se > 0 else " (no seed noise)")
            self.assertIn(f"<b>{p['label']}</b> ({p['why']}; {text})", page, p)
            self.assertIn(f"src='study/xt/{p['png']}'", page)
