"""answer.csv: written by the report's writer from the committed studies, read back, and every
row (ratio, interval, verdict, heavy_tailed; per scene and across scenes) compared with recompute_answer.py's
independent recomputation from the study CSV; the leading samplers of the page's answer table likewise. And
the issue's example: fence, 4 spp, jittered mitchell r=1 is heavy-tailed and never equivalent."""
import math
import os
import tempfile
import unittest

from . import recompute as rc, recompute_answer as ra
from ..aliaslab_analysis.io import study_csv
from ..aliaslab_analysis.findings import Study
from ..aliaslab_analysis.report import answer_csv
from ..aliaslab_analysis.stats import factors

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PRESENTED = os.path.join(REPO, "results", "presented", "study.csv.gz")
QUICK = os.path.join(REPO, "results", "study", "study.csv.gz")
TOL = 2e-5  # answer.csv keeps 6 significant digits


def close(a, b):
    if isinstance(a, float) and math.isnan(a):
        return isinstance(b, float) and math.isnan(b)
    return math.isclose(float(a), float(b), rel_tol=TOL, abs_tol=1e-12)


class AnswerCsv(unittest.TestCase):
    def check(self, path):
        df, notes = study_csv.load_study(path)
        s = Study(df, notes)
        with tempfile.TemporaryDirectory() as tmp:
            table = answer_csv.read(answer_csv.write(s.answer, tmp))
        rows = rc.read(path)
        per = ra.scenes(rows)
        summary = ra.across(per)
        self.assertEqual(len(table), len(per) + len(summary))
        checked = 0
        for r in table.to_dict("records"):
            k = (r["sampler"], r["filter"], float(r["radius"]), r["filter_params"], r["reconstruction"], r["prefilter"])
            if r["scope"] == "all":
                med, lo, hi, verdict, heavy, n, eq = summary[(r["target"], int(r["spp"]), k)]
                self.assertEqual((int(r["scenes"]), int(r["equivalent_scenes"])), (n, eq), r)
                self.assertEqual(bool(r["heavy_tailed"]), heavy > 0, r)
                want = (med, lo, hi)
            else:
                ratio, lo, hi, verdict, heavy, best = per[(r["target"], int(r["spp"]), r["scope"], k)]
                self.assertEqual((bool(r["heavy_tailed"]), bool(r["best"])), (heavy, best), r)
                want = (ratio, lo, hi)
            for got, w in zip((r["ratio"], r["ci_low"], r["ci_high"]), want):
                self.assertTrue(close(got, w), f"{r}: recomputed {want}")
            self.assertEqual(r["verdict"], verdict, f"{r}: recomputed {want}")
            self.assertEqual(float(r["margin"]), ra.MARGIN)
            checked += 1
        # the page's table: the leading samplers per (target, spp), from the file as written
        picks = factors.sampler_picks(answer_csv.summary(table))
        lead = factors.leaders(picks, len(s.scenes))
        for (target, spp), (_, g) in lead.items():
            self.assertEqual(sorted(g["sampler"]), ra.leaders(summary, target, spp, len(s.scenes)), (target, spp))
        return table, checked

    @unittest.skipUnless(os.path.isfile(PRESENTED), "no committed presented study")
    def test_the_presented_study(self):
        table, checked = self.check(PRESENTED)
        self.assertGreater(checked, 10000)
        self.assertTrue({"equivalent", "worse"} <= set(table["verdict"]))
        fence = table[(table["scope"] == "fence") & (table["spp"] == 4) & (table["sampler"] == "jittered")
                      & (table["filter"] == "mitchell") & (table["radius"] == 1.0)]
        self.assertEqual(len(fence), 3)  # one row per target
        self.assertTrue(fence["heavy_tailed"].all())
        self.assertTrue((fence["verdict"] != "equivalent").all())
        self.assertTrue((fence["interval"] == "bootstrap").all())

    @unittest.skipUnless(os.path.isfile(QUICK), "no committed quick study")
    def test_the_quick_study(self):
        _, checked = self.check(QUICK)
        self.assertGreater(checked, 10000)


class TQuantile(unittest.TestCase):
    def test_the_independent_quantile_matches_the_tables(self):
        # Student's t tables (two-sided 95 %): df 1 12.706, 7 2.365, 30 2.042, inf 1.960
        for df, want in ((1, 12.7062), (7, 2.36462), (30, 2.04227), (math.inf, 1.95996)):
            self.assertAlmostEqual(ra.t_quantile(0.975, df), want, places=4)


if __name__ == "__main__":
    unittest.main()
