"""The analysis in layers: each module of aliaslab_analysis/ sits in one layer folder, and a module imports
only from its own layer or the layers below it.

    io < stats < findings < charts < report < viewer < teaching < the command line (cli.py)

io reads and checks files; stats computes estimates; findings holds a study's numbers and text (data only, no
HTML or Markdown); charts computes and draws figures; report writes the HTML (and Markdown) pages; viewer renders
and exports the comparison viewer; teaching builds the teaching strand from the viewer's exports.
"""
import ast
import glob
import os
import unittest

PACKAGE = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "aliaslab_analysis")
LAYERS = ["io", "stats", "findings", "charts", "report", "viewer", "teaching"]
ROOT_MODULES = {"__init__.py", "cli.py", "api.py"}  # api.py: the documented API (io, stats, findings)


def layer_of(parts):
    """The layer index of a module given by its path parts under the package; the root is above every layer."""
    return LAYERS.index(parts[0]) if len(parts) > 1 and parts[0] in LAYERS else len(LAYERS)


def upward_imports(source, parts):
    """The imports of a module (path parts under the package, e.g. ['findings', 'study.py']) that reach a layer
    above its own: [(line, imported layer)]. Relative imports are resolved against the module's folder; absolute
    ones count when they name the package (analysis.aliaslab_analysis....)."""
    own = layer_of(parts)
    folder = list(parts[:-1])
    found = []
    for node in ast.walk(ast.parse(source)):
        targets = []
        if isinstance(node, ast.ImportFrom):
            if node.level:
                if node.level - 1 > len(folder):
                    continue  # above the package (analysis/...): not one of its layers
                mod = folder[:len(folder) - (node.level - 1)] + (node.module.split(".") if node.module else [])
                # `from .. import x` at the package root: x names the layer
                targets = [mod] if mod else [[a.name] for a in node.names]
            elif (node.module or "").startswith("analysis.aliaslab_analysis."):
                targets = [node.module.split(".")[2:]]
        elif isinstance(node, ast.Import):
            targets = [a.name.split(".")[2:] for a in node.names if a.name.startswith("analysis.aliaslab_analysis.")]
        for t in targets:
            if t and t[0] in LAYERS and LAYERS.index(t[0]) > own:
                found.append((node.lineno, t[0]))
    return found


def modules():
    for path in sorted(glob.glob(os.path.join(PACKAGE, "**", "*.py"), recursive=True)):
        yield path, os.path.relpath(path, PACKAGE).split(os.sep)


class Layers(unittest.TestCase):
    def test_no_module_imports_from_a_layer_above_its_own(self):
        for path, parts in modules():
            with open(path, encoding="utf-8") as f:
                self.assertEqual(upward_imports(f.read(), parts), [], "/".join(parts))

    def test_every_module_sits_in_a_layer(self):
        for _, parts in modules():
            if len(parts) == 1:
                self.assertIn(parts[0], ROOT_MODULES, "a loose module at the package root")
            else:
                self.assertIn(parts[0], LAYERS)

    def test_the_check_sees_an_upward_import(self):
        findings = ["findings", "study.py"]
        self.assertEqual(upward_imports("from ..report.markdown import inline\n", findings), [(1, "report")])
        self.assertEqual(upward_imports("def f():\n    from ..charts import axes\n", findings), [(2, "charts")])
        self.assertEqual(upward_imports("from analysis.aliaslab_analysis.viewer import plan\n", findings),
                         [(1, "viewer")])
        self.assertEqual(upward_imports("from ..io import errors\nfrom ..stats import ties\nfrom . import answer\n",
                                        findings), [])
        self.assertEqual(upward_imports("from .teaching import build\n", ["cli.py"]), [])
        self.assertEqual(upward_imports("from . import teaching\n", ["viewer", "cli.py"]), [])
        self.assertEqual(upward_imports("from .. import teaching\n", ["viewer", "cli.py"]), [(1, "teaching")])


if __name__ == "__main__":
    unittest.main()
