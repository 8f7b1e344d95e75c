"""One copy of the rendered definitions: a page inside the repository's results/ links to results/docs,
a page elsewhere gets its own RESULTS/docs; the committed pages hold no other copy."""
import os
import subprocess
import tempfile
import unittest

from ..aliaslab_analysis.report import docs_html

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


class DocsFolder(unittest.TestCase):
    def test_pages_inside_results_share_results_docs(self):
        shared = os.path.realpath(os.path.join(REPO, "results", "docs"))
        for inside in ("results", "results/study", "results/prefilter", "results/a/b"):
            self.assertEqual(os.path.realpath(docs_html.docs_folder(os.path.join(REPO, inside), REPO)), shared, inside)

    def test_pages_elsewhere_get_their_own(self):
        with tempfile.TemporaryDirectory() as tmp:
            self.assertEqual(docs_html.docs_folder(tmp, REPO), os.path.join(tmp, "docs"))
        # a sibling folder whose name starts like results/ is not inside it
        self.assertEqual(docs_html.docs_folder(os.path.join(REPO, "results2"), REPO),
                         os.path.join(REPO, "results2", "docs"))

    def test_no_committed_copy_but_results_docs(self):
        try:
            files = subprocess.run(["git", "ls-files", "results"], cwd=REPO, capture_output=True, text=True,
                                   check=True).stdout.split()
        except (OSError, subprocess.CalledProcessError):
            self.skipTest("not a git checkout")
        copies = sorted({os.path.dirname(f) for f in files if f.endswith(".html") and "/docs/" in f + "/"
                         and os.path.basename(os.path.dirname(f)) == "docs"})
        self.assertEqual(copies, ["results/docs"])


class Rendered(unittest.TestCase):
    def test_no_formula_becomes_a_link(self):
        """Markdown reads `P[e_k](rho)` as a link to "rho" unless it is code: no rendered definition
        links to a target that is neither a page, an anchor nor a file of the repository."""
        import re
        for name in sorted(os.listdir(os.path.join(REPO, "docs"))):
            if not name.endswith(".md"):
                continue
            with open(os.path.join(REPO, "docs", name), encoding="utf-8") as f:
                page = docs_html.to_html(f.read())
            for href in re.findall(r"href=['\"]([^'\"]+)['\"]", page):
                target = href.split("#")[0]
                if not target or "://" in href:
                    continue
                self.assertTrue(os.path.exists(os.path.join(REPO, "docs", target)), f"{name}: link to {href}")


if __name__ == "__main__":
    unittest.main()
