"""filter_profile() against the filterprofile program's profile rows (the floats exactly: %.9g), and
filter_eval() against the profile by the filter's definition: g(x) g(y) on the square for separable filters,
g(|d|) on the disc for radial ones, zero outside the support."""
import csv
import io
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import support  # noqa: E402
import aliaslab  # noqa: E402

STEPS = 400  # FilterResponseGrid::profileSteps (lib/measure/filter_response.h)
RADIAL = {"tent", "gaussian"}  # the filters on a disc (docs: lib/filter/filter.h)


class Profile(unittest.TestCase):
    def test_profile_equals_filterprofile(self):
        rows = [r for r in csv.DictReader(io.StringIO(support.run("filterprofile"))) if r["kind"] == "profile"]
        names = sorted({r["filter"] for r in rows})
        self.assertEqual(names, sorted(aliaslab.filters()))
        for name in names:
            got_rows = [r for r in rows if r["filter"] == name]
            r = float(got_rows[0]["radius"])
            self.assertAlmostEqual(r, aliaslab.default_radius(name), places=5)
            self.assertEqual(got_rows[0]["describe"], aliaslab.filter_describe(name))
            rr = np.float64(np.float32(aliaslab.default_radius(name)))  # Filter::radius() is a float
            x = -rr - 0.25 + (2 * rr + 0.5) * np.arange(STEPS + 1) / STEPS  # as the program steps it, in double
            got = aliaslab.filter_profile(name, None, x)
            want = np.array([float(v["value"]) for v in got_rows], dtype=np.float32)
            self.assertEqual(got.dtype, np.float32)
            self.assertTrue(np.array_equal(got, want), name)


class Eval(unittest.TestCase):
    def test_eval_is_the_profile_on_the_square_or_the_disc(self):
        x, y = np.meshgrid(np.linspace(-3.3, 3.3, 67), np.linspace(-3.1, 3.1, 63))
        for name in aliaslab.filters():
            radius = 1.25
            f = aliaslab.filter_eval(name, radius, x, y)
            self.assertEqual(f.shape, x.shape)
            if name in RADIAL:
                d = np.hypot(x, y).astype(np.float32)
                want = np.where(d <= radius, aliaslab.filter_profile(name, radius, d), 0)
            else:
                want = aliaslab.filter_profile(name, radius, x) * aliaslab.filter_profile(name, radius, y)
                want = np.where((np.abs(x) <= radius) & (np.abs(y) <= radius), want, 0)
            np.testing.assert_allclose(f, want, rtol=1e-5, atol=1e-7, err_msg=name)
            self.assertTrue(np.all(f[(np.abs(x) > radius) | (np.abs(y) > radius)] == 0), name)

    def test_eval_broadcasts(self):
        f = aliaslab.filter_eval("mitchell", 2.0, np.linspace(-2, 2, 5)[:, None], np.zeros(3))
        self.assertEqual(f.shape, (5, 3))
        self.assertEqual(float(aliaslab.filter_eval("box", 0.5, 0.0, 0.0)), 1.0)


if __name__ == "__main__":
    unittest.main()
