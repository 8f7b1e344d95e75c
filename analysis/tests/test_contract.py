"""findings/contract.py: every check recomputed from the committed studies' CSVs by another path (the csv module,
plain loops) and the finding's claims against it; a study whose jittered noise is made larger than random's
yields violations, the finding says so, and the page's contract section shows them in its warning box."""
import csv
import io
import math
import os
import unittest

from ..aliaslab_analysis.findings import contract
from ..aliaslab_analysis.io.study_csv import load_study
from ..aliaslab_analysis.io import text_file

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STUDIES = [text_file.existing(os.path.join(REPO, "results", p, "study.csv")) for p in ("presented", "study", "negative_control")]


def plain_checks(path):
    rows = {}
    with io.StringIO(text_file.read_text(path), newline="") as f:
        for r in csv.DictReader(f):
            if (r["filter"], r["reconstruction"], r["prefilter"]) != ("box", "weighted", "none"):
                continue
            if abs(float(r["radius"]) - 0.5) > 1e-12:
                continue
            rows.setdefault((r["scene"], int(r["spp"]), r["sampler"]), (float(r["noise"]), float(r["noise_se"])))
    out = {}
    for (scene, spp, sampler), (a, sa) in rows.items():
        if sampler == "random" or (scene, spp, "random") not in rows:
            continue
        b, sb = rows[(scene, spp, "random")]
        if b <= 0:
            continue
        r = a / b
        se = r * math.sqrt(((sa / a) if a > 0 else 0) ** 2 + (sb / b) ** 2)
        bound = {"jittered": 1.0, "nrooks": spp / (spp - 1), "sobol": 2.0 if spp & (spp - 1) == 0 else None}.get(sampler)
        out[(scene, sampler, spp)] = (r, se, bound, bound is not None and se > 0 and (r - bound) / se > 3)
    return out


class Contract(unittest.TestCase):
    def test_committed_studies(self):
        for path in STUDIES:
            if not os.path.isfile(path):
                continue
            with self.subTest(path=path):
                df, _ = load_study(path)
                mine = {(c["scene"], c["sampler"], c["spp"]): c for c in contract.checks(df)}
                ref = plain_checks(path)
                self.assertEqual(set(mine), set(ref))
                for k, (r, se, bound, bad) in ref.items():
                    self.assertAlmostEqual(mine[k]["ratio"], r, places=12)
                    self.assertAlmostEqual(mine[k]["se"], se, places=12)
                    self.assertEqual(mine[k]["bound"], bound)
                    self.assertEqual(mine[k]["violated"], bad)
                f = contract.finding(df)
                claims = {c["kind"]: c for c in f.claims}
                self.assertEqual(claims["contract_checks"]["value"], sum(b is not None for _, _, b, _ in ref.values()))
                self.assertEqual(claims["contract_violations"]["value"], sum(v[3] for v in ref.values()))
                if "closest" in claims:
                    c = claims["closest"]
                    worst = max((k for k in ref if ref[k][2]), key=lambda k: ref[k][0] / ref[k][2])
                    self.assertEqual((c["scene"], c["sampler"], c["spp"]), worst)

    def test_a_violation_is_found_and_shown_first(self):
        path = os.path.join(REPO, "results", "negative_control", "study.csv")
        df, _ = load_study(path)
        jit = df["sampler"] == "jittered"
        df.loc[jit, "noise"] = df.loc[jit, "noise"] * 1.5  # jittered made 1.5x noisier: above random's
        f = contract.finding(df)
        bad = [c for c in f.claims if c["kind"] == "violation"]
        self.assertTrue(bad)
        self.assertTrue(all(c["sampler"] == "jittered" for c in bad))
        self.assertIn("violated", f.text)
        from ..aliaslab_analysis.report.contract import contract_section

        class C:
            pass
        c = C()
        c.df, c.science = df, "docs/science.html"
        html = contract_section(c)
        self.assertIn("#fde8e8", html)  # the warning box
        self.assertIn("jittered", html)


if __name__ == "__main__":
    unittest.main()
