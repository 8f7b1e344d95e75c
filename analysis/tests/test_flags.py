"""stats/flags.py: a flagged row is reference-limited when its raw error is within REF_LIMIT times the target
reference's variance, unstable otherwise; unflagged rows get no label, whatever their numbers."""
import unittest

import pandas as pd

from ..aliaslab_analysis.stats import flags


class Kinds(unittest.TestCase):
    def test_the_two_reasons_apart(self):
        df = pd.DataFrame(dict(
            flagged=[1, 1, 1, 0, 1],
            # corrected error, its raw value is this + target_ref_error
            mse_target=[2e-6, 8e-6, 15.6, 1e-9, 0.0],
            target_ref_error=[1e-6, 1e-6, 1e-6, 1e-6, 0.0]))
        got = list(flags.kinds(df))
        # raw 3e-6 <= 1e-5: limited; raw 9e-6 <= 1e-5: limited; raw 15.6: unstable; unflagged: "";
        # a flagged row with no reference variance and zero error: raw 0 <= 0, limited
        self.assertEqual(got, [flags.REFERENCE_LIMITED, flags.REFERENCE_LIMITED, flags.UNSTABLE, "",
                               flags.REFERENCE_LIMITED])

    def test_older_csv_uses_the_own_reference(self):
        df = pd.DataFrame(dict(flagged=[1, 1], mse_area=[1e-7, 1.0], ref_error=[1e-6, 1e-6]))
        self.assertEqual(list(flags.kinds(df)), [flags.REFERENCE_LIMITED, flags.UNSTABLE])


if __name__ == "__main__":
    unittest.main()
