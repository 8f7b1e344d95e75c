"""Effect sizes and the margin of equivalence (stats/effect.py, tails.py, student.py) on constructed rows with
known answers: rows at 0.95x, 1.05x and 1.2x of the comparator with tight intervals are equivalent,
equivalent and worse at a 10 % margin; a significant 3 % gap is equivalent; a heavy-tailed row is never
equivalent; the interval's coverage is checked by simulation (95 % with Student's t, not with +-2 se)."""
import math
import unittest

import numpy as np
import pandas as pd

from ..aliaslab_analysis.stats import effect, equivalence, student, tails

K = 8


def row(name, seeds, sampler=None, se_ref=0.0, det=False, flagged=0):
    x = np.asarray(seeds, dtype=float)
    se = math.sqrt(float(np.var(x, ddof=1)) / len(x) + se_ref ** 2)
    return dict(scene="s", sampler=sampler or name, spp=16, prefilter="none", target="box:0.5", filter_name=name,
                radius=1.0, filter_params=name, reconstruction="weighted", error=float(x.mean()), error_se=se,
                seed_values=x, deterministic=det, seeds=len(x), flagged=flagged)


def tight(mean, rng, cv=0.005):
    v = 1 + cv * rng.standard_normal(K)
    return mean * v / v.mean()  # exactly `mean`


class Verdicts(unittest.TestCase):
    def setUp(self):
        self.rng = np.random.default_rng(1)

    def test_the_three_rules_at_a_ten_percent_margin(self):
        self.assertEqual(effect.verdict(0.94, 0.96, 0.10), effect.EQUIVALENT)
        self.assertEqual(effect.verdict(1.04, 1.06, 0.10), effect.EQUIVALENT)
        self.assertEqual(effect.verdict(1.19, 1.21, 0.10), effect.WORSE)
        self.assertEqual(effect.verdict(1.05, 1.15, 0.10), effect.UNDETERMINED)
        self.assertEqual(effect.verdict(0.9, 1.05, 0.10, heavy=True), effect.UNDETERMINED)
        self.assertEqual(effect.verdict(1.04, 1.06, 0.02), effect.WORSE)  # the margin is a parameter

    def test_across_scenes_equivalent_needs_half_the_scenes_and_no_heavy_tail(self):
        self.assertEqual(equivalence.verdict(1.0, 1.05, 0.10, 0, 1, 2), effect.EQUIVALENT)
        self.assertEqual(equivalence.verdict(1.0, 1.05, 0.10, 0, 0, 2), effect.UNDETERMINED)
        self.assertEqual(equivalence.verdict(1.0, 1.05, 0.10, 1, 2, 2), effect.UNDETERMINED)
        self.assertEqual(equivalence.verdict(1.2, 1.5, 0.10, 0, 0, 2), effect.WORSE)

    def test_rows_at_095_105_and_12_against_a_comparator(self):
        cell = pd.DataFrame([row("ref", tight(1.0, self.rng)), row("a", tight(0.95, self.rng)),
                             row("b", tight(1.05, self.rng)), row("c", tight(1.2, self.rng))])
        out = effect.versus(cell, 0, 0.10)
        self.assertEqual(list(out["verdict"]), ["equivalent", "equivalent", "equivalent", "worse"])
        for r, want in zip(out.itertuples(), (1.0, 0.95, 1.05, 1.2)):
            self.assertAlmostEqual(r.ratio, want, places=12)
            self.assertLess(r.ci_high - r.ci_low, 0.03)  # tight
        self.assertEqual(list(out["interval"])[1:], ["log"] * 3)

    def test_in_a_cell_the_best_is_the_comparator_and_a_significant_3_percent_gap_is_equivalent(self):
        base = 1 + 0.02 * self.rng.standard_normal(K)
        # two filters of one sampler: paired, the 3 % gap many standard errors of the paired difference
        best = row("box", 1.0 * base, sampler="pmj02")
        near = row("tent", 1.03 * base * (1 + 0.001 * self.rng.standard_normal(K)), sampler="pmj02")
        cell = pd.DataFrame([near, best, row("far", tight(1.2, self.rng))])
        out = effect.cell_effects(cell, 0.10)
        self.assertEqual(list(out["best"]), [False, True, False])
        r = out.iloc[0]
        self.assertGreater(r["ci_low"], 1.0)             # significant
        self.assertEqual(r["verdict"], effect.EQUIVALENT)  # but inside the margin
        self.assertEqual(out.iloc[2]["verdict"], effect.WORSE)

    def test_a_heavy_tailed_row_is_never_equivalent_and_never_the_best(self):
        wild = np.full(K, 0.5)
        wild[3] = 4.5  # mean 1.0, one seed carries 56 % of the summed error
        self.assertTrue(tails.heavy(wild))
        cell = pd.DataFrame([row("wild", wild), row("ok", tight(1.02, self.rng))])
        out = effect.cell_effects(cell, 0.10)
        self.assertEqual(list(out["best"]), [False, True])
        self.assertTrue(out.iloc[0]["heavy_tailed"])
        self.assertEqual(out.iloc[0]["interval"], "bootstrap")
        self.assertNotEqual(out.iloc[0]["verdict"], effect.EQUIVALENT)
        for margin in (0.1, 1.0, 5.0):  # whatever the margin
            self.assertNotEqual(effect.cell_effects(cell, margin).iloc[0]["verdict"], effect.EQUIVALENT)

    def test_the_heavy_tail_rule(self):
        self.assertFalse(tails.heavy(tight(1.0, self.rng, cv=0.3)))
        self.assertFalse(tails.heavy([1.0] * 7 + [1.9]))   # share 0.213 < 2/8
        self.assertTrue(tails.heavy([1.0] * 7 + [2.4]))    # share 0.255 > 2/8
        self.assertFalse(tails.heavy([1.0, 9.0, 1.0]))     # too few seeds to say
        self.assertFalse(tails.heavy(None))
        # the example: seven seeds at 0.0042-0.0044, one at 0.036
        self.assertTrue(tails.heavy([0.0042, 0.0043, 0.0044, 0.0043, 0.0042, 0.0044, 0.0043, 0.036]))

    def test_a_fixed_grid_row_has_the_references_part_only(self):
        grid = row("grid", np.full(K, 1.3), se_ref=0.01, det=True)
        out = effect.cell_effects(pd.DataFrame([row("a", tight(1.0, self.rng)), grid]), 0.10)
        g = out.iloc[1]
        self.assertEqual(g["verdict"], effect.WORSE)
        self.assertLess(g["ci_high"] - g["ci_low"], 0.1)


class Coverage(unittest.TestCase):
    """The 95 % interval covers the true ratio about 95 % of the time, for paired and independent rows with K = 8
    gamma-distributed per-seed errors; +-2 se (normal) covers visibly less for paired rows (7 degrees of
    freedom), which is why Student's t is used."""

    def simulate(self, paired, n=3000, cv=0.05, ratio=1.07):
        rng = np.random.default_rng(7 if paired else 8)
        shape = 1 / cv ** 2
        hit_t = hit_z = 0
        for _ in range(n):
            common = rng.gamma(shape, 1 / shape, K)
            if paired:  # shared seed-to-seed part and a smaller own part
                a = ratio * common * rng.gamma(4 * shape, 1 / (4 * shape), K)
                b = common * rng.gamma(4 * shape, 1 / (4 * shape), K)
                true = ratio  # both own parts have mean 1
            else:
                a, b = ratio * rng.gamma(shape, 1 / shape, K), common
                true = ratio
            ra = effect.Row(a.mean(), a.std(ddof=1) / math.sqrt(K), a, False, K)
            rb = effect.Row(b.mean(), b.std(ddof=1) / math.sqrt(K), b, False, K)
            lo, hi = effect.log_interval(ra, rb, paired)
            hit_t += lo <= true <= hi
            h = math.log(hi / lo) / 2 / student.quantile(0.975, 7 if paired else 14) * 2  # +-2 se
            c = math.log(ra.e / rb.e)
            hit_z += math.exp(c - h) <= true <= math.exp(c + h)
        return hit_t / n, hit_z / n

    def test_paired(self):
        t, z = self.simulate(True)
        self.assertGreater(t, 0.935)
        self.assertLess(t, 0.965)
        self.assertLess(z, 0.93)

    def test_independent(self):
        t, _ = self.simulate(False)
        self.assertGreater(t, 0.935)
        self.assertLess(t, 0.965)


class Student(unittest.TestCase):
    def test_quantiles_against_the_tables(self):
        for df, want in ((1, 12.7062047), (2, 4.3026527), (7, 2.3646243), (14, 2.1447867), (30, 2.0422725),
                         (math.inf, 1.9599640)):
            self.assertAlmostEqual(student.quantile(0.975, df), want, places=6)
        self.assertAlmostEqual(student.quantile(0.025, 7), -2.3646243, places=6)
        self.assertAlmostEqual(student.cdf(0.0, 5), 0.5, places=12)

    def test_welch_satterthwaite(self):
        self.assertAlmostEqual(student.welch_df([1.0, 1.0], [7, 7]), 14.0)
        self.assertEqual(student.welch_df([1.0, 0.5], [7, math.inf]), 1.5 ** 2 / (1 / 7))
        self.assertEqual(student.welch_df([1.0], [math.inf]), math.inf)


if __name__ == "__main__":
    unittest.main()
