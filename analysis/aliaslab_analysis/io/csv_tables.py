"""Reading the experiments' small CSVs (convergence, filter profiles, point sets), checked.

Every column asked for must be present, there must be data rows and numeric columns must hold numbers;
the error names the file, line and column.
"""
import os

import pandas as pd

from .errors import InputError, fail


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
