"""The analysis scripts on legitimate degenerate data and on broken data.

Legitimate data (every error 0, aliasing negative everywhere, NaN / Inf values) is drawn, with
empty panels saying so, and exits 0; broken data gets exit 2 and a message naming the file and
the column, never a traceback; compare.py counts a NaN mse as a regression.
"""
import math
import os
import tempfile
import unittest

import pandas as pd

from . import synthetic
from .synthetic import run
from ..aliaslab_analysis.findings import compare
from ..aliaslab_analysis.charts import convergence_experiment, filter_profiles
from ..aliaslab_analysis.charts import cli as charts_cli

METRICS = ["mse", "aliasing", "noise", "mse_area", "mse_target", "blur", "cross", "mse_se", "noise_se",
           "aliasing_se", "mse_target_se"]


def is_png(path):
    with open(path, "rb") as f:
        return f.read(8).startswith(b"\x89PNG")


class DegenerateStudies(unittest.TestCase):
    """Each study has one scene ('a') to keep the suite fast."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def draw(self, modify, new_columns=True):
        csv = synthetic.write(os.path.join(self.tmp.name, "s.csv"), modify=modify, new_columns=new_columns,
                              scenes=["a"])
        out = os.path.join(self.tmp.name, "charts")
        code, _, err = run(charts_cli.main, [csv, "--out", out])
        self.assertEqual(code, 0, err)
        for name in ("speed_accuracy_a", "convergence_a", "heatmap_a", "stability", "decomposition_a", "radius_a"):
            self.assertTrue(is_png(os.path.join(out, name + ".png")), name)
        return out

    def test_every_error_zero_is_drawn_as_empty_panels(self):
        def zero(r):
            for c in METRICS:
                r[c] = 0.0
            r["psnr"] = math.inf
        out = self.draw(zero)
        self.assertTrue(pd.read_csv(os.path.join(out, "pareto.csv")).empty)  # nothing > 0 on log axes

    def test_every_error_zero_in_an_old_csv(self):
        def zero(r):
            for c in ("mse", "aliasing", "noise", "mse_area"):
                r[c] = 0.0
            r["psnr"] = math.inf
        self.draw(zero, new_columns=False)

    def test_aliasing_negative_everywhere(self):
        def negative(r):
            r["aliasing"] = -abs(r["aliasing"]) - 1e-6
        out = self.draw(negative)
        table = pd.read_csv(os.path.join(out, "decomposition.csv.gz"))
        self.assertTrue((table["aliasing"] < 0).all())

    def test_nan_and_inf_values(self):
        # No error is finite: every row's errors are NaN or Inf (alternating), some pixels NaN.
        count = [0]

        def broken(r):
            count[0] += 1
            bad = math.nan if count[0] % 2 else math.inf
            for c in ("mse", "mse_area", "mse_target", "noise"):
                r[c] = bad
            r["psnr"] = bad
            r["nan_pixels"] = 7
        out = self.draw(broken)
        self.assertTrue(pd.read_csv(os.path.join(out, "pareto.csv")).empty)

    def test_some_nan_and_inf_values_are_left_out(self):
        count = [0]

        def broken(r):
            count[0] += 1
            if count[0] % 3 == 0:
                r["mse_target"] = math.nan
                r["mse"] = math.nan
            elif count[0] % 3 == 1:
                r["mse_target"] = math.inf
                r["noise"] = math.inf
        out = self.draw(broken)
        front = pd.read_csv(os.path.join(out, "pareto.csv"))
        self.assertFalse(front.empty)
        self.assertTrue(front["error"].map(math.isfinite).all())

    def test_a_single_spp_level_is_drawn_without_slopes(self):
        csv = synthetic.write(os.path.join(self.tmp.name, "s.csv"), scenes=["a"])
        df = pd.read_csv(csv)
        df[df["spp"] == 4].to_csv(csv, index=False)
        code, _, err = run(charts_cli.main, [csv, "--out", os.path.join(self.tmp.name, "c")])
        self.assertEqual(code, 0, err)


class BrokenFiles(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def assert_refused(self, main, args, *words):
        code, _, err = run(main, args)
        self.assertEqual(code, 2, err)
        for w in words:
            self.assertIn(w, err)
        self.assertNotIn("Traceback", err)

    def test_convergence_chart_names_file_and_column_of_a_garbage_value(self):
        csv = self.path("c.csv")
        rows = [("random", "disk", n, 1.0 / n, 4) for n in (1, 2, 4)]
        rows[1] = ("random", "disk", 2, "garbage", 4)
        pd.DataFrame(rows, columns=convergence_experiment.COLUMNS).to_csv(csv, index=False)
        self.assert_refused(convergence_experiment.main, [csv, "--out", self.path("o")], csv, "rmse", "line 3")

    def test_convergence_chart_on_binary_garbage(self):
        csv = self.path("c.csv")
        with open(csv, "wb") as f:
            f.write(bytes(range(256)) * 8)
        self.assert_refused(convergence_experiment.main, [csv, "--out", self.path("o")], csv)

    def test_convergence_chart_on_text_that_is_not_its_csv(self):
        csv = self.path("c.csv")
        with open(csv, "w") as f:
            f.write("hello world\nthis is not a CSV, at all\n")
        self.assert_refused(convergence_experiment.main, [csv, "--out", self.path("o")], csv, "missing column")

    def test_filter_profiles_names_file_and_column_of_a_garbage_value(self):
        csv = self.path("p.csv")
        rows = [("box", 0.5, "box r=0.5", "profile", x / 10, 1.0) for x in range(-3, 4)]
        rows[2] = ("box", 0.5, "box r=0.5", "profile", -0.1, "1,0e-3x")
        pd.DataFrame(rows, columns=filter_profiles.COLUMNS).to_csv(csv, index=False)
        self.assert_refused(filter_profiles.main, ["--csv", csv, "--out", self.path("o")], csv, "value")

    def test_filter_profiles_on_binary_garbage(self):
        csv = self.path("p.csv")
        with open(csv, "wb") as f:
            f.write(b"\xff\xfe\x00garbage\x00\x81" * 100)
        self.assert_refused(filter_profiles.main, ["--csv", csv, "--out", self.path("o")], csv)

    def test_study_with_a_garbage_optional_column_names_it(self):
        def garbage(r):
            if r["spp"] == 16:
                r["mse_target"] = "oops"
        csv = synthetic.write(self.path("s.csv"), modify=garbage, scenes=["a"])
        self.assert_refused(charts_cli.main, [csv, "--out", self.path("o")], csv, "mse_target")


class CompareNaN(unittest.TestCase):
    def test_every_new_mse_nan_is_a_regression(self):
        with tempfile.TemporaryDirectory() as tmp:
            a = synthetic.write(os.path.join(tmp, "a.csv"))

            def nan(r):
                r["mse"] = math.nan
            b = synthetic.write(os.path.join(tmp, "b.csv"), modify=nan)
            code, out, err = run(compare.main, [a, b])
            self.assertEqual(code, 1, out + err)
            self.assertIn("REGRESSION", out)

    def test_one_infinite_mse_is_a_regression(self):
        with tempfile.TemporaryDirectory() as tmp:
            a = synthetic.write(os.path.join(tmp, "a.csv"))

            def inf(r):
                if r["scene"] == "a" and r["sampler"] == "jittered" and r["spp"] == 4 and r["filter"] == "box":
                    r["mse"] = math.inf
            b = synthetic.write(os.path.join(tmp, "b.csv"), modify=inf)
            self.assertEqual(run(compare.main, [a, b])[0], 1)

    def test_nan_before_and_after_is_still_a_regression_but_nan_to_finite_is_not(self):
        self.assertTrue(compare.is_worse(math.nan, math.nan))
        self.assertTrue(compare.is_worse(1.0, math.nan))
        self.assertFalse(compare.is_worse(math.nan, 1.0))
        self.assertFalse(compare.is_worse(2.0, 1.0))


if __name__ == "__main__":
    unittest.main()
