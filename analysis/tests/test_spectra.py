"""The error spectra in the report: per scene and the independent-vs-correlated comparison.

On a synthetic study with spectra files (a white `random`, a blue `zsobol`) the report has, per scene,
the spectrum section, the overview chart and the side-by-side at 4 and 16 spp, and every image it links
exists; without spectra files (older studies) the section says so and nothing fails. The spectrum loader
and chart are checked against the synthetic law (synthetic.spectrum_power).
"""
import os
import tempfile
import unittest

from . import synthetic
from ..aliaslab_analysis.charts import figures, spectra
from ..aliaslab_analysis.io import study_csv
from ..aliaslab_analysis.report import cli as report_cli
from .test_report import links, run


def section(page, scene):
    """The HTML of one scene's section (from its heading to the next scene or the next h2)."""
    start = page.index(f"<h3 id='scene-{figures.slug(scene)}'>")
    end = min([i for i in (page.find("<h3 ", start + 1), page.find("<h2", start + 1)) if i > 0])
    return page[start:end]


class WithSpectra(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.results = os.path.join(cls.tmp.name, "r")
        cls.csv = synthetic.make_results(cls.results, spectra=True)
        cls.page = synthetic.report_page(cls.results, "--link")

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_loader_reads_every_scene_and_the_law(self):
        spec = spectra.load(self.csv)
        self.assertEqual(set(spec["scene"]), set(synthetic.SCENES))
        c = spectra.curves(spec, "a", 16)
        self.assertEqual(set(c), set(synthetic.SAMPLERS) | {"zsobol"})
        f, p = c["zsobol"]
        for fi, pi in zip(f, p):
            self.assertAlmostEqual(pi, synthetic.spectrum_power("zsobol", 16, fi), delta=1e-12)
        self.assertTrue(all(f[i] < f[i + 1] for i in range(len(f) - 1)))

    def test_pick_samplers(self):
        self.assertEqual(spectra.pick_samplers(["zsobol", "jittered", "random", "bluenoise-dither:random"]),
                         ("random", ["zsobol", "bluenoise-dither:random"]))
        self.assertEqual(spectra.pick_samplers(["random", "jittered"]), ("random", []))
        self.assertEqual(spectra.pick_samplers(["zsobol"]), (None, ["zsobol"]))

    def test_every_scene_has_the_section_charts_and_pair(self):
        for scene in synthetic.SCENES:
            s = section(self.page, scene)
            self.assertIn("Where the error sits on screen", s)
            self.assertNotIn("No error spectra", s)
            slug = figures.slug(scene)
            self.assertIn(f"spectrum_{slug}_spp16.png", s)
            for spp in (4, 16):
                self.assertIn(f"spectrum_pair_{slug}_spp{spp}.png", s)
                self.assertIn(f"random-spp{spp}-box-r0.5-weighted-error.png", s)
                self.assertIn(f"zsobol-spp{spp}-box-r0.5-weighted-error.png", s)
                self.assertIn(f"{spp} spp: random (independent) vs zsobol (correlated)", s)
            self.assertIn("blurred mse", s)
            self.assertIn("FLIP", s)
            self.assertIn("low-frequency share", s)

    def test_blurred_mse_shown_beside_mse_with_values(self):
        df, _ = study_csv.load_study(self.csv)
        r = df[(df["scene"] == "a") & (df["sampler"] == "zsobol") & (df["spp"] == 4)
               & (df["filter_name"] == "box") & (df["radius"] == 0.5)].iloc[0]
        s = section(self.page, "a")
        self.assertIn(f"blurred mse {r['blurred_mse']:.3g}", s)
        self.assertIn(f"mse {r['mse']:.3g}", s)

    def test_every_linked_file_exists(self):
        for link in links(self.page):
            if link.startswith(("#", "http")):
                continue
            self.assertTrue(os.path.isfile(os.path.join(self.results, link.split("#")[0])), link)

    def test_chart_is_nonempty_png(self):
        spec = spectra.load(self.csv)
        path = os.path.join(self.tmp.name, "c.png")
        self.assertEqual(spectra.chart(spec, "a", 4, path), path)
        with open(path, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertIsNone(spectra.chart(spec, "a", 3, os.path.join(self.tmp.name, "none.png")))
        self.assertIsNone(spectra.chart(spec, "nope", 4, os.path.join(self.tmp.name, "none.png")))


class WithoutSpectra(unittest.TestCase):
    def check(self, new_columns):
        with tempfile.TemporaryDirectory() as tmp:
            results = os.path.join(tmp, "r")
            csv_path = synthetic.make_results(results, new_columns=new_columns)
            self.assertIsNone(spectra.load(csv_path))
            code, out, err = run(report_cli.main, [results, "--link"])
            self.assertEqual(code, 0, err)
            with open(os.path.join(results, "index.html"), encoding="utf-8") as f:
                page = f.read()
            # said once, above the scenes, not repeated in each (nothing repeated)
            self.assertEqual(page.count("No error spectra"), 1)
            self.assertLess(page.index("id='scenes'"), page.index("No error spectra"))
            self.assertLess(page.index("No error spectra"), page.index("id='scene-"))
            self.assertNotIn("spectrum_", page)
            return page

    def test_new_columns_no_spectra(self):
        self.check(True)

    def test_old_csv_no_spectra(self):
        page = self.check(False)
        self.assertNotIn("blurred mse", page)

    def test_spectra_without_correlated_sampler_says_so(self):
        with tempfile.TemporaryDirectory() as tmp:
            results = os.path.join(tmp, "r")
            csv_path = synthetic.make_results(results)
            synthetic.write_spectra(os.path.dirname(csv_path), list(synthetic.SAMPLERS))
            code, out, err = run(report_cli.main, [results, "--link"])
            self.assertEqual(code, 0, err)
            with open(os.path.join(results, "index.html"), encoding="utf-8") as f:
                page = f.read()
            self.assertIn("Side-by-side comparison omitted", page)
            self.assertIn("spectrum_a_spp16.png", page)

    def test_malformed_spectrum_file_is_skipped(self):
        with tempfile.TemporaryDirectory() as tmp:
            os.makedirs(os.path.join(tmp, "spectra"))
            with open(os.path.join(tmp, "spectra", "x.csv"), "w") as f:
                f.write("not,a,spectrum\n1,2,3\n")
            self.assertIsNone(spectra.load(os.path.join(tmp, "study.csv")))


if __name__ == "__main__":
    unittest.main()
