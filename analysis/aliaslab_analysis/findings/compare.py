"""Compares two sweep CSVs (before / after a change, or two machines).

Usage: /usr/bin/python3 -m analysis compare BEFORE.csv AFTER.csv
           [--z 3] [--time-ratio 2] [--min-ms 1] [--rel-tol 1e-6] [--independent-pixels]

Configurations are matched on (scene, width, height, sampler, spp, filter,
radius, filter_params, reconstruction). For each matched pair it reports
the metrics (mse, aliasing, noise, mse_area) that changed by more than their
seed-to-seed uncertainty and the timings (trace_ms, reconstruct_ms and their
sum) whose ratio exceeds --time-ratio either way (rows where both times are
below --min-ms are ignored). Exit status: 1 when some mse got significantly
worse or is NaN / Inf in AFTER (a regression), 2 on bad input (including two CSVs without a
configuration in common), 0 otherwise.

Uncertainty. Write a pixel's error in seed k as e = b + eps, with b the
structured part (aliasing) and eps the seed-dependent part, Var eps = s^2
(noise). The mse is the mean over K = seeds independent seeds of the
per-seed mse M_k = mean_p e_pk^2, so se(mse) = sd(M_k) / sqrt(K). For
Gaussian eps, Var(e^2) = 4 b^2 s^2 + 2 s^4; if the pixels' fluctuations were
perfectly correlated (the worst case: averaging over pixels cannot reduce
them) and the error were spread evenly, sd(M_k)^2 = 4 aliasing noise +
2 noise^2. Hence
    se(mse)      = sqrt((4 max(aliasing, 0) noise + 2 noise^2) / K)
    se(noise)    = noise sqrt(2 / (K - 1))        (unbiased variance, K - 1 dof)
    se(aliasing) = sqrt(se(mse)^2 + (se(noise) / K)^2)
    se(mse_area) = se(mse) with aliasing replaced by mse_area - noise.
Independent pixels would divide these by up to sqrt(#pixels), so the rule
is conservative: it rarely cries wolf and catches changes of a few standard
errors of the worst case (with noise-dominated error and K = 8, an mse must
about triple). --independent-pixels divides every se by sqrt(P_eff),
P_eff = width height / (2 radius + 1)^2 (pixels sharing no samples); it is
far more sensitive but assumes the error is spread evenly over the image,
so edge-concentrated error can make it report changes that are noise. A difference is significant when
    |after - before| > z sqrt(se_before^2 + se_after^2) + rel_tol max(|before|, |after|);
the relative tolerance absorbs printing precision for deterministic patterns
(noise 0, se 0).
"""
import argparse
import math
import sys

import pandas as pd

from ..io import errors, study_csv

METRICS = ["mse", "aliasing", "noise", "mse_area"]
TIMES = ["trace_ms", "reconstruct_ms", "time_ms"]


def standard_errors(row, independent_pixels=False):
    """Seed-to-seed standard errors of the metrics of one row (see module doc)."""
    k = max(int(row["seeds"]), 1)
    pixels = 1.0
    if independent_pixels:
        pixels = max(1.0, float(row["width"]) * float(row["height"]) / (2 * float(row["radius"]) + 1) ** 2)
    noise = max(float(row["noise"]), 0.0)
    alias = max(float(row["aliasing"]), 0.0)
    alias_area = max(float(row["mse_area"]) - noise, 0.0)
    se_mse = math.sqrt((4 * alias * noise + 2 * noise ** 2) / k)
    se_noise = noise * math.sqrt(2 / (k - 1)) if k > 1 else noise
    se = {
        "mse": se_mse,
        "noise": se_noise,
        "aliasing": math.sqrt(se_mse ** 2 + (se_noise / k) ** 2),
        "mse_area": math.sqrt((4 * alias_area * noise + 2 * noise ** 2) / k),
    }
    return {c: v / math.sqrt(pixels) for c, v in se.items()}


def significant(before, after, se_b, se_a, z, rel_tol):
    if not (math.isfinite(before) and math.isfinite(after)):
        return not (math.isnan(before) and math.isnan(after))
    return abs(after - before) > z * math.hypot(se_b, se_a) + rel_tol * max(abs(before), abs(after))


def is_worse(before, after):
    """after is worse than before: larger, or not finite (NaN or Inf) where before was finite. A NaN
    or Inf mse is a regression (it cannot be compared, so it must not pass silently)."""
    if not math.isfinite(after):
        return math.isfinite(before) or math.isnan(after) or after != before
    return math.isfinite(before) and after > before


def unique_rows(df, path):
    dup = df.duplicated(study_csv.config_key(df), keep="last")
    if dup.any():
        print(f"note: {path}: {int(dup.sum())} repeated configuration(s); the last row of each is used",
              file=sys.stderr)
    return df[~dup]


def label(row):
    return (f"{row['scene']} {int(row['width'])}x{int(row['height'])} {row['sampler']} spp={int(row['spp'])} "
            f"{row['filter']} r={row['radius']:g}{(' ' + row['filter_params']) if row['filter_params'] else ''} "
            f"{row['reconstruction']}" + (f" target={row['target']}" if "target" in row and str(row["target"]) else ""))


def compare(before, after, z=3.0, time_ratio=2.0, min_ms=1.0, rel_tol=1e-6, independent_pixels=False):
    """Returns (metric changes, time changes, only-before keys, only-after keys) as DataFrames/lists."""
    key = study_csv.CONFIG_KEY + [c for c in ("prefilter", "target") if c in before and c in after]
    m = before.merge(after, on=key, how="outer", suffixes=("_b", "_a"), indicator=True)
    only_b = m[m["_merge"] == "left_only"]
    only_a = m[m["_merge"] == "right_only"]
    both = m[m["_merge"] == "both"]
    metric_rows, time_rows = [], []
    for _, r in both.iterrows():
        rb = {c: r[f"{c}_b"] for c in METRICS + ["seeds"]}
        ra = {c: r[f"{c}_a"] for c in METRICS + ["seeds"]}
        for d in (rb, ra):
            d.update(width=r["width"], height=r["height"], radius=r["radius"])
        se_b, se_a = standard_errors(rb, independent_pixels), standard_errors(ra, independent_pixels)
        for c in METRICS:
            b, a = float(rb[c]), float(ra[c])
            if significant(b, a, se_b[c], se_a[c], z, rel_tol) or (c == "mse" and not math.isfinite(a)):
                sigma = math.hypot(se_b[c], se_a[c])
                metric_rows.append({
                    "configuration": label(r), "metric": c, "before": b, "after": a,
                    "change": (f"{(a - b) / b:+.1%}" if b and math.isfinite(a) and math.isfinite(b)
                               else ("not finite" if not math.isfinite(a) else "new")),
                    "z": (a - b) / sigma if sigma > 0 else math.copysign(math.inf, a - b),
                    "flagged": int(r["flagged_b"] or r["flagged_a"]),
                    "regression": int(c == "mse" and is_worse(b, a) and not (r["flagged_b"] or r["flagged_a"]))})
        for c in TIMES:
            b, a = float(r[f"{c}_b"]), float(r[f"{c}_a"])
            if max(a, b) < min_ms or min(a, b) <= 0:
                continue
            if a / b > time_ratio or b / a > time_ratio:
                time_rows.append({"configuration": label(r), "timing": c, "before_ms": b, "after_ms": a,
                                  "ratio": a / b})
    return (pd.DataFrame(metric_rows), pd.DataFrame(time_rows),
            [label(r) for _, r in only_b.iterrows()], [label(r) for _, r in only_a.iterrows()])


def main(argv=None, prog=None):
    ap = argparse.ArgumentParser(prog=prog,
                                 description="Compare two aliaslab study CSVs; exit 1 on an mse regression")
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("--z", type=float, default=3.0, help="significance in standard errors (default 3)")
    ap.add_argument("--time-ratio", type=float, default=2.0, help="report timings changed by more (default 2)")
    ap.add_argument("--min-ms", type=float, default=1.0, help="ignore timings below this in both runs (ms)")
    ap.add_argument("--rel-tol", type=float, default=1e-6, help="relative tolerance added to the threshold")
    ap.add_argument("--independent-pixels", action="store_true",
                    help="divide standard errors by sqrt(width height / (2 r + 1)^2) (more sensitive)")
    args = ap.parse_args(argv)
    if args.z <= 0:
        errors.fail(f"--z: must be > 0, got {args.z}")
    if args.time_ratio <= 1:
        errors.fail(f"--time-ratio: must be > 1, got {args.time_ratio}")
    try:
        before = unique_rows(study_csv.read_study_csv(args.before), args.before)
        after = unique_rows(study_csv.read_study_csv(args.after), args.after)
    except errors.InputError as e:
        errors.fail(str(e))

    metrics, times, only_b, only_a = compare(before, after, args.z, args.time_ratio, args.min_ms, args.rel_tol,
                                             args.independent_pixels)
    matched = len(before) - len(only_b)
    if matched == 0:
        errors.fail(f"no configuration is in both {args.before} and {args.after}: they match on "
                    f"(scene, width, height, sampler, spp, filter, radius, filter_params, reconstruction); "
                    f"compare two runs of the same study (e.g. sweep --preset default before and after a change)")
    print(f"matched {matched} configuration(s); {len(only_b)} only in {args.before}, "
          f"{len(only_a)} only in {args.after}")
    for name, keys in ((args.before, only_b), (args.after, only_a)):
        for k in keys[:10]:
            print(f"  only in {name}: {k}")
        if len(keys) > 10:
            print(f"  ... and {len(keys) - 10} more")
    with pd.option_context("display.width", 200, "display.max_colwidth", 80, "display.max_rows", 500):
        if metrics.empty:
            print(f"\nno metric changed by more than {args.z:g} standard errors")
        else:
            print(f"\nmetrics changed by more than {args.z:g} standard errors (z = change / combined se):")
            print(metrics.to_string(index=False, float_format=lambda v: f"{v:.4g}"))
        if times.empty:
            print(f"\nno timing changed by more than a factor {args.time_ratio:g}")
        else:
            print(f"\ntimings changed by more than a factor {args.time_ratio:g}:")
            print(times.to_string(index=False, float_format=lambda v: f"{v:.4g}"))
    regressions = int(metrics["regression"].sum()) if not metrics.empty else 0
    if regressions:
        print(f"\nREGRESSION: mse significantly worse in {regressions} configuration(s)")
        return 1
    print("\nno significant accuracy regression")
    return 0
