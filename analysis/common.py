"""Shared helpers of the aliaslab analysis scripts: reading the study CSV,
the log-log slope fit, the Pareto front and figure saving.

Run every script with /usr/bin/python3 (Debian's numpy, pandas, matplotlib).
"""
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

# The sweep CSV's columns, in order (lib/study/csv.h).
STUDY_COLUMNS = [
    "scene", "width", "height", "sampler", "spp", "filter", "radius", "filter_params",
    "reconstruction", "seeds", "mse", "aliasing", "noise", "mse_area", "psnr", "ref_spp",
    "ref_error", "flagged", "nan_pixels", "negative_pixels", "undefined_pixels", "trace_ms",
    "reconstruct_ms", "threads",
]
# Columns that identify one configuration (compare.py matches on them).
CONFIG_KEY = ["scene", "width", "height", "sampler", "spp", "filter", "radius", "filter_params",
              "reconstruction"]
# Columns added later (coord/COLUMNS.md); any may be absent from an older CSV.
# Text columns; `prefilter` is part of the configuration key when present.
OPTIONAL_TEXT = ["target", "prefilter"]
OPTIONAL_NUMERIC = ["mse_target", "blur", "cross", "mse_se", "noise_se", "aliasing_se", "mse_target_se",
                    "flip", "lowfreq_error", "lowfreq_error_se", "blurred_mse", "mean_spp", "max_spp"]
TEXT_COLUMNS = {"scene", "sampler", "filter", "filter_params", "reconstruction", "target", "prefilter"}


class InputError(Exception):
    """Bad input: the message names the file (and line or column)."""


def fail(message):
    """Prints an input error and exits with status 2 (1 is kept for regressions)."""
    print(f"error: {message}", file=sys.stderr)
    sys.exit(2)


def prepare_out(path, option="--out"):
    """Creates the output folder `path` (or fails, exit 2, naming the option) before anything is written."""
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as e:
        fail(f"{option}: cannot create folder '{path}': {e.strerror or e}")
    if not os.access(path, os.W_OK):
        fail(f"{option}: folder '{path}' is not writable")


def require_rows(df, path, columns):
    """Fails (exit 2) unless df has every column in `columns` and at least one data row."""
    missing = [c for c in columns if c not in df.columns]
    if missing:
        fail(f"{path}: line 1: missing column(s) {', '.join(missing)}")
    if df.empty:
        fail(f"{path}: no data rows")


def read_table(path, columns, numeric):
    """Reads a small experiment CSV (convergence, filter profiles): every column in `columns` must be
    present, there must be data rows, and every column in `numeric` must hold numbers (NaN written
    as 'nan' is allowed). Raises InputError naming the file, line and column."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file")
    try:
        df = pd.read_csv(path, dtype=str, keep_default_na=False)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError, ValueError) as e:
        raise InputError(f"{path}: not a readable CSV: {str(e).strip()}") from e
    return check_table(df, path, columns, numeric)


def check_table(df, path, columns, numeric):
    """The checks of read_table on a DataFrame read as text; returns it with `numeric` converted."""
    missing = [c for c in columns if c not in df.columns]
    if missing:
        raise InputError(f"{path}: line 1: missing column(s) {', '.join(missing)} "
                         f"(expected {', '.join(columns)})")
    if df.empty:
        raise InputError(f"{path}: no data rows")
    for c in numeric:
        raw = df[c].astype(str).str.strip()
        converted = pd.to_numeric(raw, errors="coerce")
        bad = converted.isna() & ~raw.str.lower().isin(["nan", "-nan", "+nan"])
        if bad.any():
            line = int(bad.to_numpy().nonzero()[0][0]) + 2
            raise InputError(f"{path}: line {line}: column {c}: not a number: {raw[bad].iloc[0]!r}")
        df[c] = converted
    return df


def read_study_csv(path):
    """Reads a sweep CSV, checking its columns and that it has data rows; returns a DataFrame with
    `time_ms` = trace_ms + reconstruct_ms added. Raises InputError."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file")
    try:
        df = pd.read_csv(path, dtype=str, keep_default_na=False)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as e:
        raise InputError(f"{path}: not a readable CSV: {e}") from e
    missing = [c for c in STUDY_COLUMNS if c not in df.columns]
    if missing:
        raise InputError(f"{path}: line 1: missing column(s) {', '.join(missing)}")
    if df.empty:
        raise InputError(f"{path}: no data rows")
    for c in STUDY_COLUMNS + [c for c in OPTIONAL_NUMERIC if c in df.columns]:
        if c in TEXT_COLUMNS:
            continue
        raw = df[c].astype(str).str.strip()
        converted = pd.to_numeric(raw, errors="coerce")
        bad = converted.isna() & ~raw.str.lower().isin(["nan", "-nan", "+nan", ""])
        if bad.any():
            line = int(bad.to_numpy().nonzero()[0][0]) + 2
            raise InputError(f"{path}: line {line}: column {c}: not a number: {raw[bad].iloc[0]!r}")
        df[c] = converted
    df["time_ms"] = df["trace_ms"] + df["reconstruct_ms"]
    return df


def config_key(df):
    """The columns that identify one configuration in df: CONFIG_KEY, plus `prefilter` when present
    (under either spelling of the filter column)."""
    key = [("filter_name" if c == "filter" and "filter" not in df.columns else c) for c in CONFIG_KEY]
    return key + (["prefilter"] if "prefilter" in df.columns else [])


def check_unique(df, path):
    """Raises InputError when two rows of df share a configuration key: a CSV holds one study, and
    averaging or picking one of two runs silently would hide that they differ."""
    key = config_key(df)
    dup = df.duplicated(key, keep=False)
    if not dup.any():
        return
    first = df[dup].iloc[0]
    same = df[(df[key] == first[key]).all(axis=1)]
    lines = ", ".join(str(int(i) + 2) for i in same.index[:5])
    what = " ".join(f"{c}={first[c]}" for c in key if str(first[c]) != "")
    raise InputError(f"{path}: {int(dup.sum())} rows repeat a configuration (same {', '.join(key)}); "
                     f"e.g. lines {lines}: {what}. A study CSV must hold each configuration once: "
                     "was it written by two runs with different options, or are shards concatenated "
                     "with their merge? Use one run's CSV (sweep --merge combines shards)")


# How load_study renames the CSV's columns (the CSV itself stays as written by the sweep).
RENAMED = {"filter": "filter_name"}


def load_study(path):
    """Reads a study CSV for analysis and returns (DataFrame, notes).

    The DataFrame has one row per configuration (a CSV repeating a configuration
    raises InputError, see check_unique) and well-named columns:
      - every CSV column under its own name, except `filter`, which is renamed
        `filter_name` (`filter` shadows DataFrame.filter; see RENAMED);
      - numbers as floats (NaN / Inf kept as such), text as str;
      - `time_ms` = trace_ms + reconstruct_ms (time per image);
      - `prefilter` = 'none' when the CSV has no such column (older sweeps);
      - `target` = 'box:0.5' when absent (older sweeps measured mse_area against
        the pixel-area reference, the default target, which the sweep writes box:0.5);
      - `error` = the error against the study's common target, the column every
        ranking uses: mse_target, or for older CSVs without it mse_area (the
        same quantity against the pixel-area reference);
      - `error_se` = its standard error (mse_target_se), NaN when unknown;
      - `blur_cross` = blur + cross when both are present, else mse_area - mse
        (older CSVs: blur and the cross term together, not separable);
      - `aliasing_zero` = True where aliasing is within two standard errors of
        0 (needs aliasing_se; False when unknown).
    `notes` lists, in words, each fallback taken, for the report and charts to show.
    """
    df = read_study_csv(path)
    check_unique(df, path)
    notes = []
    df = df.rename(columns=RENAMED)
    if "prefilter" not in df.columns:
        df["prefilter"] = "none"
    if "target" not in df.columns:
        df["target"] = "box:0.5"
    if "mse_target" in df.columns:
        df["error"] = df["mse_target"]
    else:
        df["error"] = df["mse_area"]
        notes.append("This CSV has no mse_target column (written by an older sweep): the error against "
                     "the target is mse_area, the error against the pixel-area reference.")
    df["error_se"] = df["mse_target_se"] if "mse_target_se" in df.columns else np.nan
    if "blur" in df.columns and "cross" in df.columns:
        df["blur_cross"] = df["blur"] + df["cross"]
    else:
        df["blur_cross"] = df["mse_area"] - df["mse"]
        notes.append("No blur and cross columns: blur and the cross term are shown together as "
                     "mse_area - mse.")
    if "mse_target_se" not in df.columns:
        notes.append("No standard-error columns (*_se): charts carry no error bars and "
                     "'zero within error' cannot be stated.")
    if "aliasing_se" in df.columns:
        df["aliasing_zero"] = zero_within_error(df["aliasing"], df["aliasing_se"])
    else:
        df["aliasing_zero"] = False
    bad = ~np.isfinite(df["error"].to_numpy(dtype=float))
    if bad.any():
        notes.append(f"{int(bad.sum())} row(s) have a non-finite error (NaN or Inf): they are left out of "
                     "rankings and charts.")
    return df, notes


def describe_target(target):
    """The target as the CSV writes it, with the pixel-area reference named: 'box:0.5 (the pixel area)'."""
    return f"{target} (the pixel-area reference)" if str(target) in ("box:0.5", "area") else str(target)


def zero_within_error(value, se):
    """True where |value| <= 2 se (se finite and > 0 or value exactly 0): the value is zero within error."""
    value = np.asarray(value, dtype=float)
    se = np.asarray(se, dtype=float)
    with np.errstate(invalid="ignore"):
        return (value == 0) | (np.isfinite(se) & (np.abs(value) <= 2 * se))


# A slope needs this many spp levels (two points always fit a line exactly).
MIN_SLOPE_LEVELS = 3


def slope_or_none(n, y):
    """The log-log slope of y against n when at least MIN_SLOPE_LEVELS distinct n have y > 0, else None."""
    n = np.asarray(n, dtype=float)
    y = np.asarray(y, dtype=float)
    ok = np.isfinite(y) & (y > 0) & (n > 0)
    if len(np.unique(n[ok])) < MIN_SLOPE_LEVELS:
        return None
    return fit_loglog_slope(n[ok], y[ok])[0]


def fit_loglog_slope(n, y, n_min=None, n_max=None, powers_of_two_only=False):
    """Least squares of log y on log n over n_min <= n <= n_max (and y > 0).
    Returns (slope, intercept, slope_standard_error, points); raises
    ValueError with fewer than two usable points or a single distinct n.
    Same definition as fitLogLogSlope in lib/study/convergence.h."""
    n = np.asarray(n, dtype=float)
    y = np.asarray(y, dtype=float)
    keep = np.isfinite(y) & (y > 0) & (n > 0)
    if n_min is not None:
        keep &= n >= n_min
    if n_max is not None:
        keep &= n <= n_max
    if powers_of_two_only:
        with np.errstate(divide="ignore"):
            l2 = np.log2(np.where(n > 0, n, 1))
        keep &= np.abs(l2 - np.round(l2)) < 1e-9
    lx, ly = np.log(n[keep]), np.log(y[keep])
    if len(lx) < 2:
        raise ValueError("fewer than two points in the N range")
    sxx = float(np.sum((lx - lx.mean()) ** 2))
    if sxx <= 0:
        raise ValueError("every point has the same N")
    slope = float(np.sum((lx - lx.mean()) * (ly - ly.mean())) / sxx)
    intercept = float(ly.mean() - slope * lx.mean())
    se = 0.0
    if len(lx) > 2:
        rss = float(np.sum((ly - intercept - slope * lx) ** 2))
        se = math.sqrt(rss / (len(lx) - 2) / sxx)
    return slope, intercept, se, int(len(lx))


def pareto_front(x, y):
    """Indices of the points no other point beats in both x and y (both
    minimised), sorted by x. A point equal to another in both is kept once."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    order = np.lexsort((y, x))
    front, best = [], math.inf
    for i in order:
        if y[i] < best:
            front.append(int(i))
            best = y[i]
    return front


# Distinct colours for up to 14 series (tab10, then four more).
PALETTE = [plt.cm.tab10(i) for i in range(10)] + ["black", "gold", "navy", "lime"]


def colour(i):
    """The i-th series colour."""
    return PALETTE[i % len(PALETTE)]


def slug(text):
    """A file-name-safe version of a scene or method name."""
    base = os.path.splitext(os.path.basename(str(text)))[0]
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", base) or "unnamed"


def save_figure(fig, out_dir, name):
    """Writes name.png and name.svg into out_dir; returns the two paths."""
    os.makedirs(out_dir, exist_ok=True)
    paths = []
    for ext in ("png", "svg"):
        path = os.path.join(out_dir, f"{name}.{ext}")
        fig.savefig(path, dpi=120, bbox_inches="tight")
        paths.append(path)
    plt.close(fig)
    return paths


def most_common(series):
    """The most frequent value (ties broken by first appearance)."""
    counts = series.value_counts(sort=False)
    return counts.idxmax()
