"""The report's adaptive section (report/adaptive.py): every number it states is recomputed
from the committed quick study's CSV by another path (the csv module and plain loops, the rule written again
from the module's statement), under every target; the verdict rule can say each of wins, loses and tied;
the losing cells show their density and error images."""
import csv
import io
import math
import os
import re
import tempfile
import types
import unittest

from ..aliaslab_analysis.io import study_csv, study_rows
from ..aliaslab_analysis.report import adaptive
from ..aliaslab_analysis.io import text_file

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
COMMITTED = os.path.join(REPO, "results", "study", "study.csv.gz")


def recompute(path, target):
    """{(scene, spp, base): dict} by the module doc's rule, from the raw CSV."""
    with io.StringIO(text_file.read_text(path), newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["target"] == target and math.isfinite(float(r["mse_target"]))]
    own_name, own_r = target.split(":")
    cells = {}
    for r in rows:
        cells.setdefault((r["scene"], int(r["spp"])), []).append(r)
    out = {}
    for (scene, spp), cell in cells.items():
        bases = {}
        for r in cell:
            s = r["sampler"]
            if s.startswith("adaptive-") and ":" in s:
                bases.setdefault(s.split(":", 1)[1].split("+")[0], []).append(r)
        for base, ad in bases.items():
            conf = lambda r: (r["filter"], float(r["radius"]), r["reconstruction"], r.get("prefilter") or "none")
            have = set(conf(r) for r in ad)
            b_rows = [r for r in cell if r["sampler"] == base and conf(r) in have]
            if not b_rows:
                continue
            at_own = [r for r in b_rows if r["filter"] == own_name and float(r["radius"]) == float(own_r)]
            pool = at_own or b_rows
            b = min(pool, key=lambda r: float(r["mse_target"]))
            a = min((r for r in ad if conf(r) == conf(b)), key=lambda r: float(r["mse_target"]))
            ea, sa, eb, sb = (float(a["mse_target"]), float(a["mse_target_se"]), float(b["mse_target"]),
                              float(b["mse_target_se"]))
            s = math.sqrt(sa * sa + sb * sb)
            word = "loses" if ea - eb > 2 * s else "wins" if eb - ea > 2 * s else "tied"
            ratio = ea / eb
            out[(scene, spp, base)] = dict(
                verdict=word, ratio=ratio, ratio_se=ratio * math.sqrt((sa / ea) ** 2 + (sb / eb) ** 2),
                z=(eb - ea) / s, adaptive=a["sampler"], filter=b["filter"], radius=float(b["radius"]),
                noise_ratio=float(a["noise"]) / float(b["noise"]), max_spp=int(float(a["max_spp"])),
                aliasing=float(a["aliasing"]), aliasing_se=float(a["aliasing_se"]), own=bool(at_own))
    return out


def rows_of(study):
    """What the section reads of findings.Study (its targets, the primary first, and rows(target)), without the
    rankings that Study computes on construction (slow on 13,500 rows)."""
    df, _ = study_csv.load_study(study)
    targets = study_rows.targets(df)
    return types.SimpleNamespace(targets=targets, primary=targets[0],
                                 rows=lambda t=None: df[df["target"].astype(str) == (t or targets[0])])


def context(study, results, images):
    return types.SimpleNamespace(s=rows_of(study), study=study, results=results, images=images, embed=False,
                                 science="../docs/science.html")


class AdaptiveSection(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.s = rows_of(COMMITTED)

    def test_numbers_recomputed_under_every_target(self):
        for target in self.s.targets:
            got = {(c["scene"], c["spp"], c["base"]): c for c in adaptive.comparisons(self.s.rows(target), target)}
            want = recompute(COMMITTED, target)
            self.assertEqual(sorted(got), sorted(want), target)
            self.assertGreater(len(want), 0)
            for k, w in want.items():
                g = got[k]
                self.assertEqual(g["verdict"], w["verdict"], k)
                self.assertEqual(g["adaptive"], w["adaptive"], k)
                self.assertEqual((g["filter"], g["radius"], g["own_filter"]), (w["filter"], w["radius"], w["own"]), k)
                self.assertEqual(g["max_spp"], w["max_spp"], k)
                for q in ("ratio", "ratio_se", "z", "noise_ratio", "aliasing", "aliasing_se"):
                    self.assertTrue(math.isclose(g[q], w[q], rel_tol=1e-9, abs_tol=1e-15), (k, q, g[q], w[q]))

    def test_the_quick_study_has_verdicts_of_the_rule(self):
        # since the adaptive samplers continue their base's own sequence no cell of the quick study loses
        # (docs/adaptive.md); it has wins and ties, and only the rule's three words
        words = [w["verdict"] for w in recompute(COMMITTED, "box:0.5").values()]
        self.assertLessEqual(set(words), {"wins", "loses", "tied"})
        for v in ("wins", "tied"):
            self.assertIn(v, words)

    def test_verdict_rule(self):
        # se of the difference sqrt(0.1^2 + 0.1^2) = 0.1414: 2 se = 0.283
        self.assertEqual(adaptive.verdict(1.0, 0.1, 1.5, 0.1)[0], "wins")
        self.assertEqual(adaptive.verdict(1.5, 0.1, 1.0, 0.1)[0], "loses")
        self.assertEqual(adaptive.verdict(1.0, 0.1, 1.2, 0.1)[0], "tied")
        self.assertEqual(adaptive.verdict(1.2, 0.1, 1.0, 0.1)[0], "tied")
        word, ratio, ratio_se, z = adaptive.verdict(2.0, 0.2, 4.0, 0.2)
        self.assertAlmostEqual(ratio, 0.5)
        self.assertAlmostEqual(ratio_se, 0.5 * math.sqrt(0.1 ** 2 + 0.05 ** 2))
        self.assertAlmostEqual(z, 2.0 / math.sqrt(0.08))
        self.assertEqual(adaptive.base_of("adaptive-error:sobol+floor=0.5"), "sobol")
        self.assertIsNone(adaptive.base_of("jittered"))

    def test_page_states_the_recomputed_numbers_and_shows_the_images(self):
        results = os.path.join(REPO, "results", "study")
        page = adaptive.adaptive_section(context(COMMITTED, results, os.path.join(results, "images")))
        want = recompute(COMMITTED, "box:0.5")
        n = {v: sum(w["verdict"] == v for w in want.values()) for v in ("wins", "loses", "tied")}
        self.assertIn(f"Over the {len(want)} cells: it wins {n['wins']}, loses {n['loses']}, ties {n['tied']}.", page)
        text = re.sub(r"<[^>]+>", "", page).replace("&plusmn;", "±")
        for (scene, spp, base), w in want.items():
            self.assertIn(f"{w['ratio']:.2f}x ± {w['ratio_se']:.2f}", text)
            if w["verdict"] != "loses":
                self.assertNotIn(f"{scene}, {spp} spp: ", text)
                continue
            line = f"{scene}, {spp} spp: {w['adaptive']} loses to {base} by {w['ratio']:.2f}x ± {w['ratio_se']:.2f}"
            self.assertIn(line, text)
            said = text[text.index(line):].split("\n")[0]
            self.assertIn(f"({-w['z']:.1f} standard errors)", said)
            self.assertIn(f"its noise is {w['noise_ratio']:.2f}x the base's", said)
            self.assertIn(f"aliasing {w['aliasing']:.2g} ± {w['aliasing_se']:.1g}", said)
            zero = abs(w["aliasing"]) <= 2 * w["aliasing_se"]
            self.assertEqual("zero within two standard errors" in said, zero)
            self.assertIn(f"max_spp {w['max_spp']}" if w["max_spp"] <= spp else f"up to {w['max_spp']} in one pixel",
                          said)
            # the committed images of this cell, density beside the base's error (results/adaptive/study/)
            stem = f"../adaptive/study/{scene}/"
            self.assertIn(f"src='{stem}{w['adaptive'].replace(':', '_')}-spp{spp}-box-r0.5-weighted-density.png'", page)
            self.assertIn(f"src='{stem}{base}-spp{spp}-box-r0.5-weighted-error.png'", page)

    def test_no_images_no_figures_and_no_adaptive_no_section(self):
        with tempfile.TemporaryDirectory() as tmp:
            with io.StringIO(text_file.read_text(COMMITTED), newline="") as f:
                rows = list(csv.DictReader(f))
            path = os.path.join(tmp, "plain", "study.csv")
            os.makedirs(os.path.dirname(path))
            everything = list(rows[0])
            older = [c for c in everything if c not in ("max_spp", "mean_spp")]  # a CSV before adaptive columns
            for keep, columns, expect in ((lambda r: True, everything, True),
                                          (lambda r: not r["sampler"].startswith("adaptive"), everything, False),
                                          (lambda r: True, older, True)):
                with open(path, "w", newline="") as f:
                    w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
                    w.writeheader()
                    w.writerows(r for r in rows if keep(r))
                page = adaptive.adaptive_section(context(path, tmp, os.path.join(tmp, "none")))
                self.assertEqual(bool(page), expect)
                self.assertNotIn("<img", page)
                # the sentence on where the samples went is written for losing cells that moved samples
                moved_loser = any(w["verdict"] == "loses" and w["max_spp"] > k[1]
                                  for k, w in recompute(path, "box:0.5").items()) if expect and columns is everything else False
                self.assertEqual("in one pixel" in page, columns is everything and moved_loser)


if __name__ == "__main__":
    unittest.main()
