"""The analysis scripts' checks of a study CSV (study_csv.read_study_csv / load_study).

A cut last line, a row with another number of fields, an empty required value or a non-finite size
is refused (exit 2, a message naming the file and line, no traceback); values beyond what float
images can give (huge but finite errors, which made matplotlib overflow) are noted and left out;
the nonfinite_samples column is optional (older CSVs: unknown) and a non-zero count is noted.
"""
import io
import os
import tempfile
import unittest

from . import synthetic
from .synthetic import run
from ..aliaslab_analysis.io import study_csv
from ..aliaslab_analysis.charts import cli as charts_cli
from ..aliaslab_analysis.report import cli as report_cli
from ..aliaslab_analysis.io.errors import InputError
from ..aliaslab_analysis.io import text_file


class CsvInput(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.csv = synthetic.write(os.path.join(self.tmp.name, "s.csv"), scenes=["a"])
        with open(self.csv, newline="") as f:
            self.text = f.read()

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, text, name="bad.csv"):
        path = os.path.join(self.tmp.name, name)
        with open(path, "w", newline="") as f:
            f.write(text)
        return path

    def refused(self, path, *parts):
        with self.assertRaises(InputError) as e:
            study_csv.load_study(path)
        for p in parts:
            self.assertIn(p, str(e.exception))
        code, _, err = run(charts_cli.main, [path, "--out", os.path.join(self.tmp.name, "charts")])
        self.assertEqual(code, 2, err)
        self.assertNotIn("Traceback", err)
        self.assertIn(os.path.basename(path), err)

    def test_a_cut_last_line_is_refused_naming_it(self):
        lines = self.text.count("\n")
        path = self.write(self.text[:-30])
        self.refused(path, f"line {lines}", "cut (no newline at the end")

    def test_a_row_with_fewer_fields_is_refused(self):
        rows = self.text.split("\r\n")
        rows[3] = ",".join(rows[3].split(",")[:-4])
        self.refused(self.write("\r\n".join(rows)), "line 4", "fields")

    def with_field(self, line, column, value):
        """The synthetic study written with field `column` of line index `line` (0: the header) set to `value`."""
        rows = self.text.split("\r\n")
        f = rows[line].split(",")
        f[column] = value
        rows[line] = ",".join(f)
        return self.write("\r\n".join(rows))

    def test_an_empty_required_value_is_refused(self):
        self.refused(self.with_field(2, 10, ""), "line 3", "column mse is empty")  # column 10: mse

    def motion_csv(self, change=None, drop=None):
        """The synthetic study with the motion columns of a study with frames; `change(i, row)` edits data row i."""
        import csv as csvmod
        rows = list(csvmod.reader(io.StringIO(self.text)))
        head = rows[0] + [c for c in study_csv.MOTION_COLUMNS if c != drop]
        out = [head]
        for i, r in enumerate(rows[1:]):
            if not r:
                continue
            m = dict(zip(study_csv.MOTION_COLUMNS, ["8", "0.25", "0", "1e-3", "1e-4", "2e-3", "1e-4", "3e-3", "1e-4",
                                                     "5e-4"]))
            if change:
                change(i, m)
            out.append(r + [m[c] for c in study_csv.MOTION_COLUMNS if c != drop])
        text = io.StringIO()
        csvmod.writer(text, lineterminator="\n").writerows(out)
        return self.write(text.getvalue(), "motion.csv")

    def test_motion_columns_are_checked(self):
        df, _ = study_csv.load_study(self.motion_csv())
        self.assertEqual(float(df["shimmer"].iloc[0]), 1e-3)
        self.refused(self.motion_csv(lambda i, m: m.update(shimmer="abc") if i == 2 else None),
                     "line 4", "column shimmer", "not a number")
        self.refused(self.motion_csv(drop="shimmer"), "line 1", "motion column(s) shimmer")
        self.refused(self.motion_csv(lambda i, m: m.update(motion_dx="0.5") if i == 1 else None),
                     "line 3", "holds one motion")
        self.refused(self.motion_csv(lambda i, m: m.update(frames="inf") if i == 0 else None), "line 2", "frames")
        # NaN in every shimmer loads (the value is unknown) and the section leaves it out of its rankings
        df, _ = study_csv.load_study(self.motion_csv(lambda i, m: m.update(shimmer="nan")))
        self.assertTrue(df["shimmer"].isna().all())

    def test_a_non_finite_size_is_refused(self):
        self.refused(self.with_field(1, 4, "inf"), "line 2", "column spp")  # column 4: spp

    def test_huge_finite_errors_are_noted_and_drawn_without_overflow(self):
        def huge(r):
            for c in ("mse", "mse_area", "mse_target", "noise", "aliasing", "mse_se", "mse_target_se", "blur"):
                r[c] = float(r[c]) * 1e300 if r[c] not in ("", None) else r[c]
        path = synthetic.write(os.path.join(self.tmp.name, "huge.csv"), modify=huge, scenes=["a"])
        df, notes = study_csv.load_study(path)
        self.assertTrue(any("beyond 1e+30" in n and "mse" in n for n in notes), notes)
        self.assertTrue(df["mse"].isna().all())
        code, _, err = run(charts_cli.main, [path, "--out", os.path.join(self.tmp.name, "charts")])
        self.assertEqual(code, 0, err)
        self.assertNotIn("Traceback", err)

    def test_a_report_of_a_study_without_one_finite_error_is_refused_clearly(self):
        def huge(r):
            for c in ("mse", "mse_area", "mse_target"):
                r[c] = 1e305
        path = synthetic.write(os.path.join(self.tmp.name, "huge.csv"), modify=huge, scenes=["a"])
        os.makedirs(os.path.join(self.tmp.name, "page"))
        code, _, err = run(report_cli.main, [os.path.join(self.tmp.name, "page"), "--study", path])
        self.assertEqual(code, 2, err)
        self.assertIn("no row has a finite error", err)
        self.assertNotIn("Traceback", err)

    def test_nonfinite_samples_is_optional_and_counted(self):
        df, notes = study_csv.load_study(self.csv)  # the synthetic CSV has no such column: unknown
        self.assertTrue(df["nonfinite_samples"].isna().all())
        self.assertFalse(any("nonfinite_samples" in n for n in notes), notes)
        count = [0]

        def dropped(r):
            count[0] += 1
            r["nonfinite_samples"] = 5 if count[0] == 2 else 0
        path = os.path.join(self.tmp.name, "nf.csv")
        import csv as csvmod
        rows = list(csvmod.DictReader(io.StringIO(self.text)))
        with open(path, "w", newline="") as f:
            w = csvmod.DictWriter(f, fieldnames=list(rows[0].keys()) + ["nonfinite_samples"])
            w.writeheader()
            for r in rows:
                dropped(r)
                w.writerow(r)
        df, notes = study_csv.load_study(path)
        self.assertEqual(int(df["nonfinite_samples"].sum()), 5)
        self.assertTrue(any("1 row(s) left NaN or infinite samples" in n for n in notes), notes)

    def test_the_committed_presented_study_still_loads(self):
        import csv as csvmod
        path = os.path.join(os.path.dirname(__file__), "..", "..", "results", "presented", "study.csv.gz")
        self.assertTrue(os.path.isfile(path), "the committed presented study is results/presented/study.csv.gz")
        df, notes = study_csv.load_study(path)
        # one row per scene x sampler x spp x filter at a radius (filter_params) x target
        self.assertEqual(len(df), df["scene"].nunique() * df["sampler"].nunique() * df["spp"].nunique()
                         * df["filter_params"].nunique() * df["target"].nunique())
        self.assertEqual(int(df["nonfinite_samples"].sum()), 0)  # every sample of the presented study finite
        # the same study as an older sweep wrote it (before the column existed): loads, the count unknown
        older = os.path.join(self.tmp.name, "older.csv")
        with io.StringIO(text_file.read_text(path), newline="") as f, open(older, "w", newline="") as g:
            reader = csvmod.DictReader(f)
            names = [n for n in reader.fieldnames if n != "nonfinite_samples"]
            w = csvmod.DictWriter(g, fieldnames=names, extrasaction="ignore")
            w.writeheader()
            w.writerows(reader)
        df, notes = study_csv.load_study(older)
        # one row per scene x sampler x spp x filter at a radius (filter_params) x target, each combination once
        per = df.groupby(["scene", "sampler", "spp", "filter_params", "target"]).size()
        self.assertEqual(int(per.max()), 1)
        self.assertEqual(len(df), df["scene"].nunique() * df["sampler"].nunique() * df["spp"].nunique()
                         * df["filter_params"].nunique() * df["target"].nunique())
        self.assertTrue(df["nonfinite_samples"].isna().all())  # unknown: the column came later

    def test_a_fifo_is_refused_without_blocking(self):
        path = os.path.join(self.tmp.name, "fifo.csv")
        os.mkfifo(path)
        with self.assertRaises(InputError) as e:
            study_csv.load_study(path)
        self.assertIn("not a regular file", str(e.exception))


if __name__ == "__main__":
    unittest.main()
