"""Reading a study CSV (the sweep's output, lib/study/records/csv.h) for analysis: load_study.

load_study(path) -> (DataFrame, notes) is the one entry: columns checked, numbers converted, one row per
configuration (a repeated configuration is refused), well-named columns added (`error`, the error against
the common target every ranking uses, and the others listed in its doc), and the fallbacks taken for
older CSVs listed in words. read_study_csv is the plain checked read (compare uses it). A study CSV may be
gzipped (study.csv.gz): read the same (io/text_file.py).
"""
import io
import os

import numpy as np
import pandas as pd

from . import study_rows, text_file
from .errors import InputError

# The sweep CSV's columns, in order (lib/study/records/csv.h).
STUDY_COLUMNS = [
    "scene", "width", "height", "sampler", "spp", "filter", "radius", "filter_params",
    "reconstruction", "seeds", "mse", "aliasing", "noise", "mse_area", "psnr", "ref_spp",
    "ref_error", "flagged", "nan_pixels", "negative_pixels", "undefined_pixels", "trace_ms",
    "reconstruct_ms", "threads",
]
# Columns that identify one configuration (compare matches on them).
CONFIG_KEY = ["scene", "width", "height", "sampler", "spp", "filter", "radius", "filter_params",
              "reconstruction"]
# Columns added later (coord/COLUMNS.md); any may be absent from an older CSV.
# Text columns; `prefilter` is part of the configuration key when present.
OPTIONAL_TEXT = ["target", "prefilter", "mse_target_seeds", "align_mse_target_offsets"]
OPTIONAL_NUMERIC = ["mse_target", "blur", "cross", "mse_se", "noise_se", "aliasing_se", "mse_target_se",
                    "flip", "lowfreq_error", "lowfreq_error_se", "blurred_mse", "mean_spp", "max_spp",
                    # one row per (configuration, target)
                    "target_ref_error", "blur_se", "deterministic", "blurred_mse_own", "lowfreq_error_own",
                    "lowfreq_error_own_se", "cpu_ms", "cpu_ms_se",
                    # the blur curve (the error left after a Gaussian blur of sigma 0.5, 1, 2, 4 px)
                    "blur_ratio_0.5", "blur_ratio_0.5_se", "blur_ratio_1", "blur_ratio_1_se", "blur_ratio_2",
                    "blur_ratio_2_se", "blur_ratio_4", "blur_ratio_4_se",
                    # NaN / infinite samples left out of the images (absent: unknown)
                    "nonfinite_samples",
                    # the filter's natural radius; the fixed grid's error over K sub-pixel camera
                    # offsets (references moved with the camera), on the fixed grid's rows only
                    "natural_radius", "align_offsets", "align_mse_target", "align_mse_target_sd",
                    "align_mse_target_se"]
# A study with frames (sweep --frames F > 1; lib/study/records/csv.h, docs/science.md "Motion") adds these after the
# still columns, all of them required once `frames` is there; frames and the motion are finite and one per CSV.
MOTION_COLUMNS = ["frames", "motion_dx", "motion_dy", "shimmer", "shimmer_se", "flicker_same", "flicker_same_se",
                  "flicker_new", "flicker_new_se", "target_shimmer"]
MOTION_KEY = ["frames", "motion_dx", "motion_dy"]
# Key and count columns, which must be finite; values beyond ABSURD in any other numeric column are
# beyond what float images can give (their squared differences stay below about 1e77): such a value is
# treated as unknown (NaN) with a note, so charts and rankings leave it out instead of overflowing.
FINITE_COLUMNS = ["width", "height", "spp", "radius", "seeds", "ref_spp"]
ABSURD = 1e30
TEXT_COLUMNS = {"scene", "sampler", "filter", "filter_params", "reconstruction", "target", "prefilter",
                "mse_target_seeds", "align_mse_target_offsets"}



def read_study_csv(path):
    """Reads a sweep CSV, checking its columns and that it has data rows; returns a DataFrame with
    `time_ms` = trace_ms + reconstruct_ms added. Raises InputError."""
    if os.path.isdir(path):
        raise InputError(f"{path}: is a folder, not a study CSV")
    if not os.path.exists(path):
        raise InputError(f"{path}: no such file")
    if not os.path.isfile(path):
        raise InputError(f"{path}: not a regular file (a FIFO or device?): a study CSV is read from a file")
    text = check_lines(path)
    try:
        df = pd.read_csv(io.StringIO(text), dtype=str, keep_default_na=False)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as e:
        raise InputError(f"{path}: not a readable CSV: {e}") from e
    missing = [c for c in STUDY_COLUMNS if c not in df.columns]
    if missing:
        raise InputError(f"{path}: line 1: missing column(s) {', '.join(missing)}")
    if df.empty:
        raise InputError(f"{path}: no data rows")
    motion = MOTION_COLUMNS if "frames" in df.columns else []
    missing = [c for c in motion if c not in df.columns]
    if missing:
        raise InputError(f"{path}: line 1: a study with frames (column frames) without the motion column(s) "
                         f"{', '.join(missing)}: written by another version of the sweep? Rerun it")
    for c in STUDY_COLUMNS + [c for c in OPTIONAL_NUMERIC if c in df.columns] + motion:
        if c in TEXT_COLUMNS:
            continue
        raw = df[c].astype(str).str.strip()
        converted = pd.to_numeric(raw, errors="coerce")
        empty = raw == ""
        if empty.any() and c in STUDY_COLUMNS:
            line = int(empty.to_numpy().nonzero()[0][0]) + 2
            raise InputError(f"{path}: line {line}: column {c} is empty (a cut or damaged row)")
        bad = converted.isna() & ~raw.str.lower().isin(["nan", "-nan", "+nan", ""])
        if bad.any():
            line = int(bad.to_numpy().nonzero()[0][0]) + 2
            raise InputError(f"{path}: line {line}: column {c}: not a number: {raw[bad].iloc[0]!r}")
        df[c] = converted
    for c in FINITE_COLUMNS:
        bad = ~np.isfinite(df[c].to_numpy(dtype=float)) | (df[c].to_numpy(dtype=float) < 0)
        if bad.any():
            line = int(bad.nonzero()[0][0]) + 2
            raise InputError(f"{path}: line {line}: column {c}: {df[c].iloc[line - 2]!r} is not a finite number >= 0")
    if motion:
        check_motion(df, path)
    df["time_ms"] = df["trace_ms"] + df["reconstruct_ms"]
    return df


def check_motion(df, path):
    """Raises InputError naming the line when a study with frames has a non-finite or fractional frame count, a
    non-finite motion, or a second (frames, motion): one CSV holds one motion (the sweep refuses to mix them)."""
    for c in MOTION_KEY:
        v = df[c].to_numpy(dtype=float)
        bad = ~np.isfinite(v) | ((v < 1) | (v != np.round(v)) if c == "frames" else False)
        if np.any(bad):
            line = int(np.nonzero(bad)[0][0]) + 2
            raise InputError(f"{path}: line {line}: column {c}: {df[c].iloc[line - 2]!r} is not "
                             + ("a whole number of frames >= 1" if c == "frames" else "a finite motion in pixels per frame"))
    first = df[MOTION_KEY].iloc[0]
    other = ~(df[MOTION_KEY] == first).all(axis=1)
    if other.any():
        i = int(np.nonzero(other.to_numpy())[0][0])
        r = df[MOTION_KEY].iloc[i]
        raise InputError(f"{path}: line {i + 2}: {int(r['frames'])} frames of motion ({r['motion_dx']:g}, "
                         f"{r['motion_dy']:g}), line 2 {int(first['frames'])} frames of ({first['motion_dx']:g}, "
                         f"{first['motion_dy']:g}): a study CSV holds one motion")


def check_lines(path):
    """Raises InputError naming the line when the CSV's last line is cut (no newline at its end, as a
    killed sweep leaves it; or a gzipped CSV's last member cut short) or a row has another number of fields
    than the header. Returns the CSV's text (decompressed when gzipped: io/text_file.py)."""
    import csv
    text = text_file.read_text(path)
    if not text:
        raise InputError(f"{path}: is empty (0 bytes)")
    rows = list(csv.reader(io.StringIO(text)))
    if not text.endswith("\n"):
        raise InputError(f"{path}: line {len(rows)}: cut (no newline at the end of the file): the sweep that "
                         "wrote it was interrupted; rerun it to finish the study")
    width = len(rows[0])
    for i, r in enumerate(rows[1:], start=2):
        if r and len(r) != width:
            raise InputError(f"{path}: line {i}: has {len(r)} fields, the header {width} (a cut or damaged row)")
    return text


def absurd_values(df, path):
    """Sets values beyond ABSURD (or non-finite) in the measured columns to NaN and returns notes that say
    where; leaves the key and count columns (FINITE_COLUMNS, checked by read_study_csv) alone."""
    notes = []
    skip = set(FINITE_COLUMNS) | {"time_ms"}
    measured = [c for c in df.columns if c not in TEXT_COLUMNS and c not in skip
                and pd.api.types.is_numeric_dtype(df[c])]
    found = {}
    for c in measured:
        v = df[c].to_numpy(dtype=float)
        with np.errstate(invalid="ignore"):
            huge = np.isfinite(v) & (np.abs(v) > ABSURD)
        if huge.any():
            found[c] = (int(huge.sum()), int(huge.nonzero()[0][0]) + 2)
            df.loc[huge, c] = np.nan
    if found:
        where = ", ".join(f"{c} ({n}, first on line {line})" for c, (n, line) in found.items())
        notes.append(f"{path}: values beyond {ABSURD:g} (more than float images can give) are treated as "
                     f"unknown and left out of rankings and charts: {where}.")
    if "time_ms" in df.columns:
        df["time_ms"] = df["trace_ms"] + df["reconstruct_ms"]
    return notes


def config_key(df):
    """The columns that identify one row in df: CONFIG_KEY, plus `prefilter` and `target` when present
    (under either spelling of the filter column; a study with several targets has a row per target)."""
    key = [("filter_name" if c == "filter" and "filter" not in df.columns else c) for c in CONFIG_KEY]
    return key + [c for c in ("prefilter", "target") if c in df.columns]


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
        0 (needs aliasing_se; False when unknown);
      - the columns study_rows.add_columns adds: `deterministic`, `cost`,
        `cost_se` and `seed_values`, with their fallbacks for older CSVs.
    `notes` lists, in words, each fallback taken, for the report and charts to show.
    """
    df = read_study_csv(path)
    check_unique(df, path)
    notes = absurd_values(df, path)
    if "nonfinite_samples" not in df.columns:  # an older sweep: unknown (NaN), like the other added columns
        df["nonfinite_samples"] = np.nan
    else:
        dropped = df["nonfinite_samples"].fillna(0).to_numpy(dtype=float)
        if (dropped > 0).any():
            notes.append(f"{int((dropped > 0).sum())} row(s) left NaN or infinite samples out of their images "
                         f"({int(dropped.sum())} samples in all, column nonfinite_samples): their errors miss "
                         "that light.")
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
    study_rows.add_columns(df, notes)
    return df, notes


def require_finite_errors(df, path):
    """Raises InputError when no row of a loaded study has a finite error (every one NaN, infinite or
    beyond ABSURD): there is nothing to rank, so a report of findings cannot be made (the charts can:
    they draw empty panels)."""
    if not np.isfinite(df["error"].to_numpy(dtype=float)).any():
        raise InputError(f"{path}: no row has a finite error (every one is NaN, infinite or beyond {ABSURD:g}): "
                         "nothing to rank, so no report of findings can be made")


def describe_target(target):
    """The target as the CSV writes it, with the pixel-area reference named: 'box:0.5 (the pixel area)'."""
    return f"{target} (the pixel-area reference)" if str(target) in ("box:0.5", "area") else str(target)


def zero_within_error(value, se):
    """True where |value| <= 2 se (se finite and > 0 or value exactly 0): the value is zero within error."""
    value = np.asarray(value, dtype=float)
    se = np.asarray(se, dtype=float)
    with np.errstate(invalid="ignore"):
        return (value == 0) | (np.isfinite(se) & (np.abs(value) <= 2 * se))
