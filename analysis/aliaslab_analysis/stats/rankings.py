"""Rankings with ties: the top group of every (target, scene, spp) cell and, per method, its record across
scenes.

cells(df) applies ties.top_group to every cell of the rows that can be ranked: a finite error and not
deterministic (the fixed grid has no standard error: its error is one alignment's luck; the shifted grid
`uniform-shifted` ranks in its place). Deterministic rows come back too, with their ratio, never in a top
group (`top` False), so that charts can show them as such. Flagged rows (error not told from zero given the references' and
the seeds' error) stay in: they are among the most accurate, and dropping them would bias every count.
Each row's `ratio` = error / the cell's reference error, the lowest error of a measured, unflagged row
(ties.py: error told from zero; a smaller error is too uncertain to divide by); NaN when the cell has none.

across_scenes(ranked) gives per (target, spp, method): `scenes` (scenes where the method has a ratio),
`in_top` (scenes where it is in the top group), `flagged` (scenes where its row is flagged),
`undetermined` (scenes where its error is not known well enough to rank, ties.py), the median
ratio over those scenes and its seeded bootstrap interval (bootstrap.py).

answer(summary) names, per (target, spp), the methods in the top group in at least half of the scenes
(the majority rule), or, when none reaches that, those with the most scenes in the top group.
"""
import numpy as np
import pandas as pd

from . import bootstrap, ties

METHOD = ["sampler", "filter_name", "radius", "filter_params", "reconstruction", "prefilter"]
CELL = ["target", "scene", "spp"]


def rankable(df):
    """Rows with a finite error that are not deterministic."""
    err = df["error"].to_numpy(dtype=float)
    det = df["deterministic"].to_numpy(dtype=bool) if "deterministic" in df.columns else np.zeros(len(df), bool)
    return df[np.isfinite(err) & ~det]


def deterministic(df):
    return df["deterministic"].to_numpy(dtype=bool) if "deterministic" in df.columns else np.zeros(len(df), bool)


def cells(df, z=ties.Z):
    """Every row with a finite error, with the columns of ties.top_group and `ratio` (module doc)."""
    ok = rankable(df)
    fixed = df[np.isfinite(df["error"].to_numpy(dtype=float)) & deterministic(df)]
    fixed_cells = dict(iter(fixed.groupby(CELL, sort=True))) if len(fixed) else {}
    parts = []
    for key, cell in ok.groupby(CELL, sort=True):
        g = ties.top_group(cell, z)
        err = g["error"].to_numpy(dtype=float)
        ref = err[(g["flagged"].to_numpy() == 0) & g["measured"].to_numpy() & (err > 0)]
        base = ref.min() if len(ref) else np.nan
        g["ratio"] = err / base
        parts.append(g)
        if key in fixed_cells:
            f = fixed_cells[key]
            parts.append(f.assign(best=False, gap=f["error"] - err[g["best"].to_numpy()][0], gap_se=np.nan,
                                  gap_z=np.nan, paired=False, top=False, undetermined=False, measured=True,
                                  ratio=f["error"] / base))
    if not parts:
        return ok.assign(best=False, gap=np.nan, gap_se=np.nan, gap_z=np.nan, paired=False, top=False,
                         measured=False, undetermined=False, ratio=np.nan)
    return pd.concat(parts)


def across_scenes(ranked, seed=bootstrap.SEED, n_boot=bootstrap.N_BOOT):
    """Per (target, spp, method): scenes, in_top, flagged, median_ratio, ci_low, ci_high (module doc)."""
    out = []
    for key, g in ranked.groupby(["target", "spp"] + METHOD, sort=True, dropna=False):
        r = g["ratio"].to_numpy(dtype=float)
        fin = np.isfinite(r)
        lo, hi = bootstrap.interval(r[fin], seed, n_boot)
        out.append(dict(zip(["target", "spp"] + METHOD, key), scenes=int(fin.sum()), in_top=int(g["top"].sum()),
                        deterministic=bool(deterministic(g).any()),
                        flagged=int((g["flagged"] == 1).sum()), undetermined=int(g["undetermined"].sum()),
                        median_ratio=float(np.median(r[fin])) if fin.any() else np.nan, ci_low=lo, ci_high=hi))
    cols = ["target", "spp"] + METHOD + ["deterministic", "scenes", "in_top", "flagged", "undetermined", "median_ratio", "ci_low",
                                         "ci_high"]
    table = pd.DataFrame(out, columns=cols)
    return table.sort_values(["target", "spp", "in_top", "median_ratio"], ascending=[True, True, False, True],
                             kind="stable").reset_index(drop=True)


def answer(summary, scenes_in_study):
    """Per (target, spp): the methods of the answer (module doc), as a dict {(target, spp): DataFrame}."""
    out = {}
    for (target, spp), g in summary[~summary["deterministic"].astype(bool)].groupby(["target", "spp"], sort=True):
        need = (scenes_in_study + 1) // 2
        pick = g[g["in_top"] >= need]
        if pick.empty:
            pick = g[g["in_top"] == g["in_top"].max()]
        out[(target, int(spp))] = pick.sort_values(["in_top", "median_ratio"], ascending=[False, True])
    return out


def majority(scenes_in_study):
    """The number of scenes in the top group that puts a method in the answer."""
    return (scenes_in_study + 1) // 2
