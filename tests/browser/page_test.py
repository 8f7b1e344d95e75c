"""The report page in a real browser (issue 30 item 6): a tiny study is swept and reported here (about 10 s),
its index.html loaded from file:// in headless Chromium at 1366 px, and checked: no severe console message
(a failed load, a script error), every link and anchor resolves, every image decodes (lazy ones included),
every entry of the table of contents points at an element of the page, the scene gallery links to the scenes,
a click on a chart opens it enlarged (Esc closes it), and the section comparing a 12-px quick study of the
same scenes opens with its tables. The committed pages (results/index.html, the
studies' pages beside it, engineering.html, the definitions) are loaded too: every link, script, style sheet
and image of theirs resolves. A screenshot of the top of the page at 1366 px is
written to ARTIFACTS/page-1366.png (CI keeps it: look at it when the page changes).

  python3 tests/browser/page_test.py --sweep build/bin/sweep --source . --artifacts build/artifacts
Exit 77 (CTest: skipped) with the reason when chromium, chromium-driver or python3-selenium is missing.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import unittest
import urllib.parse

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import browser  # noqa: E402

ARGS = None
COMMITTED = ("index.html", "study/index.html", "prefilter/index.html", "engineering.html", "docs/science.html")


def sweep(program, source, out, folder, size, images=True):
    study = os.path.join(out, folder)
    subprocess.run([program, "--scenes", f"{source}/scenes/zoneplate.txt,{source}/scenes/fence.txt", "--size", size,
                    size, "--samplers", "uniform,jittered,sobol,zsobol", "--spp", "4,16", "--filters", "box,lanczos",
                    "--radii", "0.5,1", "--seeds", "2", "--ref-spp", "64", "--target", "area,gaussian:1.5",
                    "--cache", os.path.join(out, "cache"), "--out", study, "--quiet", "--threads", "2"]
                   + (["--images"] if images else []), check=True)
    return os.path.join(study, "study.csv")


def sweep_and_report(program, source, out):
    """The page of a 24-px study, with a 12-px one of the same scenes as its quick study (report --quick)."""
    study = sweep(program, source, out, "study", "24")
    quick = sweep(program, source, out, "quick", "12", images=False)
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONDONTWRITEBYTECODE="1")
    subprocess.run([sys.executable, "-m", "analysis", "report", out, "--study", study, "--quick", quick],
                   check=True, cwd=source, env=env, stdout=subprocess.DEVNULL)
    return os.path.join(out, "index.html")


class Page(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.page = sweep_and_report(ARGS.sweep, ARGS.source, cls.tmp.name)
        cls.driver = browser.start(1366, 900)
        cls.driver.get("file://" + cls.page)
        cls.failed_images = browser.wait_images(cls.driver)
        cls.log = browser.console(cls.driver)
        browser.screenshot(cls.driver, os.path.join(ARGS.artifacts, "page-1366.png"))

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()
        cls.tmp.cleanup()

    def js(self, code, *args):
        return self.driver.execute_script(code, *args)

    def test_no_severe_console_message(self):
        self.assertEqual(browser.severe(self.log), [])

    def test_every_image_decodes(self):
        self.assertEqual(self.failed_images, [])
        self.assertGreater(self.js("return document.querySelectorAll('figure img').length;"), 10)

    def test_every_link_resolves(self):
        hrefs = self.js("return Array.from(document.querySelectorAll('a[href]')).map(a => a.getAttribute('href'));")
        self.assertTrue(hrefs)
        for href in hrefs:
            parts = urllib.parse.urlsplit(href)
            self.assertIn(parts.scheme, ("", "file"), f"a link leaves the page's folder: {href}")
            if not parts.path:  # an anchor on this page
                self.assertTrue(self.js("return document.getElementById(arguments[0]) !== null;",
                                        urllib.parse.unquote(parts.fragment)), f"no element with id {href}")
                continue
            target = os.path.normpath(os.path.join(os.path.dirname(self.page), urllib.parse.unquote(parts.path)))
            self.assertTrue(os.path.exists(target), f"{href}: {target} does not exist")

    def test_the_table_of_contents_points_at_the_page(self):
        ids = self.js("return Array.from(document.querySelectorAll('nav.toc a')).map(a => a.hash.slice(1));")
        for required in ("answer", "findings", "tradeoff", "scenes", "scene-zoneplate", "scene-fence", "heatmap-fence",
                         "gallery"):
            self.assertIn(required, ids)
        for i in ids:
            self.assertTrue(self.js("return document.getElementById(arguments[0]) !== null;", i), i)
        # sticky: after scrolling far down, the contents are still on screen
        self.js("window.scrollTo(0, document.body.scrollHeight / 2);")
        top = self.js("return document.querySelector('nav.toc').getBoundingClientRect().top;")
        self.assertGreaterEqual(top, -1)
        self.assertLess(top, 50)

    def test_the_answer_table_and_the_trade_off_charts_open(self):
        """Issue 44: the answer at a glance is a table near the top of the page (a row per spp level, a column per
        target, read from the answer.csv.gz beside the page), the rules name the margin, and every target's trade-off
        chart decodes; screenshots of both go to ARTIFACTS (answer-table.png, tradeoff.png)."""
        from selenium.webdriver.common.by import By
        table = self.driver.find_element(By.CSS_SELECTOR, "table.answer-table")
        self.assertLess(self.js("return arguments[0].getBoundingClientRect().top + window.scrollY;", table), 1800)
        self.assertEqual(self.js("return arguments[0].querySelectorAll('tr').length;", table), 3)  # head, 4, 16 spp
        targets = self.js("return arguments[0].querySelectorAll('th code').length;", table)
        self.assertEqual(targets, 2)
        self.assertGreater(self.js("return arguments[0].querySelectorAll('.samplers').length;", table), 3)
        self.assertTrue(os.path.isfile(os.path.join(os.path.dirname(self.page), "answer.csv.gz")))
        self.assertIn("margin of 10 %", self.js("return document.getElementById('rules').textContent;"))
        browser.screenshot(self.driver, os.path.join(ARGS.artifacts, "answer-table.png"),
                           self.js("return arguments[0].getBoundingClientRect().top + window.scrollY - 60;", table))
        charts = self.driver.find_elements(By.CSS_SELECTOR, "figure[id^='tradeoff-chart-'] img")
        self.assertEqual(len(charts), targets)
        for img in charts:
            self.js("arguments[0].scrollIntoView();", img)
            self.assertGreater(self.js("return arguments[0].naturalWidth;", img), 100)
        browser.screenshot(self.driver, os.path.join(ARGS.artifacts, "tradeoff.png"),
                           self.js("return document.getElementById('tradeoff').getBoundingClientRect().top "
                                   "+ window.scrollY;"))
        self.js("window.scrollTo(0, 0);")

    def test_the_quick_study_against_this_one_opens(self):
        """Issue 44 item 6: the section comparing the smaller study with this one, with its answer table (a row per
        target and spp) and its scene table (a row per scene); a screenshot goes to ARTIFACTS (sizes.png)."""
        top = self.js("var s = document.getElementById('sizes'); return s ? s.getBoundingClientRect().top "
                      "+ window.scrollY : -1;")
        self.assertGreater(top, 0)
        rows = self.js("var t = [], e = document.getElementById('sizes').nextElementSibling;"
                       "while (e && e.tagName != 'H2') { if (e.tagName == 'TABLE') t.push(e.querySelectorAll('td')"
                       ".length ? e.querySelectorAll('tr').length - 1 : 0); e = e.nextElementSibling; } return t;")
        self.assertEqual(rows, [4, 2])  # 2 targets x 2 spp; 2 scenes
        browser.screenshot(self.driver, os.path.join(ARGS.artifacts, "sizes.png"), top - 20)
        self.js("window.scrollTo(0, 0);")

    def test_the_gallery_links_every_scene(self):
        links = self.js("return Array.from(document.querySelectorAll('.gallery a')).map(a => a.hash);")
        self.assertEqual(sorted(links), ["#scene-fence", "#scene-zoneplate"])

    def test_a_click_enlarges_a_chart_and_escape_closes_it(self):
        from selenium.webdriver.common.by import By
        from selenium.webdriver.common.keys import Keys
        img = self.driver.find_element(By.CSS_SELECTOR, "figure img")
        self.js("arguments[0].scrollIntoView();", img)
        img.click()
        box = self.driver.find_element(By.ID, "lightbox")
        self.assertIn("open", box.get_attribute("class"))
        self.assertEqual(box.find_element(By.TAG_NAME, "img").get_attribute("src"), img.get_attribute("src"))
        self.driver.find_element(By.TAG_NAME, "body").send_keys(Keys.ESCAPE)
        self.assertNotIn("open", box.get_attribute("class"))

    def test_every_link_of_the_committed_pages_resolves(self):
        """The committed pages (results/index.html and the studies' pages beside it) from file://: every link,
        script, style sheet and image refers to a file that exists (the sub-studies' definitions: the one copy in
        results/docs) and every anchor to an element of its page."""
        pages = [os.path.join(ARGS.source, "results", p) for p in COMMITTED]
        pages = [p for p in pages if os.path.isfile(p)]
        self.assertTrue(pages)
        try:
            for page in pages:
                self.driver.get("file://" + page)
                refs = self.js("return [...document.querySelectorAll('a[href]')].map(a => a.getAttribute('href'))"
                               ".concat([...document.querySelectorAll('script[src], img[src]')].map(e => "
                               "e.getAttribute('src')), [...document.querySelectorAll('link[href]')].map(e => "
                               "e.getAttribute('href')), [...document.querySelectorAll('img[data-src]')].map(e => "
                               "e.getAttribute('data-src')));")
                self.assertGreater(len(refs), 5, page)
                for href in refs:
                    parts = urllib.parse.urlsplit(href)
                    if parts.scheme == "data":
                        continue
                    self.assertIn(parts.scheme, ("", "file"), f"{page}: a link leaves the page's folder: {href}")
                    if not parts.path:
                        self.assertTrue(self.js("return document.getElementById(arguments[0]) !== null;",
                                                urllib.parse.unquote(parts.fragment)), f"{page}: no element {href}")
                        continue
                    target = os.path.normpath(os.path.join(os.path.dirname(page), urllib.parse.unquote(parts.path)))
                    self.assertTrue(os.path.exists(target), f"{page}: {href}: {target} does not exist")
        finally:
            self.driver.get("file://" + self.page)

    def test_the_definitions_open_as_html(self):
        href = self.js("return Array.from(document.querySelectorAll('a')).find(a => a.textContent.includes("
                       "'docs/science.md')).getAttribute('href');")
        self.assertTrue(href.endswith(".html"), href)
        self.driver.get("file://" + os.path.join(os.path.dirname(self.page), href))
        self.assertGreater(self.js("return document.querySelectorAll('.docs table, .docs li').length;"), 5)
        self.assertEqual(browser.severe(browser.console(self.driver)), [])
        self.driver.get("file://" + self.page)


def main():
    global ARGS
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sweep", required=True)
    ap.add_argument("--source", required=True, help="the repository root")
    ap.add_argument("--artifacts", required=True, help="folder of the screenshot (CI artefact)")
    ap.add_argument("--skip", help="skip with this reason (exit 77)")
    ARGS, rest = ap.parse_known_args()
    why = ARGS.skip or browser.missing()
    if why:
        print(f"SKIPPED: {why}")
        return 77
    ARGS.source = os.path.abspath(ARGS.source)
    ARGS.artifacts = os.path.abspath(ARGS.artifacts)
    result = unittest.main(argv=[sys.argv[0]] + rest, exit=False, verbosity=2).result
    return 0 if result.wasSuccessful() else 1


if __name__ == "__main__":
    sys.exit(main())
