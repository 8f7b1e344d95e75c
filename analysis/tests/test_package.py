"""The analysis is a package: one entry point, no sys.path edits, a concept a module.

`python3 -m analysis COMMAND` runs from the repository root, no file edits the import path, and no C++ program
launches Python: the programs write CSV and the charts come from `python3 -m analysis convergence|pointsets`."""
import glob
import os
import re
import subprocess
import sys
import unittest

from ..aliaslab_analysis import cli

ANALYSIS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPO = os.path.dirname(ANALYSIS)
SOURCES = sorted(glob.glob(os.path.join(ANALYSIS, "**", "*.py"), recursive=True))


def python(args, cwd):
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONDONTWRITEBYTECODE="1")
    env.pop("PYTHONPATH", None)
    return subprocess.run([sys.executable] + args, cwd=cwd, env=env, capture_output=True, text=True)


class Package(unittest.TestCase):
    def test_no_file_edits_the_import_path(self):
        edit = re.compile(r"sys\.path\.(insert|append|extend)|sys\.path\s*[+]?=|site\.addsitedir")
        for path in SOURCES:
            with open(path, encoding="utf-8") as f:
                self.assertIsNone(edit.search(f.read()), path)

    def test_modules_stay_short(self):
        for path in SOURCES:
            with open(path, encoding="utf-8") as f:
                self.assertLessEqual(len(f.readlines()), 300, path)

    def test_one_entry_point_lists_every_command(self):
        r = python(["-m", "analysis", "-h"], REPO)
        self.assertEqual(r.returncode, 0, r.stderr)
        for command in cli.COMMANDS:
            self.assertIn(f"  {command} ", r.stdout)
            r2 = python(["-m", "analysis", command, "-h"], REPO)
            self.assertEqual(r2.returncode, 0, r2.stderr)
            self.assertIn(f"usage: python3 -m analysis {command}", r2.stdout)
        self.assertEqual(python(["-m", "analysis", "nosuch"], REPO).returncode, 2)
        self.assertEqual(python(["-m", "analysis"], REPO).returncode, 2)

    def test_an_interpreter_without_pandas_is_told_how_to_run(self):
        # -S: no site-packages, so numpy, pandas and matplotlib cannot be imported
        r = python(["-S", "-m", "analysis", "report", "somewhere"], REPO)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertNotIn("Traceback", r.stderr)
        self.assertIn("lacks numpy, pandas, matplotlib", r.stderr)
        self.assertIn("/usr/bin/python3 -m analysis report somewhere", r.stderr)

    def test_no_program_launches_python(self):
        launch = re.compile(r"runProgram\s*\(\s*\{\s*\"[^\"]*python|analysis/[a-z_/]+\.py\"")
        sources = [p for pattern in ("experiments/**/*.cpp", "experiments/**/*.h", "lib/**/*.cpp")
                   for p in glob.glob(os.path.join(REPO, pattern), recursive=True)]
        self.assertGreater(len(sources), 10)
        for path in sources:
            with open(path, encoding="utf-8") as f:
                self.assertIsNone(launch.search(f.read()), path)
        self.assertIsNotNone(launch.search('runProgram({"/usr/bin/python3", dir + "/analysis/x_chart.py", out})'))


if __name__ == "__main__":
    unittest.main()
