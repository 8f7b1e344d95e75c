"""The teaching strand's rules (teaching/facts.py) on a small synthetic table: broken filters kept apart and not
called worst, the extremes, the grid's scene."""
import unittest

import pandas as pd

from ..aliaslab_analysis.teaching import facts


class Teaching(unittest.TestCase):
    def rows(self):
        base = dict(scene="s", spp=4, target="box:0.5", reconstruction="weighted", prefilter="none",
                    deterministic=0, undefined_pixels=0, mse_target_se=0.001)
        rows = []
        for sampler, f, r, mse, noise, und in (("jittered", "box", 0.5, 0.02, 0.01, 0),
                                                ("uniform", "box", 0.5, 0.03, 0.0, 0),
                                                ("jittered", "lanczos", 0.5, 5.0, 1.5, 0),
                                                ("jittered", "tent", 0.5, 0.05, 0.02, 7),
                                                ("jittered", "box", 2.0, 0.04, 0.001, 0)):
            rows.append(dict(base, sampler=sampler, filter_name=f, radius=r, mse_target=mse, noise=noise,
                             undefined_pixels=und, deterministic=int(sampler == "uniform")))
        return pd.DataFrame(rows)

    def test_broken_filters_are_apart_and_not_worst(self):
        rows = self.rows()
        bad = facts.degenerate(rows)
        self.assertIn(("s", "jittered", 4, "lanczos", 0.5), bad)  # noise 150 times the box's
        self.assertIn(("s", "jittered", 4, "tent", 0.5), bad)  # undefined pixels
        self.assertEqual(len(bad), 2)
        ext, spp = facts.extremes(rows, bad)
        best, worst, degen = ext["s"]
        self.assertEqual((best["filter_name"], worst["filter_name"], worst["radius"]), ("box", "box", 2.0))
        self.assertEqual(len(degen), 2)

    def test_grid_scene(self):
        g = facts.grid_scene(self.rows())
        self.assertEqual((g["scene"], g["wins"], g["scenes"]), ("s", 0, 1))
        self.assertAlmostEqual(g["ratio"], 1.5)


if __name__ == "__main__":
    unittest.main()
