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
    text = {"scene", "sampler", "filter", "filter_params", "reconstruction"}
    for c in STUDY_COLUMNS:
        if c in text:
            continue
        raw = df[c].astype(str).str.strip()
        converted = pd.to_numeric(raw, errors="coerce")
        bad = converted.isna() & ~raw.str.lower().isin(["nan", "-nan", ""])
        if bad.any():
            line = int(bad.to_numpy().nonzero()[0][0]) + 2
            raise InputError(f"{path}: line {line}: column {c}: not a number: {raw[bad].iloc[0]!r}")
        df[c] = converted
    df["time_ms"] = df["trace_ms"] + df["reconstruct_ms"]
    return df


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
