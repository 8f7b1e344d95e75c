"""answer.csv.gz: the answer as data (stats/equivalence.table), written gzipped by the report beside its page and
read back for the page's answer table, so that the page shows what the file says.

Columns: target, spp, scope (a scene, or "all" across scenes), the method (sampler, filter, radius,
filter_params, reconstruction, prefilter, deterministic), ratio (to the scene's best; for "all" the median over
scenes), ci_low, ci_high (95 %: per scene the interval of stats/effect.py, for "all" the bootstrap over scenes),
verdict (equivalent / worse / undetermined at the margin), heavy_tailed, margin, interval (how the interval was
made: log, bootstrap, linear, best; bootstrap-scenes for "all"), best (the scene's best row), error and
error_se (per scene), scenes and equivalent_scenes (for "all": the scenes with a ratio and those where the
method is equivalent)."""
import gzip
import io
import os

import pandas as pd

from ..io import errors, text_file
from ..stats import equivalence

NAME = "answer.csv.gz"


def write(table, folder):
    """Writes FOLDER/answer.csv.gz atomically (6 significant digits; gzip -9 without a name or time, so the same
    table gives the same bytes); returns its path."""
    path = os.path.join(folder, NAME)
    tmp = path + ".partial"
    try:
        data = gzip.compress(table.to_csv(index=False, float_format="%.6g").encode("utf-8"), compresslevel=9, mtime=0)
        with open(tmp, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except OSError as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        errors.fail(f"{folder}: cannot write {NAME}: {e.strerror or e}")
    return path


def read(path):
    """answer.csv(.gz) as a DataFrame (text columns as text, booleans as bool); gzipped or not."""
    t = pd.read_csv(io.StringIO(text_file.read_text(path)), dtype={"scope": str, "sampler": str, "filter": str, "filter_params": str,
                                 "reconstruction": str, "prefilter": str, "verdict": str, "interval": str,
                                 "target": str}, keep_default_na=False, na_values=[""])
    for c in ("deterministic", "heavy_tailed", "best"):
        t[c] = t[c].astype(str).str.lower().isin(["true", "1"])
    return t


def summary(table):
    """The across-scene records of answer.csv (scope "all") under the names of equivalence.across, for
    stats/factors: filter_name, median_ratio, equivalent, heavy (0/1)."""
    a = table[table["scope"] == equivalence.ALL]
    return a.rename(columns={"filter": "filter_name", "ratio": "median_ratio", "equivalent_scenes": "equivalent"}).assign(
        heavy=lambda d: d["heavy_tailed"].astype(int))
