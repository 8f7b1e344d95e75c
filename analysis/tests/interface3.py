"""Development and test data only (never presented as data): converts a study CSV of today's sweep into the
shape of the study CSV's Interface 3, with plausible invented values for the new columns.

convert(src, dst) writes, for every configuration of src:
  - three rows, targets box:0.5 (mse_target as in src), gaussian:1.5 and lanczos:3 (mse_target plus an
    invented blur that grows with the mismatch of the row's filter width and the target's);
  - mse_target_seeds: K values with mean mse_target and sd / sqrt(K) = mse_target_se, correlated between
    the rows of one sample set (a shared per-seed part, RHO) as a real sweep's are;
  - deterministic (1 for the fixed grid `uniform`), and a `uniform-shifted` copy of every uniform row with a
    seed-to-seed spread (its structured error varies with the offset);
  - cpu_ms = 0.9 time_ms, cpu_ms_se = 3 % of it; target_ref_error, blur_se, the *_own columns;
  - flagged by Interface 3's rule, mse_target < 2 mse_target_se.
Run: /usr/bin/python3 -m analysis.tests.interface3 SRC.csv DST.csv
"""
import sys

import numpy as np
import pandas as pd

TARGETS = {"box:0.5": 0.5, "gaussian:1.5": 0.75, "lanczos:3": 0.6}
RHO = 0.8
WIDTH = {"box": 1.0, "tent": 0.7, "gaussian": 0.6, "mitchell": 0.7, "lanczos": 0.6, "catmullrom": 0.65,
         "hann": 0.6, "blackmanharris": 0.55}


def seed_values(rng, mean, se, k, shared):
    """k values with exactly the given mean and sd / sqrt(k) = se; `shared` (k,) is the sample set's part."""
    own = rng.standard_normal(k)
    z = RHO * shared + np.sqrt(1 - RHO ** 2) * own
    z = z - z.mean()
    sd = z.std(ddof=1)
    z = z / sd if sd > 0 else z
    return mean + z * se * np.sqrt(k)


def convert(src, dst, seed=29):
    df = pd.read_csv(src, keep_default_na=False, na_values=["nan", "-nan"])
    rng = np.random.default_rng(seed)
    if "prefilter" not in df.columns:
        df["prefilter"] = "none"
    shifted = df[df["sampler"] == "uniform"].copy()
    shifted["sampler"] = "uniform-shifted"
    shifted["noise"] = shifted["mse"] * 0.4
    shifted["mse_target_se"] = shifted["mse_target"] * 0.08
    df = pd.concat([df, shifted], ignore_index=True)
    k = int(df["seeds"].iloc[0])
    out = []
    for target, width in TARGETS.items():
        t = df.copy()
        t["target"] = target
        eff = t["filter"].map(WIDTH).fillna(0.7) * t["radius"]
        extra = 0.0 if target == "box:0.5" else 0.02 * (eff - width) ** 2 * t.groupby("scene")["mse_target"].transform("median") * 50
        t["mse_target"] = t["mse_target"] + extra
        t["blur"] = t["blur"] + extra
        t["blur_se"] = t["blur"] * 0.05
        t["target_ref_error"] = t["ref_error"] * (1.0 if target == "box:0.5" else 1.3)
        out.append(t)
    df = pd.concat(out, ignore_index=True)
    det = df["sampler"] == "uniform"
    df["deterministic"] = det.astype(int)
    df.loc[det, "mse_target_se"] = 0.0
    seeds = []
    shared = {}
    for _, r in df.iterrows():
        key = (r["scene"], r["sampler"], r["spp"], r["prefilter"], r["target"])
        if key not in shared:
            shared[key] = rng.standard_normal(k)
        if r["deterministic"]:
            seeds.append(";".join([f"{r['mse_target']:.9g}"] * k))
        else:
            v = seed_values(rng, r["mse_target"], r["mse_target_se"], k, shared[key])
            seeds.append(";".join(f"{x:.9g}" for x in v))
    df["mse_target_seeds"] = seeds
    time = df["trace_ms"] + df["reconstruct_ms"]
    df["cpu_ms"] = 0.9 * time
    df["cpu_ms_se"] = 0.03 * df["cpu_ms"]
    df["blurred_mse_own"] = df["blurred_mse"]
    df["lowfreq_error_own"] = df["lowfreq_error"]
    df["lowfreq_error_own_se"] = df["lowfreq_error_se"]
    df["flagged"] = ((df["mse_target"] < 2 * df["mse_target_se"]) & ~det).astype(int)
    df.to_csv(dst, index=False)
    return dst


if __name__ == "__main__":
    convert(sys.argv[1], sys.argv[2])
