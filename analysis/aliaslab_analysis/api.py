"""aliaslab's analysis as a documented API: the rules the page uses, one import away (docs/python.md).

Run from the repository root with Debian's /usr/bin/python3. A sentence of the page in three lines:

    from analysis.aliaslab_analysis import api
    df, notes = api.load_study(api.study_path("results/presented"))  # study.csv or study.csv.gz
    api.answer(df).query("scope == 'all' and verdict != 'worse'")  # the contenders at each spp

Every function here is the one the page itself calls (io, stats and findings layers; this module imports
nothing above findings, analysis/tests/test_layers.py); it adds names and docstrings, never another rule.
The rules, in short (docs/science.md has the mathematics):
  - error: mse_target, the error against the study's target, with its standard error error_se;
  - tie group (tie_group): the rows of one (target, scene, spp) cell whose error is within Z = 2 standard errors
    of the difference of the cell's best (paired over seeds where two rows share their samples);
  - equivalence (answer, per_scene, across, verdict): each row's ratio R = e / e_best with its 95 % interval;
    equivalent when the interval's upper end is below 1 + margin (MARGIN = 0.10), worse when its lower end is
    above it, undetermined otherwise; heavy-tailed rows are never equivalent; across scenes, the median ratio
    with a bootstrap interval over scenes, equivalent only when equivalent in at least half the scenes;
  - fronts (fronts, pareto): the rows no other row beats on both error and cost;
  - decomposition (decomposition_residuals): mse_target = noise + aliasing + blur + cross = mse + blur + cross.
"""
import os

import numpy as np

from .findings import study as _study
from .io import study_csv as _study_csv
from .io import study_rows as _study_rows
from .stats import effect as _effect
from .stats import equivalence as _equivalence
from .stats import fronts as _fronts
from .stats import ties as _ties
from .stats.rankings import CELL, METHOD, method_label

MARGIN = _effect.MARGIN  # the margin of practical equivalence (0.10: within 10 % of the best)
Z = _ties.Z  # standard errors of a difference within which two errors are tied (2)
EQUIVALENT, WORSE, UNDETERMINED = _effect.EQUIVALENT, _effect.WORSE, _effect.UNDETERMINED
ALL = _equivalence.ALL  # the scope of an across-scene record in answer()

__all__ = ["ALL", "CELL", "EQUIVALENT", "MARGIN", "METHOD", "UNDETERMINED", "WORSE", "Z", "across", "answer",
           "decomposition_residuals", "fronts", "load_study", "method_label", "pareto", "per_scene", "study",
           "study_path", "targets", "tie_group", "tied", "verdict"]


def study_path(folder):
    """The study CSV of a folder: study.csv, else study.csv.gz (a committed study may be either)."""
    for name in ("study.csv", "study.csv.gz"):
        if os.path.exists(os.path.join(folder, name)):
            return os.path.join(folder, name)
    return os.path.join(folder, "study.csv")


def load_study(path):
    """Reads a sweep's study CSV: (DataFrame, notes). One row per configuration; `error` = mse_target and
    `error_se` its standard error; the CSV's `filter` column is named `filter_name`; notes list each fallback
    taken for older CSVs. Raises io.errors.InputError naming the file and line for a bad CSV."""
    return _study_csv.load_study(path)


def targets(df):
    """The study's targets (reference filters the error is measured against), the primary one first."""
    return _study_rows.targets(df)


def study(df, notes=(), margin=MARGIN):
    """Everything the page's findings share, computed once (findings.study.Study): .ranked (per_scene),
    .summary (across), .answer (answer.csv), .leaders, .picks, .scenes, .levels (spp), .primary (target)."""
    return _study.Study(df, list(notes), margin)


def per_scene(df, margin=MARGIN):
    """Every row with a finite error, compared with its cell's best (target, scene, spp): columns ratio,
    ci_low, ci_high (95 %), interval (log / bootstrap / linear / best), heavy_tailed, best and verdict."""
    return _equivalence.per_scene(df, margin)


def across(per, margin=MARGIN):
    """Per (target, spp, method), from per_scene(): scenes, equivalent / worse / undetermined / heavy counts,
    median_ratio over the scenes with its bootstrap interval (ci_low, ci_high) and the across-scene verdict."""
    return _equivalence.across(per, margin)


def answer(df, margin=MARGIN):
    """results/answer.csv recomputed from the rows: per target x spp x scope (each scene, then "all") x method,
    ratio to the best, ci_low, ci_high, verdict, margin, equivalent_scenes (stats/equivalence.table)."""
    per = per_scene(df, margin)
    return _equivalence.table(per, across(per, margin), margin)


def verdict(low, high, margin=MARGIN, heavy=False):
    """The verdict of a ratio interval [low, high]: 'equivalent' when high < 1 + margin (and not heavy),
    'worse' when low > 1 + margin, else 'undetermined'."""
    return _effect.verdict(low, high, margin, heavy)


def tied(gap, gap_se, z=Z):
    """True where an error difference `gap` is within z standard errors `gap_se` (elementwise)."""
    return _ties.tied(gap, gap_se, z)


def tie_group(df, target, scene, spp, z=Z):
    """The rows of cell (target, scene, spp), random ones only (the deterministic grid has no seed spread and is
    shown apart), with the tie rule's columns: best, gap (e - e_best), gap_se, gap_z, paired, measured,
    top (in the tie group) and undetermined; sorted by error. The page says "tied" for every `top` row."""
    cell = df[(df["target"].astype(str) == str(target)) & (df["scene"] == scene) & (df["spp"] == spp)]
    if "deterministic" in cell.columns:
        cell = cell[~cell["deterministic"].astype(bool)]
    return _ties.top_group(cell, z).sort_values("error")


def pareto(err, cost):
    """A boolean per point: on the strict front of error against cost (no other point at most as high in both
    and lower in one); points with a non-finite value are off it."""
    return _fronts.pareto(np.asarray(err, dtype=float), np.asarray(cost, dtype=float))


def fronts(rows):
    """The front rows of every (target, scene) of `rows` on (error, cost), sorted by cost, with front_rank."""
    return _fronts.fronts(rows)


def decomposition_residuals(df):
    """Per row, how far the two identities of the decomposition are from holding (rounding only when they
    hold): a DataFrame with `terms` = mse_target - (noise + aliasing + blur + cross) and
    `mse` = mse_target - (mse + blur + cross), both relative to mse_target. Needs the blur and cross columns."""
    t = df["mse_target"].to_numpy(dtype=float)
    parts = df["noise"].to_numpy(dtype=float) + df["aliasing"].to_numpy(dtype=float)
    tail = df["blur"].to_numpy(dtype=float) + df["cross"].to_numpy(dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = df[CELL + METHOD].copy()
        out["terms"] = (t - (parts + tail)) / np.abs(t)
        out["mse"] = (t - (df["mse"].to_numpy(dtype=float) + tail)) / np.abs(t)
    return out
