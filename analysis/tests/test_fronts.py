"""Fronts of error against time (stats/fronts.py): a point is on a front when no other point
beats it in both error and time; on constructed points, on random clouds, and on every front of the committed
studies (per scene and across scenes), no front point is dominated and every point off a front is; and when the
cost is set by spp."""
import os
import unittest

import numpy as np
import pandas as pd

from ..aliaslab_analysis.io import study_csv
from ..aliaslab_analysis.findings import Study
from ..aliaslab_analysis.stats import fronts

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STUDIES = [os.path.join(REPO, "results", p, "study.csv.gz") for p in ("presented", "study")]


def dominated(err, cost, i):
    """Whether another point beats point i in both (<= in both, < in one), by a plain loop."""
    for j in range(len(err)):
        if j != i and err[j] <= err[i] and cost[j] <= cost[i] and (err[j] < err[i] or cost[j] < cost[i]):
            return True
    return False


class Pareto(unittest.TestCase):
    def assert_front(self, err, cost, on):
        for i in range(len(err)):
            if not (np.isfinite(err[i]) and np.isfinite(cost[i])):
                self.assertFalse(on[i])
                continue
            self.assertEqual(bool(on[i]), not dominated(err, cost, i), (i, err[i], cost[i]))

    def test_constructed_points(self):
        err = [1.0, 2.0, 2.0, 1.1, 1.0, np.nan]
        cost = [10.0, 10.5, 5.0, 12.0, 10.0, 1.0]
        on = fronts.pareto(err, cost)
        # a tie with a slightly slower point is not a front point: d (1.1, 12) is beaten by a (1.0, 10)
        self.assertEqual(list(on), [True, False, True, False, True, False])
        self.assert_front(err, cost, on)

    def test_random_clouds(self):
        rng = np.random.default_rng(5)
        for _ in range(20):
            err, cost = rng.lognormal(size=60), np.round(rng.lognormal(size=60), 1)
            self.assert_front(err, cost, fronts.pareto(err, cost))

    def test_cost_set_by_spp(self):
        pts = pd.DataFrame(dict(spp=[4, 4, 16, 16], cost=[10.0, 11.0, 40.0, 80.0], cost_se=[1.0, 1.0, 2.0, 2.0]))
        levels = {x["spp"]: x for x in fronts.cost_by_spp(pts)}
        self.assertTrue(levels[4]["set_by_spp"])     # 1 ms apart, spread 2 sqrt(2) ms
        self.assertFalse(levels[16]["set_by_spp"])   # 40 ms apart, spread 5.7 ms
        self.assertAlmostEqual(levels[16]["spread"], 2 * np.sqrt(8))

    def test_no_front_point_of_the_committed_studies_is_dominated(self):
        checked = 0
        for path in STUDIES:
            if not os.path.isfile(path):
                continue
            df, notes = study_csv.load_study(path)
            s = Study(df, notes)
            for _, g in s.ranked.groupby(["target", "scene"]):
                self.assert_front(g["error"].to_numpy(float), g["cost"].to_numpy(float),
                                  fronts.front_mask(g))
                checked += 1
            p = s.points()
            self.assert_front(p["median_ratio"].to_numpy(float), p["cost"].to_numpy(float), p["front"].to_numpy())
        if not checked:
            self.skipTest("no committed study")


if __name__ == "__main__":
    unittest.main()
