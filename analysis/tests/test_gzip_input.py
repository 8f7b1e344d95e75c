"""Gzipped study CSVs (io/text_file.py; the committed studies are study.csv.gz): the readers give the same
DataFrames from a CSV and from its gzip (one member, as gzip -9 -n writes it, or several, as the sweep appends);
a gzip cut short is refused naming the file; the default studies are found under their .gz names; answer.csv.gz
is written gzipped, deterministically, and read back; the committed studies are where the page and tests look."""
import gzip
import os
import shutil
import subprocess
import tempfile
import unittest

import pandas as pd

from . import synthetic
from ..aliaslab_analysis.findings.study import Study
from ..aliaslab_analysis.io import study_csv, text_file
from ..aliaslab_analysis.io.errors import InputError
from ..aliaslab_analysis.report import answer_csv, studies
from ..aliaslab_analysis.report import cli as report_cli
from ..aliaslab_analysis.report import sizes

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


class GzipInput(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.csv = synthetic.write(os.path.join(self.tmp.name, "study.csv"), scenes=["a", "b"])
        with open(self.csv, "rb") as f:
            self.raw = f.read()

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def gzipped(self):
        """{name: path}: the CSV gzipped by gzip(1) -9 -n, and as three members (header, rows, rows)."""
        one = self.path("one.csv.gz")
        with open(one, "wb") as f:
            f.write(subprocess.run(["gzip", "-9", "-n", "-c", self.csv], check=True, capture_output=True).stdout)
        cut1 = self.raw.index(b"\n") + 1
        cut2 = self.raw.index(b"\n", len(self.raw) // 2) + 1
        many = self.path("many.csv.gz")
        with open(many, "wb") as f:
            for part in (self.raw[:cut1], self.raw[cut1:cut2], self.raw[cut2:]):
                f.write(gzip.compress(part, mtime=0))
        # a gzip at a plain name is read by its content, not its name
        named_plain = self.path("named_plain.csv")
        shutil.copy(one, named_plain)
        return {"one": one, "many": many, "named_plain": named_plain}

    def test_the_same_dataframes_from_a_csv_and_its_gzip(self):
        plain = study_csv.read_study_csv(self.csv)
        loaded, notes = study_csv.load_study(self.csv)
        for name, gz in self.gzipped().items():
            with open(gz, "rb") as f:
                self.assertEqual(f.read(2), b"\x1f\x8b", name)
            self.assertEqual(text_file.read_text(gz), self.raw.decode("utf-8"), name)
            pd.testing.assert_frame_equal(study_csv.read_study_csv(gz), plain, obj=name)
            df, n = study_csv.load_study(gz)
            self.assertEqual(n, notes, name)
            pd.testing.assert_frame_equal(df.drop(columns=["seed_values"]), loaded.drop(columns=["seed_values"]),
                                          obj=name)
            for a, b in zip(df["seed_values"], loaded["seed_values"]):
                self.assertTrue((a is None and b is None) or list(a) == list(b), name)

    def test_a_gzip_cut_short_or_damaged_is_refused_naming_the_file(self):
        gz = self.gzipped()["many"]
        with open(gz, "rb") as f:
            data = f.read()
        cut = self.path("cut.csv.gz")
        with open(cut, "wb") as f:
            f.write(data[:-7])
        with self.assertRaises(InputError) as e:
            study_csv.load_study(cut)
        self.assertIn("cut.csv.gz", str(e.exception))
        self.assertIn("cut short", str(e.exception))
        bad = self.path("bad.csv.gz")
        with open(bad, "wb") as f:
            f.write(data[:20] + bytes(b ^ 0x5A for b in data[20:60]) + data[60:])
        with self.assertRaises(InputError) as e:
            study_csv.load_study(bad)
        self.assertIn("bad.csv.gz", str(e.exception))
        code, _, err = synthetic.run(report_cli.main, [self.tmp.name, "--study", cut])
        self.assertEqual(code, 2)
        self.assertIn("cut short", err)

    def test_the_default_studies_are_found_gzipped(self):
        results = self.path("results")
        os.makedirs(os.path.join(results, "study"))
        gz = os.path.join(results, "study", "study.csv.gz")
        shutil.copy(self.gzipped()["one"], gz)
        self.assertEqual(report_cli.default_study(results), gz)
        self.assertEqual(studies.csv_of(results), gz)
        self.assertEqual(sizes.quick_csv(results, self.csv), gz)
        self.assertIn("2 scenes", studies.summary(gz))
        self.assertEqual(studies.summary(gz), studies.summary(self.csv))
        # a plain study.csv, when there is one, is still the one found
        shutil.copy(self.csv, os.path.join(results, "study", "study.csv"))
        self.assertEqual(report_cli.default_study(results), os.path.join(results, "study", "study.csv"))

    def test_answer_csv_is_written_gzipped_the_same_bytes_each_time(self):
        df, notes = study_csv.load_study(self.csv)
        table = Study(df, notes).answer
        first = answer_csv.write(table, self.tmp.name)
        self.assertTrue(first.endswith("answer.csv.gz"))
        with open(first, "rb") as f:
            a = f.read()
        answer_csv.write(table, self.tmp.name)
        with open(first, "rb") as f:
            self.assertEqual(f.read(), a)
        self.assertEqual(gzip.decompress(a).decode("utf-8"), table.to_csv(index=False, float_format="%.6g"))
        back = answer_csv.read(first)
        self.assertEqual(list(back.columns), list(table.columns))
        self.assertEqual(len(back), len(table))


class CommittedStudies(unittest.TestCase):
    def test_the_committed_studies_are_gzipped_under_their_new_names(self):
        for rel in ("presented/study.csv.gz", "study/study.csv.gz", "answer.csv.gz", "study/answer.csv.gz"):
            path = os.path.join(REPO, "results", rel)
            self.assertTrue(os.path.isfile(path), rel)
            with open(path, "rb") as f:
                self.assertEqual(f.read(2), b"\x1f\x8b", rel)
            self.assertFalse(os.path.exists(path[:-3]), f"{rel[:-3]} beside {rel}: one study, one file")
        # the quick study loads, and report's default finds it under its new name
        self.assertEqual(report_cli.default_study(os.path.join(REPO, "results")),
                         os.path.join(REPO, "results", "study", "study.csv.gz"))
        df, _ = study_csv.load_study(os.path.join(REPO, "results", "study", "study.csv.gz"))
        self.assertGreater(len(df), 1000)


if __name__ == "__main__":
    unittest.main()
