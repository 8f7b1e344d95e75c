"""Every chart is produced from a small generated study CSV, and the Pareto
front and flagged table match what the CSV's known structure implies."""
import itertools
import os
import sys
import tempfile
import unittest

import pandas as pd

import math

from . import recompute as rc, synthetic
from ..aliaslab_analysis.io import study_csv
from ..aliaslab_analysis.charts import (convergence_experiment, figures, filter_profiles, pointsets)
from ..aliaslab_analysis.charts import cli as charts_cli
from ..aliaslab_analysis.report import markdown as report_markdown
from ..aliaslab_analysis.report import page as report_page


def is_chart(path):
    if not os.path.isfile(path) or os.path.getsize(path) < 1000:
        return False
    with open(path, "rb") as f:
        head = f.read(400)
    return head.startswith(b"\x89PNG") if path.endswith(".png") else b"<svg" in head


class StudyCharts(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.csv = synthetic.write(os.path.join(cls.tmp.name, "study.csv"))
        cls.out = os.path.join(cls.tmp.name, "charts")
        charts_cli.main([cls.csv, "--out", cls.out])

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    NAMES = ["stability"] + [f"{kind}_{scene}" for kind in ("speed_accuracy", "convergence", "heatmap",
                                                             "decomposition", "radius") for scene in ("a", "b")]

    def test_every_chart_is_written_as_png_and_no_svg_by_default(self):
        for name in self.NAMES:
            self.assertTrue(is_chart(os.path.join(self.out, f"{name}.png")), f"{name}.png")
            self.assertFalse(os.path.exists(os.path.join(self.out, f"{name}.svg")), f"{name}.svg written unasked")

    def test_svg_asks_for_an_svg_twin_of_every_chart(self):
        out = os.path.join(self.tmp.name, "charts-svg")
        try:
            charts_cli.main([self.csv, "--out", out, "--svg"])
        finally:
            figures.write_svg(False)
        for name, ext in itertools.product(self.NAMES, ("png", "svg")):
            self.assertTrue(is_chart(os.path.join(out, f"{name}.{ext}")), f"{name}.{ext}")

    def test_the_front_keeps_the_rows_nothing_beats_in_both(self):
        # Against the common target (mse_target), not each filter's own mse (stats/fronts.py): a row is on the
        # front when no other row has both an error and a time at most its own, one of them lower. Flagged rows
        # and the fixed grid (deterministic, ranked like any method) are candidates like any other.
        rows = rc.read(self.csv)
        front = pd.read_csv(os.path.join(self.out, "pareto.csv"))
        for scene in ("a", "b.scene"):
            cand = [r for r in rows if r["scene"] == scene and math.isfinite(r["err"])]
            expected = {(p["cost"], round(p["err"], 12)) for p in cand
                        if not any(q["err"] <= p["err"] and q["cost"] <= p["cost"]
                                   and (q["err"] < p["err"] or q["cost"] < p["cost"]) for q in cand)}
            mine = front[front["scene"] == scene]
            self.assertEqual(set(zip(mine["cost"], mine["error"].round(12))), expected, scene)
            self.assertTrue(any(r["det"] for r in cand if (r["cost"], round(r["err"], 12)) in expected))
        self.assertIn("flagged", front.columns)

    def test_a_nearly_exact_row_below_zero_is_drawn_and_on_the_front(self):
        # A corrected error can be negative (the references' variance subtracted): such a row is flagged,
        # drawn at the bottom edge and, being the most accurate, on the front.
        def exact(r):
            if r["scene"] == "a" and r["sampler"] == "jittered" and r["spp"] == 64 and r["filter"] == "box" \
                    and r["radius"] == 0.5:
                r.update(mse_target=-1e-7, mse_target_se=1e-7, flagged=1)
        with tempfile.TemporaryDirectory() as tmp:
            csv = synthetic.write(os.path.join(tmp, "s.csv"), modify=exact, scenes=["a"])
            charts_cli.main([csv, "--out", os.path.join(tmp, "c")])
            self.assertTrue(is_chart(os.path.join(tmp, "c", "speed_accuracy_a.png")))
            front = pd.read_csv(os.path.join(tmp, "c", "pareto.csv"))
        row = front[(front["sampler"] == "jittered") & (front["spp"] == 64) & (front["filter_name"] == "box")
                    & (front["radius"] == 0.5)]
        self.assertEqual(len(row), 1)
        self.assertEqual(int(row["flagged"].iloc[0]), 1)

    def test_a_flagged_row_keeps_its_place_on_the_charts(self):
        # scene b, random, spp 1 is flagged: it stays in decomposition.csv.gz, and on the summary chart its
        # method's point is drawn (hollow), with the true number of scenes behind its median.
        dec = pd.read_csv(os.path.join(self.out, "decomposition.csv.gz"))
        self.assertEqual(int(dec[(dec["sampler"] == "random") & (dec["spp"] == 1)]["flagged"].sum()), 4)
        df, notes = study_csv.load_study(self.csv)
        from ..aliaslab_analysis.findings import Study
        from ..aliaslab_analysis.report.summary_chart import summary_chart
        _, _, points = summary_chart(Study(df, notes), os.path.join(self.tmp.name, "summary"))
        random1 = points[(points["sampler"] == "random") & (points["spp"] == 1)]
        self.assertEqual(len(random1), 4)  # 2 filters x 2 radii: every one drawn
        self.assertTrue((random1["scenes"] == 2).all())
        self.assertEqual(list(random1["hollow"]), list(random1["heavy"] > 0))

    def test_flagged_table_lists_the_flagged_rows(self):
        flagged = pd.read_csv(os.path.join(self.out, "flagged.csv"))
        # scene b, sampler random, spp 1: 2 filters x 2 radii.
        self.assertEqual(len(flagged), 4)
        self.assertTrue((flagged["sampler"] == "random").all() and (flagged["spp"] == 1).all())

    def test_missing_column_is_a_clear_error(self):
        bad = os.path.join(self.tmp.name, "bad.csv")
        pd.read_csv(self.csv).drop(columns=["noise"]).to_csv(bad, index=False)
        with self.assertRaises(SystemExit) as cm, open(os.devnull, "w") as devnull:
            old, sys.stderr = sys.stderr, devnull
            try:
                charts_cli.main([bad, "--out", self.out])
            finally:
                sys.stderr = old
        self.assertEqual(cm.exception.code, 2)


def exit_code(main, args):
    """main(args)'s exit status, with stderr silenced (0 when it returns normally)."""
    with open(os.devnull, "w") as devnull:
        old, sys.stderr = sys.stderr, devnull
        try:
            main(args)
        except SystemExit as e:
            return e.code
        finally:
            sys.stderr = old
    return 0


class BadInput(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, *parts):
        return os.path.join(self.tmp.name, *parts)

    def test_unknown_filter_is_refused_before_anything_is_written(self):
        csv = synthetic.write(self.path("study.csv"))
        self.assertEqual(exit_code(charts_cli.main, [csv, "--out", self.path("out"), "--filter", "nosuch"]), 2)
        self.assertFalse(os.path.exists(self.path("out")))

    def test_an_unusable_out_folder_exits_2(self):
        csv = synthetic.write(self.path("study.csv"))
        blocker = self.path("a_file")
        open(blocker, "w").close()
        self.assertEqual(exit_code(charts_cli.main, [csv, "--out", os.path.join(blocker, "sub")]), 2)
        conv = self.path("c.csv")
        pd.DataFrame([("random", "disk", n, 1.0 / n, 4) for n in (1, 2, 4)],
                     columns=convergence_experiment.COLUMNS).to_csv(conv, index=False)
        self.assertEqual(exit_code(convergence_experiment.main, [conv, "--out", os.path.join(blocker, "sub")]), 2)

    def test_header_only_inputs_are_no_data_rows(self):
        conv = self.path("c.csv")
        pd.DataFrame(columns=convergence_experiment.COLUMNS).to_csv(conv, index=False)
        self.assertEqual(exit_code(convergence_experiment.main, [conv, "--out", self.path("o")]), 2)
        prof = self.path("p.csv")
        pd.DataFrame(columns=filter_profiles.COLUMNS).to_csv(prof, index=False)
        self.assertEqual(exit_code(filter_profiles.main, ["--csv", prof, "--out", self.path("o")]), 2)
        ps = self.path("ps")
        os.makedirs(ps)
        open(os.path.join(ps, "pointsets.csv"), "w").write("sampler,n\n")
        open(os.path.join(ps, "spectra.csv"), "w").write("sampler,n,sets,k,k_norm,power\n")
        self.assertEqual(exit_code(pointsets.main, [ps, "--out", ps]), 2)

    def test_every_markdown_table_of_a_file_becomes_its_own_html_table(self):
        text = ("| a | b |\n|---|---|\n| 1 | **2** |\n\nsome text\n\n| c |\n|---|\n| 3 |\n"
                "| not | a table |\n")
        page = report_markdown.markdown_tables(text)
        self.assertEqual(page.count("<table>"), 2)
        self.assertIn("<th>c</th>", page)
        self.assertIn("<td><b>2</b></td>", page)
        self.assertNotIn("<td>c</td>", page)  # the second header is not a row of the first table


class OtherCharts(unittest.TestCase):
    def test_convergence_pointset_filter_charts_and_index(self):
        with tempfile.TemporaryDirectory() as tmp:
            # Convergence CSV with slopes -0.5 and -1.
            rows = [(s, f, n, c * n ** e, 16) for s, e in (("random", -0.5), ("jittered", -1.0))
                    for f, c in (("disk", 0.5), ("gaussian", 0.2)) for n in (1, 2, 4, 8, 16, 48, 64)]
            conv = os.path.join(tmp, "convergence")
            os.makedirs(conv)
            pd.DataFrame(rows, columns=convergence_experiment.COLUMNS).to_csv(os.path.join(conv, "c.csv"), index=False)
            convergence_experiment.main([os.path.join(conv, "c.csv"), "--out", conv, "--fit-min", "1"])
            # Point-set tables.
            ps = os.path.join(tmp, "pointsets")
            os.makedirs(ps)
            pd.DataFrame([("random", n, 4, 0.1 / n ** .5, 0.01, 0.1, 0.05, 0.3, "") for n in (16, 64)],
                         columns=["sampler", "n", "sets", "l2star_mean", "l2star_sd", "min_dist_mean",
                                  "min_dist_min", "min_dist_norm_mean", "warning"]).to_csv(
                os.path.join(ps, "pointsets.csv"), index=False)
            pd.DataFrame([("random", n, 4, k, k / n ** .5, 1.0) for n in (16, 64) for k in range(1, 9)],
                         columns=["sampler", "n", "sets", "k", "k_norm", "power"]).to_csv(
                os.path.join(ps, "spectra.csv"), index=False)
            try:
                pointsets.main([ps, "--out", ps, "--svg"])  # the one command asked for SVG here
            finally:
                figures.write_svg(False)
            # Filter profiles.
            fp = os.path.join(tmp, "filters")
            os.makedirs(fp)
            prof = [("box", 0.5, "box r=0.5", "profile", x / 10, float(abs(x) <= 5)) for x in range(-8, 9)]
            prof += [("box", 0.5, "box r=0.5", "response", v / 10, 1.0 / (1 + v)) for v in range(0, 20)]
            pd.DataFrame(prof, columns=filter_profiles.COLUMNS).to_csv(os.path.join(fp, "p.csv"), index=False)
            filter_profiles.main(["--csv", os.path.join(fp, "p.csv"), "--out", fp])
            for path in ("convergence/convergence", "pointsets/spectra", "pointsets/discrepancy",
                         "filters/filter_profiles"):
                self.assertTrue(is_chart(os.path.join(tmp, f"{path}.png")), f"{path}.png")
                svg = os.path.join(tmp, f"{path}.svg")
                self.assertTrue(is_chart(svg) if path.startswith("pointsets") else not os.path.exists(svg), svg)
            # The report's section on samplers and filters shows these charts, by relative path or embedded.
            section = report_page.isolation_section(tmp, embed=False)
            for path in ("convergence/convergence.png", "pointsets/spectra.png", "filters/filter_profiles.png"):
                self.assertIn(f"src='{path}'", section)
            self.assertNotIn("http", section)
            self.assertIn("data:image/png;base64,", report_page.isolation_section(tmp, embed=True))


if __name__ == "__main__":
    unittest.main()
