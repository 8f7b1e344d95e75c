"""compare.py flags a planted regression and passes two runs of one study."""
import contextlib
import io
import math
import os
import tempfile
import unittest

from . import synthetic
from ..aliaslab_analysis.findings import compare


def run(*args):
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        try:
            code = compare.main(list(args))
        except SystemExit as e:
            code = e.code
    return code, out.getvalue()


def within_noise(row, sign=[1]):
    """Moves mse and noise by one standard error, alternating in sign (a rerun)."""
    se = compare.standard_errors(row)
    sign[0] = -sign[0]
    row["mse"] += sign[0] * se["mse"]
    row["noise"] = max(0.0, row["noise"] - sign[0] * se["noise"])
    row["trace_ms"] *= 1.3  # a slower machine, within the time ratio


class Compare(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.a = synthetic.write(os.path.join(self.tmp.name, "a.csv"))

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def test_identical_studies_pass(self):
        b = synthetic.write(self.path("b.csv"))
        code, out = run(self.a, b)
        self.assertEqual(code, 0, out)
        self.assertIn("matched 96", out)

    def test_rerun_within_noise_passes(self):
        b = synthetic.write(self.path("b.csv"), modify=within_noise)
        code, out = run(self.a, b)
        self.assertEqual(code, 0, out)
        self.assertIn("no metric changed", out)

    def test_planted_mse_regression_fails(self):
        def plant(r):
            if r["scene"] == "a" and r["sampler"] == "random" and r["spp"] == 4 and r["filter"] == "box":
                r["mse"] *= 4  # noise-dominated row: 4x is ~7 worst-case standard errors
        code, out = run(self.a, synthetic.write(self.path("b.csv"), modify=plant))
        self.assertEqual(code, 1, out)
        self.assertIn("REGRESSION", out)

    def test_deterministic_pattern_change_is_flagged_exactly(self):
        # uniform has noise 0: its mse has no seed-to-seed uncertainty.
        def plant(r):
            if r["sampler"] == "uniform" and r["spp"] == 16:
                r["mse"] *= 1.01
        code, out = run(self.a, synthetic.write(self.path("b.csv"), modify=plant))
        self.assertEqual(code, 1, out)

    def test_improvement_and_timing_change_are_reported_without_failing(self):
        def plant(r):
            if r["sampler"] == "uniform" and r["spp"] == 64:
                r["mse"] /= 10
            if r["sampler"] == "jittered" and r["spp"] == 64:
                r["trace_ms"] *= 3
        code, out = run(self.a, synthetic.write(self.path("b.csv"), modify=plant))
        self.assertEqual(code, 0, out)
        self.assertIn("timings changed", out)
        self.assertIn("-90.0%", out)

    def test_independent_pixels_mode_detects_a_doubling(self):
        def plant(r):
            if r["scene"] == "a" and r["sampler"] == "jittered" and r["spp"] == 16 and r["filter"] == "box":
                r["mse"] *= 2
        b = synthetic.write(self.path("b.csv"), modify=plant)
        self.assertEqual(run(self.a, b)[0], 0)  # the worst-case rule cannot see it with 8 seeds
        self.assertEqual(run(self.a, b, "--independent-pixels")[0], 1)

    def test_standard_error_of_pure_noise(self):
        # aliasing 0: se(mse) = noise sqrt(2 / K).
        se = compare.standard_errors({"seeds": 8, "noise": 0.5, "aliasing": 0.0, "mse_area": 0.5, "mse": 0.5})
        self.assertAlmostEqual(se["mse"], 0.5 * math.sqrt(2 / 8))

    def test_no_configuration_in_common_exits_2(self):
        def other_size(r):
            r["width"] = int(r["width"]) + 1
        b = synthetic.write(self.path("b.csv"), modify=other_size)
        code, out = run(self.a, b)
        self.assertEqual(code, 2, out)
        self.assertNotIn("no significant accuracy regression", out)

    def test_bad_input_exits_2(self):
        with open(self.path("bad.csv"), "w") as f:
            f.write("scene,width\na,1\n")
        self.assertEqual(run(self.a, self.path("bad.csv"))[0], 2)
        self.assertEqual(run(self.a, self.path("missing.csv"))[0], 2)


if __name__ == "__main__":
    unittest.main()
