"""Tie groups (stats/ties.py: the motion section's top groups) on constructed rows with known means and
standard errors: what is tied, what is not, paired against unpaired comparisons, undetermined rows; and the
seeded bootstrap over scenes (stats/bootstrap.py)."""
import unittest

import numpy as np
import pandas as pd

from ..aliaslab_analysis.io import study_rows
from ..aliaslab_analysis.stats import bootstrap, ties


def row(sampler, error, se, filt="box", radius=0.5, seeds=None, scene="s", spp=16, flagged=0, cost=10.0,
        cost_se=0.0, deterministic=False):
    return dict(scene=scene, sampler=sampler, spp=spp, prefilter="none", target="box:0.5", filter_name=filt,
                radius=radius, filter_params="", reconstruction="weighted", error=error, error_se=se,
                flagged=flagged, seed_values=None if seeds is None else np.asarray(seeds, dtype=float),
                cost=cost, cost_se=cost_se, deterministic=deterministic)


def frame(*rows):
    return pd.DataFrame(list(rows))


def correlated_seeds(mean, shared, own, scale):
    """Per-seed values: mean + scale (shared + own), recentred to the exact mean."""
    v = scale * (np.asarray(shared) + np.asarray(own))
    return mean + v - v.mean()


class TieGroups(unittest.TestCase):
    def test_one_standard_error_apart_is_a_tie_five_is_not(self):
        # independent samplers, se 0.1 each: the difference's se is 0.1 sqrt(2) = 0.141
        g = ties.top_group(frame(row("a", 1.0, 0.1), row("b", 1.141, 0.1), row("c", 1.707, 0.1)))
        self.assertEqual(list(g["top"]), [True, True, False])
        self.assertAlmostEqual(g["gap_z"].iloc[1], 1.0, places=2)
        self.assertAlmostEqual(g["gap_z"].iloc[2], 5.0, places=2)
        self.assertFalse(g["paired"].any())

    def test_the_rule_is_two_standard_errors_of_the_difference(self):
        se = 0.1 * np.sqrt(2)
        g = ties.top_group(frame(row("a", 1.0, 0.1), row("b", 1.0 + 1.99 * se, 0.1), row("c", 1.0 + 2.01 * se, 0.1)))
        self.assertEqual(list(g["top"]), [True, True, False])

    def test_paired_and_unpaired_give_different_answers_when_seeds_are_correlated(self):
        rng = np.random.default_rng(1)
        shared, k = rng.standard_normal(8), 8
        a = correlated_seeds(1.0, shared, 0.05 * rng.standard_normal(k), 0.5)
        b = correlated_seeds(1.2, shared, 0.05 * rng.standard_normal(k), 0.5)
        se_a, se_b = a.std(ddof=1) / np.sqrt(k), b.std(ddof=1) / np.sqrt(k)
        self.assertGreater(se_a, 0.1)  # each alone is uncertain: 0.2 apart is within 2 se unpaired
        # same sampler (one sample set), two filters: paired, the shared part cancels: not tied
        same = ties.top_group(frame(row("x", 1.0, se_a, "box", seeds=a), row("x", 1.2, se_b, "tent", seeds=b)))
        self.assertTrue(same["paired"].all())
        self.assertEqual(list(same["top"]), [True, False])
        self.assertAlmostEqual(same["gap_se"].iloc[1], (b - a).std(ddof=1) / np.sqrt(k))
        # the same numbers from two samplers (independent sample sets): unpaired, tied
        other = ties.top_group(frame(row("x", 1.0, se_a, seeds=a), row("y", 1.2, se_b, seeds=b)))
        self.assertFalse(other["paired"].any())
        self.assertEqual(list(other["top"]), [True, True])
        self.assertAlmostEqual(other["gap_se"].iloc[1], np.hypot(se_a, se_b))

    def test_without_seed_values_a_sample_set_is_compared_unpaired(self):
        se, paired = ties.diff_se_matrix(frame(row("x", 1.0, 0.3), row("x", 1.2, 0.4, "tent")))
        self.assertFalse(paired.any())
        self.assertAlmostEqual(se[0, 1], 0.5)

    def test_a_huge_error_with_a_huger_spread_is_undetermined_not_tied(self):
        g = ties.top_group(frame(row("a", 1.0, 0.05), row("b", 2000.0, 1500.0, "mitchell")))
        self.assertEqual(list(g["top"]), [True, False])
        self.assertEqual(list(g["undetermined"]), [False, True])

    def test_an_error_too_small_to_tell_from_zero_is_in_the_top_group(self):
        # flagged (error < 2 se) because it is nearly exact: its upper bound is below the best measured one
        g = ties.top_group(frame(row("a", 1.0, 0.05), row("b", 0.01, 0.01, flagged=1), row("c", 3.0, 0.05)))
        self.assertTrue(g["best"].iloc[0])  # the best is the lowest *measured* error
        self.assertEqual(list(g["top"]), [True, True, False])

    def test_unknown_standard_error_ties_only_equal_errors(self):
        self.assertEqual(list(ties.tied([0.0, 0.1], [np.nan, np.nan])), [True, False])

    def test_parse_seeds(self):
        self.assertEqual(list(study_rows.parse_seeds("1;2.5;3")), [1.0, 2.5, 3.0])
        for bad in ("", None, float("nan"), "1", "a;b"):
            self.assertIsNone(study_rows.parse_seeds(bad))


class AcrossScenes(unittest.TestCase):
    def test_the_bootstrap_is_seeded_and_brackets_the_median(self):
        v = np.array([1.0, 1.1, 1.3, 1.05, 2.0, 1.2, 1.01, 1.4])
        lo, hi = bootstrap.interval(v)
        self.assertEqual((lo, hi), bootstrap.interval(v))
        self.assertLessEqual(lo, np.median(v))
        self.assertGreaterEqual(hi, np.median(v))
        self.assertEqual(bootstrap.interval([3.0]), (3.0, 3.0))


if __name__ == "__main__":
    unittest.main()
