"""results/adaptive.md's section "Keeping the base's stratification" recomputed from its committed CSVs by another
path (pandas, numpy.interp in log-log) than adaptive_record.py (csv module, explicit bracketing), and the
generated block in results/adaptive.md equal to what the generator writes now."""
import math
import os
import unittest

import numpy as np
import pandas as pd

from ..aliaslab_analysis.report import adaptive_record as ar

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DIR = os.path.join(REPO, "results", "adaptive", "progressive")
BEFORE = [os.path.join(DIR, f"before{i}.csv") for i in (1, 2)]
AFTER = [os.path.join(DIR, f"after{i}.csv") for i in (1, 2)]


def frame(paths):
    d = pd.concat([pd.read_csv(p) for p in paths])
    d = d[(d["filter"] == "box") & (d["radius"] == 0.5) & (d["reconstruction"] == "weighted")]
    return d.groupby(["scene", "sampler", "spp"]).agg(mse=("mse_target", "first"), se=("mse_target_se", "first"),
                                                       cpu=("cpu_ms", "mean")).reset_index()


class AdaptiveRecord(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.same_spp, cls.same_time = ar.compare(ar.load(BEFORE), ar.load(AFTER))
        cls.after, cls.before = frame(AFTER), frame(BEFORE)

    def test_equal_spp(self):
        a = self.after
        self.assertTrue(self.same_spp)
        for r in self.same_spp:
            row = a[(a.scene == r["scene"]) & (a.sampler == r["sampler"]) & (a.spp == r["spp"])].iloc[0]
            base = a[(a.scene == r["scene"]) & (a.sampler == r["sampler"].split(":")[1]) & (a.spp == r["spp"])].iloc[0]
            self.assertAlmostEqual(r["ratio"], row.mse / base.mse, places=12)
            self.assertAlmostEqual(r["z"], (row.mse - base.mse) / math.hypot(row.se, base.se), places=9)
            b = self.before
            old = b[(b.scene == r["scene"]) & (b.sampler == r["sampler"]) & (b.spp == r["spp"])].iloc[0]
            self.assertAlmostEqual(r["before_ratio"], old.mse / base.mse, places=12)

    def test_equal_time(self):
        a = self.after
        counts = {}
        for r in self.same_time:
            sd = a[(a.scene == r["scene"]) & (a.sampler == r["sampler"].split(":")[1])].sort_values("cpu")
            x, y = np.log(sd.cpu.to_numpy()), np.log(sd.mse.to_numpy())
            rel = (sd.se / sd.mse).to_numpy()
            row = a[(a.scene == r["scene"]) & (a.sampler == r["sampler"]) & (a.spp == r["spp"])].iloc[0]
            t = math.log(row.cpu)
            if t > x[-1]:  # beyond the last level: the last segment's line
                k = len(x) - 1
            else:
                k = max(1, int(np.searchsorted(x, t)))
            w = (t - x[k - 1]) / (x[k] - x[k - 1])
            base = math.exp(y[k - 1] + w * (y[k] - y[k - 1]))
            if x[0] <= t <= x[-1]:
                self.assertAlmostEqual(base, math.exp(np.interp(t, x, y)), places=12)
            se = ((1 - w) * rel[k - 1] + w * rel[k]) * base
            lr, lse = math.log(row.mse / base), math.hypot(row.se / row.mse, se / base)
            verdict = "wins" if lr < -2 * lse else "loses" if lr > 2 * lse else "tied"
            self.assertAlmostEqual(r["ratio"], row.mse / base, places=10)
            self.assertEqual(r["verdict"], verdict)
            counts.setdefault(r["sampler"], {"wins": 0, "tied": 0, "loses": 0})[verdict] += 1
        self.assertEqual(ar.markdown(self.same_spp, self.same_time)[2], counts)

    def test_record_holds_the_generated_block(self):
        table, summary, _ = ar.markdown(self.same_spp, self.same_time)
        with open(os.path.join(REPO, "results", "adaptive.md"), encoding="utf-8") as f:
            text = f.read()
        self.assertIn(ar.block(table, summary), text)
        with open(os.path.join(DIR, "tables.md"), encoding="utf-8") as f:
            self.assertEqual(f.read(), ar.block(table, summary))


if __name__ == "__main__":
    unittest.main()
