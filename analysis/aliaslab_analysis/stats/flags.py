"""Why a flagged row is flagged. The sweep flags a row when its error against the target cannot be told
from zero at two standard errors (mse_target < 2 mse_target_se, docs/science.md). That happens for two
opposite reasons, and the page names them apart:

  reference-limited  the raw error (mse_target + target_ref_error, before the target reference's variance
                     is subtracted) is at most REF_LIMIT times that variance: what is measured could be the
                     reference's own error, so the method is at least as accurate as the reference can tell;
  unstable           the raw error is more than REF_LIMIT times the reference's: the error is certainly
                     positive, but its spread over the seeds is as large as its mean. These are heavy-tailed
                     estimators (a few seeds carry most of the error), typically filters with negative lobes
                     at small radii whose weight sums come near zero: large, erratic errors, not small ones.

kinds(df) returns one label per row: "" (not flagged), "reference-limited" or "unstable". A CSV without
target_ref_error (older studies) uses ref_error, the own reference's variance, in its place.
"""
import numpy as np

REF_LIMIT = 10.0
REFERENCE_LIMITED = "reference-limited"
UNSTABLE = "unstable"


def kinds(df):
    """One label per row of df (module doc)."""
    flagged = df["flagged"].to_numpy(dtype=float) == 1
    err = df["mse_target"] if "mse_target" in df.columns else df["mse_area"]
    err = err.to_numpy(dtype=float)
    col = "target_ref_error" if "target_ref_error" in df.columns else "ref_error"
    ref = np.nan_to_num(df[col].to_numpy(dtype=float), nan=0.0) if col in df.columns else np.zeros(len(df))
    with np.errstate(invalid="ignore"):
        limited = flagged & (err + ref <= REF_LIMIT * ref)
    out = np.full(len(df), "", dtype=object)
    out[limited] = REFERENCE_LIMITED
    out[flagged & ~limited] = UNSTABLE
    return out
