"""The log-log slope fitter and the Pareto front against known answers."""
import math
import unittest

import numpy as np

from ..aliaslab_analysis.stats import fits


class SlopeFit(unittest.TestCase):
    def test_exact_power_law_gives_its_exponent(self):
        n = 2.0 ** np.arange(13)
        slope, intercept, se, points = fits.fit_loglog_slope(n, 0.3 * n ** -0.75)
        self.assertAlmostEqual(slope, -0.75, places=12)
        self.assertAlmostEqual(math.exp(intercept), 0.3, places=12)
        self.assertAlmostEqual(se, 0.0, places=12)
        self.assertEqual(points, 13)

    def test_recovers_known_slopes_from_noisy_data(self):
        # 10 % multiplicative noise over 2^0 .. 2^12: slope standard error ~ 0.008.
        rng = np.random.default_rng(12345)
        n = 2.0 ** np.arange(13)
        for true in (-0.5, -0.75, -1.0, -1.5):
            y = 2.0 * n ** true * np.exp(0.1 * rng.standard_normal(len(n)))
            slope, _, se, _ = fits.fit_loglog_slope(n, y)
            self.assertLess(abs(slope - true), 0.04, true)
            self.assertLess(abs(slope - true), 5 * se + 1e-3, true)

    def test_uses_only_the_stated_range_and_powers_of_two(self):
        n = np.array([1, 2, 4, 16, 32, 48, 64, 100, 256, 1024, 4096], dtype=float)
        inside = np.isin(n, [16, 32, 64, 256, 1024])
        y = np.where(inside, 1.0 / n, 5.0 * n ** -0.2)
        self.assertAlmostEqual(fits.fit_loglog_slope(n, y, 16, 1024, True)[0], -1.0, places=12)
        with self.assertRaises(ValueError):
            fits.fit_loglog_slope([4, 4], [1, 2])
        with self.assertRaises(ValueError):
            fits.fit_loglog_slope([4, 8], [0, 1])  # zeros cannot be fitted on log axes


class ParetoFront(unittest.TestCase):
    def test_front_is_the_set_of_non_dominated_points(self):
        rng = np.random.default_rng(7)
        x, y = rng.random(200), rng.random(200)
        front = set(fits.pareto_front(x, y))
        for i in range(200):
            dominated = any(x[j] <= x[i] and y[j] <= y[i] and (x[j], y[j]) != (x[i], y[i]) for j in range(200))
            self.assertEqual(i in front, not dominated, i)


if __name__ == "__main__":
    unittest.main()
