"""The columns that load_study adds to a study's rows, with the fallbacks for older CSVs, and
the study's targets in their order.

  deterministic  the CSV's column (1: every seed gave the same image, the fixed grid), else inferred:
                 noise 0 and a standard error of at most 1e-12 of the error (older CSVs wrote ~1e-19)
  cost, cost_se  cpu_ms and sqrt(cpu_ms_se^2 + (COST_FLOOR cpu_ms)^2): the thread CPU time, its spread
                 over seeds and a floor for what the seeds do not see, the spread between runs of the same
                 configuration (COST_FLOOR = 0.15 of cpu_ms, measured: results/study_speed.md "Thread CPU
                 time per configuration"); else the wall time time_ms with an unknown spread (NaN): time
                 differences are then compared as exact numbers
  seed_values    mse_target_seeds as float arrays (None where absent): paired comparisons within a sample
                 set (stats/ties.py); without them those comparisons are unpaired (conservative)
targets(df) lists the targets, the primary first: box:0.5 (the pixel area) when present, else the CSV's
first.
"""
import numpy as np


PRIMARY_TARGET = "box:0.5"
# The run-to-run spread of cpu_ms per configuration, relative (module doc).
COST_FLOOR = 0.15


def add_columns(df, notes):
    """Adds deterministic, cost, cost_se and seed_values to df (in place); appends the fallbacks to notes."""
    if "deterministic" in df.columns:
        df["deterministic"] = df["deterministic"].fillna(0).astype(float) != 0
    else:
        se = df["error_se"].to_numpy(dtype=float)
        err = np.abs(df["error"].to_numpy(dtype=float))
        with np.errstate(invalid="ignore"):
            det = (df["noise"].to_numpy(dtype=float) == 0) & np.isfinite(se) & (se <= 1e-12 * np.maximum(err, 1e-300))
        df["deterministic"] = det
        if det.any():
            names = ", ".join(sorted(df.loc[det, "sampler"].unique()))
            notes.append(f"No deterministic column: {int(det.sum())} row(s) with noise 0 and a standard error of "
                         f"about 0 ({names}) are taken as deterministic (the same image for every seed).")
    if "cpu_ms" in df.columns:
        df["cost"] = df["cpu_ms"]
        seed_se = df["cpu_ms_se"].to_numpy(dtype=float) if "cpu_ms_se" in df.columns else np.zeros(len(df))
        df["cost_se"] = np.hypot(np.nan_to_num(seed_se), COST_FLOOR * df["cpu_ms"].to_numpy(dtype=float))
    else:
        df["cost"] = df["time_ms"]
        df["cost_se"] = np.nan
        notes.append("No cpu_ms column: time is the wall time (trace_ms + reconstruct_ms) without a measured "
                     "spread, so time differences are compared as exact numbers and can reorder with the load.")
    if "mse_target_seeds" in df.columns:
        df["seed_values"] = [parse_seeds(t) for t in df["mse_target_seeds"]]
    else:
        df["seed_values"] = None
        notes.append("No mse_target_seeds column: rows of one sampler (which share their samples) are compared "
                     "as if independent, a conservative test that finds more ties.")


def targets(df):
    """The study's targets, the primary first (module doc)."""
    seen = [str(t) for t in dict.fromkeys(df["target"].astype(str))]
    if PRIMARY_TARGET in seen:
        seen.remove(PRIMARY_TARGET)
        seen.insert(0, PRIMARY_TARGET)
    return seen


def parse_seeds(text):
    """The per-seed values of mse_target_seeds ('a;b;c') as a float array, or None when empty/unreadable."""
    if text is None or (isinstance(text, float) and np.isnan(text)):
        return None
    parts = [p for p in str(text).strip().split(";") if p.strip() != ""]
    if len(parts) < 2:
        return None
    try:
        return np.array([float(p) for p in parts])
    except ValueError:
        return None


def components(df):
    """The decomposition's terms present in df, in drawing order: [(column, label)]."""
    if "blur" in df.columns and "cross" in df.columns:
        return [("noise", "noise"), ("aliasing", "aliasing"), ("blur", "blur"), ("cross", "cross term")]
    return [("noise", "noise"), ("aliasing", "aliasing"), ("blur_cross", "blur + cross (mse_area - mse)")]
