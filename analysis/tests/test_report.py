"""The report and the study loader on tiny synthetic studies.

The report is rendered once for a results folder that looks like a user's run (a merged CSV with
its two shard CSVs beside it, images, a benchmark and a fuzzing record): its findings come first,
every scene has its decomposition chart, every linked file exists, the engineering records are on
their own page, and the study is named as the user's study, not "the reference study".
"""
import io
import math
import os
import re
import tempfile
import unittest

import pandas as pd

from . import synthetic
from .synthetic import run
from ..aliaslab_analysis import findings
from ..aliaslab_analysis.stats import fits
from ..aliaslab_analysis.io import study_csv
from ..aliaslab_analysis.charts import cli as charts_cli
from ..aliaslab_analysis.report import cli as report_cli
from ..aliaslab_analysis.report import elements as report_elements
from ..aliaslab_analysis.report import findings as report_findings
from ..aliaslab_analysis.report import page as report_page


def links(page):
    """Every src and href value of the page."""
    return re.findall(r"(?:src|href)='([^']*)'", page)


class Report(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.results = os.path.join(cls.tmp.name, "mine")
        cls.csv = synthetic.make_results(cls.results)
        cls.linked = synthetic.report_page(cls.results, "--link")
        cls.embedded = synthetic.report_page(cls.results, "--reuse-charts", "--embed")
        with open(os.path.join(cls.results, "engineering.html"), encoding="utf-8") as f:
            cls.engineering = f.read()

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_findings_come_first(self):
        page = self.linked
        findings = page.index("id='findings'")
        self.assertIn("Answer for this study", page)
        self.assertLess(findings, page.index("<figure"))  # only the scene gallery's thumbnails come before
        self.assertLess(page.index("id='gallery'"), findings)
        self.assertLess(findings, page.index("id='scenes'"))
        self.assertLess(page.index("id='scenes'"), page.index("id='stability'"))
        # The one chart of the findings sits before the first scene.
        self.assertLess(page.index("summary_error_time.png"), page.index("id='scene-a'"))

    def test_the_answer_is_computed_from_the_data(self):
        # In the synthetic study the fixed grid `uniform` (noise 0: deterministic) has the lowest mse_target at
        # lanczos r=0.5 in every scene and at every spp; it is ranked like any method, so it is the answer, and
        # every other sampler is worse by more than the margin: check that against the CSV itself.
        df = pd.read_csv(self.csv)
        for spp, g in df.groupby("spp"):
            best = g.loc[g.groupby("scene")["mse_target"].idxmin()]
            self.assertEqual(set(zip(best["sampler"], best["filter"], best["radius"])),
                             {("uniform", "lanczos", 0.5)}, spp)
            self.assertRegex(self.linked, rf"At {spp} spp, [^<]*: <b>uniform</b> \(the fixed grid; 2, 1x\) at "
                                          "lanczos r=0.5")
            self.assertIn(f"<tr><th>{spp} spp</th><td><div class='samplers'><b>uniform <small>(fixed grid)</small>"
                          "</b> <small>2/2</small>", self.linked)
        self.assertIn("uniform lanczos r=0.5</td><td>64</td><td>0.000237 (deterministic)", self.linked)
        self.assertNotIn("&plusmn; 0<", self.linked.split("id='stability'")[0].replace("&plusmn; 0</td>", ""))

    def test_every_scene_has_its_decomposition_chart(self):
        for scene in ("a", "b"):
            self.assertIn(f"src='charts/decomposition_{scene}.png'", self.linked)
            with open(os.path.join(self.results, "charts", f"decomposition_{scene}.png"), "rb") as f:
                self.assertTrue(f.read(8).startswith(b"\x89PNG"))

    def test_every_linked_file_exists(self):
        found = links(self.linked)
        self.assertGreater(len([l for l in found if l.endswith(".png")]), 10)
        for link in found:
            if link.startswith("#"):
                continue
            self.assertFalse(re.match(r"^[a-z]+://", link), link)  # nothing outside the repository
            path = os.path.normpath(os.path.join(self.results, link.split("#")[0]))
            if link.endswith("science.md"):  # the definitions: the repository's own docs/science.md
                self.assertEqual(path, os.path.normpath(report_page.SCIENCE))
                continue
            self.assertTrue(os.path.isfile(path), link)

    def test_images_are_chosen_not_listed(self):
        # The contact sheets, the target and the best and worst methods: not every image.
        pngs = [l for l in links(self.linked) if "/images/" in l]
        self.assertIn("study/images/contact-a.png", pngs)
        self.assertIn("study/images/a/uniform-spp64-lanczos-r0.5-weighted.png", pngs)  # the best at 64 spp
        self.assertLess(len(pngs), 20)

    def test_embedded_page_is_self_contained(self):
        for link in re.findall(r"src='([^']*)'", self.embedded):
            self.assertTrue(link.startswith("data:image/png;base64,"), link[:60])
        self.assertNotIn("http://", self.embedded)
        self.assertNotIn("https://", self.embedded)

    def test_embedded_charts_keep_their_size_and_renders_their_pixels(self):
        # Every embedded image decodes to a PNG of its file's size; a chart (from charts/) is palette-coded
        # (written so by figures.save_figure) and no larger than its file, any other image (a render) is
        # embedded byte for byte.
        import base64
        from PIL import Image
        charts_dir = os.path.join(self.results, "charts")
        chart = sorted(f for f in os.listdir(charts_dir) if f.endswith(".png"))[0]
        path = os.path.join(charts_dir, chart)
        data = report_elements.chart_png_bytes(path)
        with Image.open(io.BytesIO(data)) as small, Image.open(path) as full:
            self.assertEqual(small.size, full.size)
            self.assertEqual(small.mode, "P")
            self.assertEqual(full.mode, "P")
        self.assertLessEqual(len(data), os.path.getsize(path))
        render = os.path.join(self.tmp.name, "render.png")
        Image.new("RGB", (5, 3), (10, 200, 30)).save(render)
        src = report_elements.image_src(self.tmp.name, render, True)
        with open(render, "rb") as f:
            self.assertEqual(base64.b64decode(src.split(",", 1)[1]), f.read())
        for link in re.findall(r"src='data:image/png;base64,([^']*)'", self.embedded):
            with Image.open(io.BytesIO(base64.b64decode(link))) as im:
                im.verify()

    def test_no_engineering_log_opens_the_page(self):
        for text in ("before the fused pass", "fuzz_scene", "Study speed"):
            self.assertNotIn(text, self.linked)
            self.assertIn(text, self.engineering)
        self.assertLess(self.linked.index("id='stability'"), self.linked.index("engineering.html"))

    def test_a_users_study_is_labelled_as_that_study(self):
        self.assertNotIn("reference study", self.linked.lower())
        title = re.search(r"<h1>(.*?)</h1>", self.linked).group(1)
        self.assertIn(os.path.realpath(self.csv), title)
        self.assertIn("quick study", title)  # 32 px: says so, from the CSV
        self.assertIn("This is a quick study", self.linked)
        self.assertEqual(report_page.study_label(self.csv, "my zone plates"), "my zone plates")

    def test_shard_csvs_beside_the_merged_one_do_not_duplicate_rows(self):
        self.assertTrue(os.path.isfile(os.path.join(self.results, "study", "study.shard-0-of-2.csv")))
        self.assertIn("96 configurations", self.linked)
        self.assertNotIn("192 configurations", self.linked)

    def test_definitions_link_to_the_repository(self):
        self.assertIn("docs/science.md", self.linked)
        self.assertNotIn("shared/guide", self.linked)
        self.assertNotIn("SCIENCE.md", self.linked)


class ReportVariants(unittest.TestCase):
    """Cheaper checks: build_report without redrawing the per-scene charts, or findings alone."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def test_an_old_csv_falls_back_and_says_so(self):
        results = os.path.join(self.tmp.name, "old")
        csv = synthetic.make_results(results, new_columns=False, shards=False, engineering=False)
        with open(report_page.build_report(results, csv, draw=False), encoding="utf-8") as f:
            page = f.read()
        self.assertIn("no mse_target column", page)
        self.assertIn("mse_area - mse", page)
        self.assertNotIn("engineering.html", page)

    def test_prefiltered_rows_are_compared_with_plain_sampling_at_higher_spp(self):
        csv = synthetic.write(os.path.join(self.tmp.name, "p.csv"), prefilter=True)
        df, notes = study_csv.load_study(csv)
        text = " ".join(report_findings.findings(df, notes, "area"))
        self.assertIn("Pre-filtered at 1 spp", text)
        self.assertIn("plain 64 spp", text)

    def test_blur_does_not_win(self):
        # box r=1 gets the lowest own mse everywhere but a large blur: every ranking must use the
        # error against the target, and the findings must say what an own-mse ranking would pick.
        def wide_box(r):
            if r["filter"] == "box" and r["radius"] == 1.0:
                r["mse"] = 1e-9
                r["blur"] = 0.5
                r["cross"] = 0.0
                r["mse_target"] = r["noise"] + r["aliasing"] + 0.5
        csv = synthetic.write(os.path.join(self.tmp.name, "w.csv"), modify=wide_box)
        df, notes = study_csv.load_study(csv)
        s = findings.Study(df, notes)
        for (target, spp), (_, pick) in s.leaders.items():
            self.assertFalse(((pick["filter_name"] == "box") & (pick["radius"] == 1.0)).any(), spp)
        own = next(f for f in findings.compute(df, notes, s) if f.key == "own_mse")
        self.assertIn("box r=1", own.text)
        self.assertGreater(next(c["value"] for c in own.claims if c["kind"] == "own_mse_ratio"), 10)
        self.assertIn("would win", " ".join(report_findings.findings(df, notes, "area")))

    def test_repeated_configurations_are_refused_by_report_and_charts(self):
        csv = synthetic.write(os.path.join(self.tmp.name, "d.csv"), scenes=["a"])
        with open(csv) as f:
            lines = f.read().splitlines()
        with open(csv, "a") as f:
            f.write(lines[5] + "\n")  # a second copy of one configuration
        for main, args in ((report_cli.main, [self.tmp.name, "--study", csv]),
                           (charts_cli.main, [csv, "--out", os.path.join(self.tmp.name, "c")])):
            code, _, err = run(main, args)
            self.assertEqual(code, 2, err)
            self.assertIn("repeat a configuration", err)
            self.assertIn("lines 6, 50", err)  # 48 rows + header: the copy is line 50
        self.assertFalse(os.path.exists(os.path.join(self.tmp.name, "c")))
        self.assertFalse(os.path.exists(os.path.join(self.tmp.name, "index.html")))


class Loader(unittest.TestCase):
    def test_load_study_renames_filter_and_adds_the_error_columns(self):
        with tempfile.TemporaryDirectory() as tmp:
            csv = synthetic.write(os.path.join(tmp, "s.csv"))
            df, notes = study_csv.load_study(csv)
            self.assertNotIn("filter", df.columns)
            self.assertEqual(set(df["filter_name"]), {"box", "lanczos"})
            self.assertTrue(callable(df.filter))  # DataFrame.filter is no longer shadowed
            raw = pd.read_csv(csv)
            self.assertEqual(list(df["error"]), list(raw["mse_target"]))
            self.assertEqual(list(df["error_se"]), list(raw["mse_target_se"]))
            # a CSV of the older columns: the fallbacks of the newer columns, each said in words
            self.assertEqual([n.split(":")[0] for n in notes], ["No deterministic column", "No cpu_ms column",
                                                                "No mse_target_seeds column"])
            # blur + cross = mse_target - noise - aliasing (the synthetic law holds exactly)
            resid = (df["noise"] + df["aliasing"] + df["blur_cross"] - df["error"]).abs().max()
            self.assertLess(resid, 1e-12)

    def test_old_csv_error_is_mse_area(self):
        with tempfile.TemporaryDirectory() as tmp:
            csv = synthetic.write(os.path.join(tmp, "s.csv"), new_columns=False)
            df, notes = study_csv.load_study(csv)
            self.assertEqual(list(df["error"]), list(pd.read_csv(csv)["mse_area"]))
            self.assertTrue(any("mse_area" in n for n in notes))
            self.assertTrue(df["error_se"].isna().all())

    def test_zero_within_error(self):
        z = study_csv.zero_within_error([0.0, 1.0, -1.0, 1.0, 3.0, 1.0], [0.0, 0.5, 0.5, 0.49, 1.0, math.nan])
        self.assertEqual(list(z), [True, True, True, False, False, False])

    def test_slopes_need_three_spp_levels(self):
        self.assertIsNone(fits.slope_or_none([4, 16], [1.0, 0.25]))
        self.assertIsNone(fits.slope_or_none([4, 16, 64], [1.0, 0.25, 0.0]))  # only two usable
        self.assertAlmostEqual(fits.slope_or_none([4, 16, 64], [1.0, 0.25, 1 / 16]), -1.0)

    def test_prefilter_is_part_of_the_key(self):
        with tempfile.TemporaryDirectory() as tmp:
            csv = synthetic.write(os.path.join(tmp, "s.csv"), prefilter=True)
            df, _ = study_csv.load_study(csv)  # no repeated configuration: prefilter tells them apart
            self.assertEqual(len(df), 192)
            self.assertIn("prefilter", study_csv.config_key(df))


if __name__ == "__main__":
    unittest.main()
