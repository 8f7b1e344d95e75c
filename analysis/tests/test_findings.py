"""Every number the findings state is recomputed from the CSV by a separate code path (recompute.py: the
csv module and plain loops, none of the analysis package) and compared; the numbers
appear in the text as stated. Run on a small Interface-3 CSV (synthetic rows converted by interface3.py:
three targets, per-seed values, the shifted grid, cpu_ms) and on the committed quick study as written
today (the fallbacks)."""
import math
import os
import tempfile
import unittest

import numpy as np

from . import interface3, recompute as rc, recompute_answer as ra, synthetic
from .findings_claims import ANSWER_KINDS, answer_claim
from ..aliaslab_analysis import findings
from ..aliaslab_analysis.io import study_csv

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
COMMITTED = os.path.join(REPO, "results", "study", "study.csv.gz")
PRESENTED = os.path.join(REPO, "results", "presented", "study.csv.gz")
RESULTS_README = os.path.join(REPO, "results", "README.md")


def findings_section(markdown):
    """The '## Findings' section of a Markdown text, without its 'Generated from' line (which names the path)."""
    start = markdown.index("## Findings")
    end = markdown.find("\n## ", start + 1)
    lines = markdown[start:end if end >= 0 else len(markdown)].strip().splitlines()
    return "\n".join(l for l in lines if not l.startswith("_Generated from"))


def expected(rows, claim):
    """The claim's value recomputed (None when the kind is not known here: the test then fails)."""
    k = claim["kind"]
    first = rc.primary(rows)
    tgt = claim.get("target", first)
    prim = [r for r in rows if r["target"] == first]
    if k == "n_scenes":
        return len(set(r["scene"] for r in rows))
    if k == "size":
        return int(max(max(r["width"], r["height"]) for r in rows))
    if k == "rows":
        return len(rows)
    if k == "ref_spp_min":
        return int(min(r["ref_spp"] for r in rows))
    if k in ANSWER_KINDS:
        return answer_claim(rows, claim)
    if k in ("front_size", "front_points", "point_cost"):
        pts = ra.points(rows, tgt)
        if k == "point_cost":
            return pts[(claim["spp"], claim["method"])][1]
        return len(ra.front(pts)) if k == "front_size" else len(pts)
    if k in ("cost_low", "cost_high", "set_by_spp"):
        pts = [p for (spp, _), p in ra.points(rows, tgt).items() if spp == claim["spp"] and math.isfinite(p[1])]
        lo, hi = min(pts, key=lambda p: p[1]), max(pts, key=lambda p: p[1])
        if k != "set_by_spp":
            return lo[1] if k == "cost_low" else hi[1]
        return int(hi[1] - lo[1] <= 2 * math.hypot(lo[2], hi[2]))
    if k == "share":
        vals = []
        for (t, scene, spp), b in ra.best_rows(rows).items():
            if t == tgt and spp == claim["spp"]:
                vals.append(b[claim["term"]] / b["err"] if claim["term"] != "blur_cross"
                            else (b["mse_area"] - b["mse"]) / b["err"])
        return float(np.nanmedian(vals))
    if k in ("own_mse_ratio", "own_mse_scenes"):
        vals = []
        for (t, scene, spp), b in sorted(ra.best_rows(rows).items()):
            if t != tgt or spp != claim["spp"]:
                continue
            cell = [r for r in rows if (r["target"], r["scene"], r["spp"]) == (t, scene, spp) and not r["det"]
                    and math.isfinite(r["err"]) and math.isfinite(r["mse"])]
            vals.append(min(cell, key=lambda r: r["mse"])["err"] / b["err"])
        return float(np.nanmedian(vals)) if k == "own_mse_ratio" else len(vals)
    if k == "aliasing_zero":
        return sum(1 for r in prim if r["aliasing"] == 0 or (math.isfinite(r["aliasing_se"])
                                                             and abs(r["aliasing"]) <= 2 * r["aliasing_se"]))
    if k == "configurations":
        return len(prim)
    if k == "aliasing_negative":
        return sum(1 for r in prim if r["aliasing"] < 0)
    if k == "flagged_rows":
        return sum(1 for r in rows if r["flagged"] == 1)
    if k in ("unstable_rows", "reference_limited_rows", "unstable_filter"):
        def limited(r):  # raw error (before the reference variance is subtracted) within 10x that variance
            ref = r["tre"] if math.isfinite(r["tre"]) else 0.0
            return r["err"] + ref <= 10.0 * ref
        pick = [r for r in rows if r["flagged"] == 1 and limited(r) == (k == "reference_limited_rows")]
        if k == "unstable_filter":
            pick = [r for r in pick if r["filter"] == claim["filter"] and r["radius"] == claim["radius"]]
        return len(pick)
    if k == "heavy_tailed_rows":
        return sum(1 for r in rows if math.isfinite(r["err"]) and ra.heavy(r))
    if k == "deterministic_rows":
        return sum(1 for r in prim if r["det"])
    if k in ("fixed_over_shifted", "against_random"):
        a, b = ("uniform", "uniform-shifted") if k == "fixed_over_shifted" else (claim["sampler"], "random")
        ea, eb = (rc.box_error(rows, rc.primary(rows), x, claim["spp"]) for x in (a, b))
        common = [s for s in ea if s in eb and eb[s] > 0]
        return float(np.median([ea[s] / eb[s] for s in common]))
    if k in ("prefilter_error", "prefilter_time"):
        def best(keep):
            out = {}
            for r in prim:
                if keep(r) and math.isfinite(r["err"]) and ra.measured(r) and r["err"] > 0 and not ra.heavy(r) \
                        and r["flagged"] != 1 and (r["scene"] not in out or r["err"] < out[r["scene"]]["err"]):
                    out[r["scene"]] = r
            return out
        low = min(r["spp"] for r in prim)
        pre = best(lambda r: r["prefilter"] != "none" and r["spp"] == low)
        plain = best(lambda r: r["prefilter"] == "none" and r["spp"] == claim["spp"])
        col = "err" if k == "prefilter_error" else "cost"
        return float(np.median([pre[x][col] / plain[x][col] for x in pre if x in plain]))
    return None


class Recomputed(unittest.TestCase):
    def check(self, path):
        df, notes = study_csv.load_study(path)
        found = findings.compute(df, notes)
        rows = rc.read(path)
        checked = 0
        for f in found:
            for claim in f.claims:
                got = claim["value"]
                want = expected(rows, claim)
                self.assertIsNotNone(want, f"no recomputation for {claim}")
                if isinstance(want, str):
                    self.assertEqual(got, want, claim)
                elif isinstance(want, list):
                    self.assertEqual(sorted(got), want, claim)
                else:
                    self.assertTrue(math.isclose(float(got), float(want), rel_tol=1e-9, abs_tol=1e-12),
                                    f"{claim}: recomputed {want}")
                checked += 1
        self.assertGreater(checked, 20)
        return found

    def test_an_interface3_study(self):
        with tempfile.TemporaryDirectory() as tmp:
            src = synthetic.write(os.path.join(tmp, "old.csv"))
            path = interface3.convert(src, os.path.join(tmp, "new.csv"))
            found = self.check(path)
        keys = [f.key for f in found]
        for key in ("study", "answer:box:0.5", "answer:gaussian:1.5", "answer:lanczos:3", "targets", "front",
                    "cost", "grid", "filters:box:0.5", "shares:lanczos:3"):
            self.assertIn(key, keys)
        text = " ".join(f.text for f in found)
        self.assertIn("uniform-shifted", text)
        self.assertIn("deterministic", text)

    def test_the_fixed_grids_alignment_columns_are_shown_and_recomputed(self):
        """A CSV with the align_* columns on its fixed-grid rows (K camera offsets: here the mean over them is
        1.5x the centred alignment's error, sd 20 % of it): the grid finding states them and they are recomputed;
        the scene tables show them beside the grid."""
        import pandas as pd
        from ..aliaslab_analysis.report.scene import scene_table
        with tempfile.TemporaryDirectory() as tmp:
            path = interface3.convert(synthetic.write(os.path.join(tmp, "o.csv")), os.path.join(tmp, "n.csv"))
            d = pd.read_csv(path, keep_default_na=False, dtype=str)
            grid = d["deterministic"] == "1"
            err = pd.to_numeric(d["mse_target"])
            d["align_offsets"] = np.where(grid, "8", "")
            d["align_mse_target"] = np.where(grid, (1.5 * err).map(repr), "")
            d["align_mse_target_sd"] = np.where(grid, (0.3 * err).map(repr), "")
            d["align_mse_target_se"] = np.where(grid, (0.3 * err / np.sqrt(8)).map(repr), "")
            d.to_csv(path, index=False)
            found = self.check(path)
            df, _ = study_csv.load_study(path)
            table = scene_table(df[(df["scene"] == "a") & (df["target"] == "box:0.5")])
        text = next(f for f in found if f.key == "grid").text
        self.assertIn("over 8 camera offsets (references moved with the camera) its mean error is 1.5x the centred",
                      text)
        self.assertIn("spread 20 %", text)
        self.assertIn("over 8 camera offsets: mean", table)
        self.assertIn("(1.5x this alignment)", table)

    def test_a_prefiltered_study(self):
        with tempfile.TemporaryDirectory() as tmp:
            found = self.check(synthetic.write(os.path.join(tmp, "p.csv"), prefilter=True))
        self.assertIn("prefilter", [f.key for f in found])

    @unittest.skipUnless(os.path.isfile(COMMITTED), "no committed quick study")
    def test_the_committed_quick_study_as_written_today(self):
        found = self.check(COMMITTED)
        study = next(f for f in found if f.key == "study")
        self.assertIn("quick study", study.text)

    @unittest.skipUnless(os.path.isfile(PRESENTED), "no committed presented study")
    def test_the_committed_presented_study(self):
        found = self.check(PRESENTED)
        self.assertIn("answer:box:0.5", [f.key for f in found])

    @unittest.skipUnless(os.path.isfile(PRESENTED), "no committed presented study")
    def test_results_readme_states_the_findings_the_code_computes(self):
        """results/README.md's findings section is the generator's output on the committed CSV, word for word: a
        number edited by hand, or a CSV changed without regenerating the section, fails here."""
        from ..aliaslab_analysis.report.cli import findings_markdown
        with open(RESULTS_README, encoding="utf-8") as f:
            stated = findings_section(f.read())
        self.assertEqual(stated, findings_section(findings_markdown(PRESENTED)))

    def test_the_numbers_appear_in_the_text_as_stated(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = interface3.convert(synthetic.write(os.path.join(tmp, "o.csv")), os.path.join(tmp, "n.csv"))
            df, notes = study_csv.load_study(path)
            found = findings.compute(df, notes)
        shown = {"pick_median_ratio": lambda v: f"{v:.3g}x", "flagged_rows": lambda v: f"{int(v)} of",
                 "rows": lambda v: f"{int(v)}", "share": lambda v: f"{100 * v:.0f} %",
                 "front_size": lambda v: f"{int(v)} of", "cost_low": lambda v: f"{v:.3g}-",
                 "cost_high": lambda v: f"-{v:.3g} ms", "heavy_tailed_rows": lambda v: f"{int(v)} of"}
        n = 0
        for f in found:
            for c in f.claims:
                if c["kind"] in shown:
                    self.assertIn(shown[c["kind"]](c["value"]), f.text, (f.key, c))
                    n += 1
        self.assertGreater(n, 10)


if __name__ == "__main__":
    unittest.main()
