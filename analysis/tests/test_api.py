"""The analysis API (aliaslab_analysis/api.py): its rules on cases worked by hand, and its place in the layers
(it may import io, stats and findings only: a reader's API, not the page's)."""
import math
import os
import unittest

import numpy as np
import pandas as pd

from analysis.aliaslab_analysis import api
from analysis.tests.test_layers import PACKAGE, upward_imports


class Rules(unittest.TestCase):
    def test_verdict_at_the_margin(self):
        self.assertEqual(api.MARGIN, 0.10)
        self.assertEqual(api.verdict(0.9, 1.05), api.EQUIVALENT)
        self.assertEqual(api.verdict(1.2, 1.5), api.WORSE)
        self.assertEqual(api.verdict(0.95, 1.2), api.UNDETERMINED)
        self.assertEqual(api.verdict(0.9, 1.05, heavy=True), api.UNDETERMINED)
        self.assertEqual(api.verdict(0.9, 1.15, margin=0.2), api.EQUIVALENT)

    def test_ties_within_two_standard_errors(self):
        self.assertEqual(api.Z, 2.0)
        np.testing.assert_array_equal(api.tied(np.array([0.0, 1.9, 2.1]), np.array([1.0, 1.0, 1.0])),
                                      [True, True, False])

    def test_pareto_front(self):
        # (error, cost): the last point is beaten by the second (lower error at the same cost)
        np.testing.assert_array_equal(api.pareto([1, 2, 3, 2.5], [3, 2, 1, 2]), [True, True, True, False])
        np.testing.assert_array_equal(api.pareto([1, math.nan], [1, 0.5]), [True, False])

    def test_decomposition_residuals(self):
        rows = {c: ["s"] for c in api.CELL + api.METHOD}
        rows.update(noise=[0.1], aliasing=[0.2], blur=[0.3], cross=[-0.05], mse=[0.3])
        whole = pd.DataFrame(dict(rows, mse_target=[0.55]))
        r = api.decomposition_residuals(whole)
        self.assertAlmostEqual(float(r["terms"].iloc[0]), 0.0, places=12)
        self.assertAlmostEqual(float(r["mse"].iloc[0]), 0.0, places=12)
        broken = api.decomposition_residuals(pd.DataFrame(dict(rows, mse_target=[0.6])))
        self.assertAlmostEqual(float(broken["terms"].iloc[0]), 0.05 / 0.6, places=12)

    def test_study_path_takes_either_name(self):
        import tempfile
        with tempfile.TemporaryDirectory() as d:
            self.assertEqual(api.study_path(d), os.path.join(d, "study.csv"))
            open(os.path.join(d, "study.csv.gz"), "wb").close()
            self.assertEqual(api.study_path(d), os.path.join(d, "study.csv.gz"))


class Layer(unittest.TestCase):
    def test_the_api_imports_nothing_above_findings(self):
        source = open(os.path.join(PACKAGE, "api.py"), encoding="utf-8").read()
        self.assertEqual(upward_imports(source, ["findings", "api.py"]), [])
        self.assertEqual(sorted(set(api.__all__) - set(dir(api))), [])


if __name__ == "__main__":
    unittest.main()
