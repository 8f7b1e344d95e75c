"""The motion section (report/motion.py) and the loop of frames (motion_loop.py).

- facts() on a hand-made study whose answers are known by design (a NaN is left out, never a traceback);
- on the committed motion study (results/motion/study/study.csv), every number of the section's prose is
  recomputed here from the CSV's text with the csv module (another path than pandas and facts()), and found in
  the page results/motion/index.html;
- the loop's frame errors are the library's (imgdiff), read from a CSV; its frame-0 error of point sampling with the box r 0.5 against the pixel-area reference equals the
  study's mse_target of that configuration (another renderer run, another reference: within 5 %);
- a still study has no motion section."""
import csv
import os
import re
import unittest

import numpy as np
import pandas as pd

from ..aliaslab_analysis.io import errors
from ..aliaslab_analysis.charts import motion_loop
from ..aliaslab_analysis.report import motion

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STUDY = os.path.join(REPO, "results", "motion", "study", "study.csv")
PAGE = os.path.join(REPO, "results", "motion", "index.html")


def row(scene, sampler, spp, name, radius, mse, shimmer, flicker, blur, shimmer_se=0.0):
    return dict(scene=scene, sampler=sampler, spp=spp, filter_name=name, radius=radius, reconstruction="weighted",
                mse_target=mse, shimmer=shimmer, shimmer_se=shimmer_se, flicker_same=flicker, blur=blur)


class Facts(unittest.TestCase):
    def test_known_design(self):
        rows = pd.DataFrame([
            # cell 1: the trade-off holds; still best gaussian 1, steadiest box (shimmer) and gaussian 2 (flicker)
            row("a", "jittered", 4, "box", 0.5, 3.0, 0.1, 9.0, 0.0),
            row("a", "jittered", 4, "gaussian", 0.5, 5.0, 0.2, 9.5, 0.3),  # narrower than a pixel: left out
            row("a", "jittered", 4, "gaussian", 1.0, 1.0, 0.5, 5.0, 0.1),
            row("a", "jittered", 4, "gaussian", 2.0, 2.0, 0.3, 4.0, 0.5),
            # cell 2: shimmer rises with the radius (no trade-off); the still best (box) also flickers least
            row("a", "uniform", 1, "box", 0.5, 1.0, 0.1, 0.1, 0.0),
            row("a", "uniform", 1, "gaussian", 1.0, 2.0, 0.15, 0.2, 0.1),
            row("a", "uniform", 1, "gaussian", 2.0, 3.0, 0.2, 0.3, 0.5),
            # scene b: one row zero within error, one deterministic zero, one not zero, one NaN (left out)
            row("b", "uniform", 1, "box", 0.5, 1.0, 1e-3, 0.1, 0.0, shimmer_se=1e-3),
            row("b", "uniform", 1, "tent", 1.0, 2.0, 2e-6, 0.2, 0.1),
            row("b", "uniform", 1, "gaussian", 1.0, 3.0, 0.2, 0.3, 0.5, shimmer_se=0.01),
            row("b", "uniform", 1, "lanczos", 1.0, 3.0, np.nan, 0.3, 0.5),
        ])
        f = motion.facts(rows)
        self.assertEqual(f, dict(cells=3, gaussian_cells=2, tradeoff=1, differ_shimmer=2, differ_flicker=1,
                                 steady=[("a", 0, 7), ("b", 2, 4)]))

    def test_no_finite_value_is_no_winner(self):
        rows = pd.DataFrame([row("a", "uniform", 1, "box", 0.5, 1.0, np.nan, 0.1, 0.0),
                             row("a", "uniform", 1, "tent", 1.0, 2.0, np.nan, 0.2, 0.1)])
        self.assertIsNone(motion.best(rows, "shimmer"))
        self.assertEqual(motion.facts(rows)["differ_shimmer"], 0)

    def test_still_study_has_no_section(self):
        self.assertIsNone(motion.motion_rows(pd.DataFrame({"target": ["box:0.5"], "error": [1.0]}), "box:0.5"))
        self.assertIsNone(motion.motion_rows(pd.DataFrame({"target": ["box:0.5"], "frames": [1]}), "box:0.5"))

    def test_frame_errors_are_read_from_the_librarys_csv(self):
        import tempfile
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "errors.csv")
            with open(path, "w") as f:
                f.write("name,frame,mse\nbox,1,0.5\nbox,0,0.25\nother,0,9\n")
            self.assertEqual(motion_loop.read_errors(path, ["box"], 2), {"box": [0.25, 0.5]})
            with self.assertRaises(errors.InputError):
                motion_loop.read_errors(path, ["box"], 3)  # frame 2 missing
            with open(path, "a") as f:
                f.write("box,1,x\n")
            with self.assertRaisesRegex(errors.InputError, "line 5"):
                motion_loop.read_errors(path, ["box"], 2)


@unittest.skipUnless(os.path.isfile(STUDY) and os.path.isfile(PAGE), "the committed motion study is not there")
class CommittedStudy(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(STUDY, newline="") as f:
            cls.rows = [r for r in csv.DictReader(f) if r["target"] == "box:0.5"]
        with open(PAGE, encoding="utf-8") as f:
            cls.page = f.read()

    def recomputed(self):
        cells, scenes = {}, {}
        for r in self.rows:
            cells.setdefault((r["scene"], r["sampler"], r["spp"]), []).append(r)
            scenes.setdefault(r["scene"], []).append(r)
        n = dict(cells=0, gaussian_cells=0, tradeoff=0, differ_shimmer=0, differ_flicker=0)

        def lowest(rs, key):
            r = min((r for r in rs if np.isfinite(float(r[key]))), key=lambda r: float(r[key]))
            return (r["filter"], float(r["radius"]), r["reconstruction"])

        for rs in cells.values():
            n["cells"] += 1
            n["differ_shimmer"] += lowest(rs, "mse_target") != lowest(rs, "shimmer")
            n["differ_flicker"] += lowest(rs, "mse_target") != lowest(rs, "flicker_same")
            g = sorted((r for r in rs if r["filter"] == "gaussian" and r["reconstruction"] == "weighted" and
                        float(r["radius"]) >= 1),
                       key=lambda r: float(r["radius"]))
            if len(g) >= 2:
                n["gaussian_cells"] += 1
                n["tradeoff"] += all(float(b["shimmer"]) < float(a["shimmer"]) and
                                     float(b["blur"]) > float(a["blur"]) for a, b in zip(g, g[1:]))

        def zero(r):
            s, se = float(r["shimmer"]), float(r["shimmer_se"])
            return abs(s) <= (2 * se if se == se and se > 0 else 0) + 1e-5

        n["steady"] = "; ".join(f"{sc} {sum(zero(r) for r in rs)} of {len(rs)}" for sc, rs in sorted(scenes.items()))
        return n

    def test_prose_numbers(self):
        n = self.recomputed()
        text = re.sub(r"<[^>]+>", "", self.page)
        self.assertIn(f"Rows whose shimmer is zero within two standard errors, per scene: {n['steady']}.", text)
        self.assertIn(f"In {n['tradeoff']} of {n['gaussian_cells']} (scene, sampler, spp) cells with two or more "
                      "Gaussian radii of 1 pixel or more", text)
        self.assertIn(f"not the steadiest in {n['differ_shimmer']} of {n['cells']} cells by shimmer and in "
                      f"{n['differ_flicker']} by flicker", text)
        self.assertIn("<h2 id='motion'>", self.page)

    def test_loop_frame0_is_the_studys_still_error(self):
        with open(os.path.join(os.path.dirname(STUDY), "loop.csv"), newline="") as f:
            loop = [r for r in csv.DictReader(f) if r["method"] == "uniform 1 spp box r 0.5" and r["frame"] == "0"]
        study = [r for r in self.rows if r["scene"] == "grating128" and r["sampler"] == "uniform" and
                 r["spp"] == "1" and r["filter"] == "box" and float(r["radius"]) == 0.5]
        self.assertEqual((len(loop), len(study)), (1, 1))
        self.assertAlmostEqual(float(loop[0]["mse"]) / float(study[0]["mse_target"]), 1.0, delta=0.05)


if __name__ == "__main__":
    unittest.main()
