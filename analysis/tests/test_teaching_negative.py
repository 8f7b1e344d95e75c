"""teaching/negative.py: the negative control's numbers recomputed from results/negative_control/study.csv, and the
grid against jittered from the presented study, by another path (the csv module, plain loops); the record
results/negative_control.md is what the code writes now; the expectations of the control hold (jittered /
random within 3 se of 1, the fixed grid's error 1/4 within 3 se, its noise 0)."""
import csv
import io
import math
import os
import unittest

from ..aliaslab_analysis.io.study_csv import load_study
from ..aliaslab_analysis.teaching import negative
from ..aliaslab_analysis.io import text_file

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CONTROL = os.path.join(REPO, "results", "negative_control", "study.csv")
PRESENTED = os.path.join(REPO, "results", "presented", "study.csv.gz")


def box_rows(path):
    with io.StringIO(text_file.read_text(path), newline="") as f:
        return [r for r in csv.DictReader(f) if r["filter"] == "box" and float(r["radius"]) == 0.5
                and r["reconstruction"] == "weighted" and r["target"] == "box:0.5" and r["prefilter"] == "none"]


class NegativeControl(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.c = negative.control(load_study(CONTROL)[0])

    def test_numbers(self):
        rows = box_rows(CONTROL)
        seen = 0
        for n in (4, 16, 64):
            mine = [r for r in rows if r["scene"] == f"negative_spp{n}" and int(r["spp"]) == n]
            rnd = next(r for r in mine if r["sampler"] == "random")
            b, sb = float(rnd["noise"]), float(rnd["noise_se"])
            self.assertAlmostEqual(self.c[n]["random"], b, places=15)
            for r in mine:
                if r["sampler"] == "random":
                    continue
                a, sa = float(r["noise"]), float(r["noise_se"])
                ratio = a / b
                se = ratio * math.hypot(sa / a if a else 0.0, sb / b)
                got = self.c[n]["samplers"][r["sampler"]]
                self.assertAlmostEqual(got[0], ratio, places=12)
                self.assertAlmostEqual(got[1], se, places=12)
                seen += 1
            u = next(r for r in mine if r["sampler"] == "uniform")
            self.assertAlmostEqual(self.c[n]["uniform_error"], float(u["mse_target"]), places=15)
        self.assertEqual(seen, 3 * 12)

    def test_expectations_hold(self):
        for n, e in self.c.items():
            r, se = e["samplers"]["jittered"]
            self.assertLess(abs(r - 1), 3 * se, n)
            self.assertLess(abs(e["uniform_error"] - 0.25), 3 * e["uniform_error_se"], n)
            self.assertEqual(e["uniform_noise"], 0)
            self.assertLess(abs(e["random"] - e["expected"]), 3 * e["random_se"], n)

    def test_record_is_current(self):
        with open(os.path.join(REPO, "results", "negative_control.md"), encoding="utf-8") as f:
            self.assertEqual(f.read(), negative.markdown(self.c, "results/negative_control/study.csv"))

    def test_grid_against_jittered(self):
        df, _ = load_study(PRESENTED)
        rows = df[(df["target"] == "box:0.5") & (df["reconstruction"] == "weighted") & (df["prefilter"] == "none")]
        spp, grid = negative.grid_vs_jittered(rows)
        plain = box_rows(PRESENTED)
        low = min(int(r["spp"]) for r in plain)
        self.assertEqual(spp, low)
        for scene in {r["scene"] for r in plain}:
            at = {r["sampler"]: float(r["mse_target"]) for r in plain if r["scene"] == scene and int(r["spp"]) == low}
            for s in ("uniform", "uniform-shifted"):
                self.assertAlmostEqual(grid[scene][s], at[s] / at["jittered"], places=12)
        text = negative.html(self.c, spp, grid)
        shifted = [v["uniform-shifted"] for v in grid.values()]
        self.assertIn(f"{min(shifted):.2f} to {max(shifted):.2f} times jittered's", text)
        self.assertIn("jittered is random and a grid is worst", text)


if __name__ == "__main__":
    unittest.main()
