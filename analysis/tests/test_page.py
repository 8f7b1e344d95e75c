"""The page of an Interface-3 study: the answer table at the top (a column
per target, read from the answer.csv beside the page) and what holds under all, the trade-off per target, the
fixed grid ranked as deterministic and the shifted grid explained, the study described from its CSV, the other
studies in the results folder linked, the rules of the verdicts stated with the margin."""
import os
import re
import tempfile
import unittest

from . import interface3, synthetic
from ..aliaslab_analysis.report import page as report_page


class Page(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.results = os.path.join(cls.tmp.name, "results")
        csv = synthetic.make_results(cls.results, shards=False, engineering=False)
        interface3.convert(csv, csv)  # three targets, per-seed values, the shifted grid, cpu_ms
        other = os.path.join(cls.results, "prefilter")  # another committed study beside it, with its page
        os.makedirs(os.path.join(other, "study"))
        synthetic.write(os.path.join(other, "study", "study.csv"), prefilter=True, scenes=["a"])
        with open(os.path.join(other, "index.html"), "w") as f:
            f.write("<html></html>")
        os.makedirs(os.path.join(cls.results, "charts_only"))  # a folder without a page: not linked
        with open(report_page.build_report(cls.results, csv, draw=False, embed=False), encoding="utf-8") as f:
            cls.page = f.read()

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_the_answer_table_comes_first_with_a_column_per_target(self):
        self.assertLess(self.page.index("id='answer'"), self.page.index("id='gallery'"))
        section = self.page[self.page.index("id='answer'"):self.page.index("id='gallery'")]
        for target in ("box:0.5", "gaussian:1.5", "lanczos:3"):
            self.assertIn(f"<th><code>{target}</code></th>", section)
            self.assertIn(f"Against <code>{target}</code>", self.page)  # its trade-off section
            self.assertIn(f"id='tradeoff-chart-{target.replace(':', '-').replace('.', '-')}'", self.page)
        for spp in (1, 4, 16, 64):
            self.assertIn(f"<tr><th>{spp} spp</th>", section)
        self.assertIn("<a href='answer.csv.gz'>answer.csv.gz</a>", section)
        self.assertTrue(os.path.isfile(os.path.join(self.results, "answer.csv.gz")))
        self.assertIn("What holds under every target", self.page)

    def test_the_fixed_grid_is_deterministic_and_the_shifted_grid_explained(self):
        scenes = self.page[self.page.index("id='scenes'"):self.page.index("id='stability'")]
        fixed = re.findall(r"<tr><td>uniform [^<]*</td><td>\d+</td><td>([^<]*)</td>", scenes)
        self.assertTrue(fixed)
        self.assertTrue(all(cell.endswith("(deterministic)") for cell in fixed), fixed)
        self.assertIn("ranked like any method", scenes)
        self.assertIn("Cranley-Patterson", self.page)
        self.assertNotIn("lucky or not", self.page)

    def test_the_study_is_described_from_its_csv(self):
        self.assertIn("2 scenes at 32 px on the larger side", self.page)
        self.assertIn("8 seeds; references at 4096 spp (64x the highest spp)", self.page)
        self.assertIn("This is a quick study", self.page)

    def test_other_studies_are_linked_with_what_they_are(self):
        self.assertIn("<a href='prefilter/index.html'>prefilter</a>", self.page)
        self.assertRegex(self.page, r"prefilter</a>: 1 scene at 32 px, 3 samplers, spp 1, 4, 16, 64, 8 seeds, "
                                    r"references at 4096 spp, targets box:0.5; pre-filtering")
        self.assertNotIn("charts_only", self.page)

    def test_the_rules_and_the_margin_are_stated(self):
        self.assertIn("How a verdict is reached", self.page)
        self.assertIn("compared paired", self.page)
        self.assertIn("seed 29", self.page)
        self.assertIn("margin of <b>10 %</b>", self.page)
        self.assertIn("heavy-tailed", self.page)

    def test_contents_gallery_and_lazy_images(self):
        # every entry of the table of contents points at an id of the page; every scene has a card
        # in the gallery linking to it; the images are linked files, decoded lazily
        toc = self.page[self.page.index("<nav class='toc'"):self.page.index("</nav>")]
        targets = re.findall(r"href='#([^']+)'", toc)
        ids = set(re.findall(r"\sid='([^']+)'", self.page))
        self.assertTrue(targets)
        self.assertLessEqual(set(targets), ids)
        for scene in ("a", "b"):
            self.assertIn(f"scene-{scene}", targets)
        gallery = self.page[self.page.index("id='gallery'"):self.page.index("id='findings'")]
        self.assertEqual(sorted(re.findall(r"href='#(scene-[^']+)'", gallery)), ["scene-a", "scene-b"])
        self.assertNotIn("data:image", self.page)
        imgs = re.findall(r"<img [^>]*>", self.page)
        self.assertTrue(imgs)
        self.assertTrue(all("loading='lazy'" in i for i in imgs if "src=" in i), imgs[:3])
        # every image has its size, so the page does not jump while they load
        sized = [re.search(r"width='(\d+)' height='(\d+)'", i) for i in imgs if "src=" in i]
        self.assertTrue(all(sized), [i for i, m in zip(imgs, sized) if not m][:3])
        with open(os.path.join(self.results, "charts", "summary_error_time.png"), "rb") as f:
            head = f.read(24)
        w, h = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
        self.assertIn(f"summary_error_time.png' width='{w}' height='{h}'", self.page)


if __name__ == "__main__":
    unittest.main()
