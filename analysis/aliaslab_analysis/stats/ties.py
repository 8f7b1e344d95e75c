"""Ties: the group of rows not significantly worse than the best of one cell (scene, spp, target).

Rule. A row is *measured* when its error is told from zero, e > Z se (an unknown se: e > 0). Row b is
the measured row with the lowest error (mse_target) in the cell (any row when none is measured). Row i is
tied with it when  e_i - e_b <= Z se(e_i - e_b),  Z = 2 (about two standard errors of the difference), and
in the top group when tied and either measured or so accurate that even its upper bound is no higher than
the best's (e_i + Z se_i <= e_b + Z se_b). A row neither measured nor that accurate is *undetermined*:
its error is not known well enough to rank it (e.g. a filter whose weights nearly cancel: a huge error
with a huger spread); it is shown, never counted as a tie. The standard error of the difference:
  - rows of one sample set (same scene, sampler, spp, prefilter and target; they differ in filter, radius
    or reconstruction) were made from the same traced samples, so their errors move together over seeds:
    they are compared paired, se = sd_k(x_ik - x_bk) / sqrt(K) over the K per-seed values of
    mse_target_seeds (the per-seed values hold the target fixed, so this is the seeds' part only);
  - rows of different sample sets (another sampler) have independent samples:
    se = sqrt(se_i^2 + se_b^2) with se = mse_target_se (which also holds the references' error, counted
    in both: conservative, the target's error is shared by every row against it).
A pair without per-seed values is compared unpaired (conservative: the shared part is counted twice).
A difference whose se is unknown (NaN: fewer than 4 seeds) is tied only when it is 0. Rows with a
non-finite error are never in the group. Deterministic rows (the fixed grid: every seed the same image,
no standard error) are left out of the cells by the callers (rankings.py) and shown as such.
"""
import numpy as np

Z = 2.0
# The columns naming the samples a row was made from: rows equal in these share their traced samples.
SAMPLE_SET = ["scene", "sampler", "spp", "prefilter", "target"]


def sample_set_ids(rows):
    """An integer per row: equal for rows that share their samples (SAMPLE_SET; columns absent are ignored)."""
    key = [c for c in SAMPLE_SET if c in rows.columns]
    return rows.groupby(key, sort=False, dropna=False).ngroup().to_numpy()


def seed_matrix(rows):
    """(values, ok): the per-seed values as an n x K array (NaN rows where absent or of another K) and a
    boolean per row that has them."""
    n = len(rows)
    if "seed_values" not in rows.columns or n == 0:
        return np.full((n, 0), np.nan), np.zeros(n, dtype=bool)
    arrays = list(rows["seed_values"])
    lengths = [len(a) if a is not None else 0 for a in arrays]
    k = max(set(lengths), key=lengths.count) if lengths else 0
    out = np.full((n, max(k, 0)), np.nan)
    ok = np.zeros(n, dtype=bool)
    for i, a in enumerate(arrays):
        if a is not None and len(a) == k and k >= 2:
            out[i] = a
            ok[i] = True
    return out, ok


def diff_se_matrix(rows):
    """n x n standard errors of e_i - e_j (see the module doc), and an n x n boolean: the pair was paired."""
    se = rows["error_se"].to_numpy(dtype=float)
    out = np.sqrt(se[:, None] ** 2 + se[None, :] ** 2)
    paired = np.zeros(out.shape, dtype=bool)
    seeds, has = seed_matrix(rows)
    ids = sample_set_ids(rows)
    for s in np.unique(ids):
        idx = np.nonzero((ids == s) & has)[0]
        if len(idx) < 2:
            continue
        v = seeds[idx]
        d = v[:, None, :] - v[None, :, :]
        k = v.shape[1]
        out[np.ix_(idx, idx)] = d.std(axis=2, ddof=1) / np.sqrt(k)
        paired[np.ix_(idx, idx)] = True
    np.fill_diagonal(out, 0.0)
    return out, paired


def tied(gap, gap_se, z=Z):
    """gap <= z gap_se, elementwise; an unknown (NaN) se ties only a zero gap."""
    gap = np.asarray(gap, dtype=float)
    gap_se = np.asarray(gap_se, dtype=float)
    with np.errstate(invalid="ignore"):
        known = np.isfinite(gap_se)
        return np.isfinite(gap) & np.where(known, gap <= z * np.where(known, gap_se, 0.0), gap <= 0)


def measured(err, se, z=Z):
    """e > z se (an unknown se: e > 0): the error is told from zero."""
    err = np.asarray(err, dtype=float)
    se = np.asarray(se, dtype=float)
    with np.errstate(invalid="ignore"):
        return np.isfinite(err) & np.where(np.isfinite(se), err > z * np.where(np.isfinite(se), se, 0.0), err > 0)


def top_group(cell, z=Z):
    """The rows of one cell with, added: `measured`, `best` (the row b of the module doc), `gap`
    (e - e_b), `gap_se`, `gap_z`, `paired` (the comparison with b was paired), `top` (in the top group)
    and `undetermined`."""
    cell = cell.copy()
    err = cell["error"].to_numpy(dtype=float)
    own_se = cell["error_se"].to_numpy(dtype=float)
    finite = np.isfinite(err)
    meas = measured(err, own_se, z)
    for c, v in (("best", False), ("gap", np.nan), ("gap_se", np.nan), ("gap_z", np.nan), ("paired", False),
                 ("top", False), ("undetermined", False)):
        cell[c] = v
    cell["measured"] = meas
    if not finite.any():
        return cell
    pool = meas if meas.any() else finite
    b = int(np.argmin(np.where(pool, err, np.inf)))
    se, paired = diff_se_matrix(cell)
    gap = err - err[b]
    gap_se = se[b]
    with np.errstate(divide="ignore", invalid="ignore"):
        gap_z = np.where(gap_se > 0, gap / gap_se, np.where(gap > 0, np.inf, 0.0))
    cell["best"] = np.arange(len(cell)) == b
    cell["gap"] = gap
    cell["gap_se"] = gap_se
    cell["gap_z"] = gap_z
    cell["paired"] = paired[b]
    upper = err + z * np.where(np.isfinite(own_se), own_se, 0.0)
    accurate = upper <= upper[b]
    cell["top"] = tied(gap, gap_se, z) & finite & (meas | accurate)
    cell["undetermined"] = finite & ~meas & ~cell["top"].to_numpy()
    return cell


def group_names(cell, name):
    """The names (name(row)) of the cell's top group, best first."""
    g = cell[cell["top"]].sort_values("error")
    return [name(r) for _, r in g.iterrows()]

