"""--tables: Markdown for results/README.md (the front of every scene by the error against the
primary target (stats/fronts.py), the stability counts and the convergence verdicts)."""
import os

import numpy as np
import pandas as pd

from ..io import study_csv, study_rows
from ..stats import fronts
from .markdown import markdown


def tables(results, study):
    out = []
    if study:
        df, notes = study_csv.load_study(study)
        out += [f"_{n}_\n" for n in notes]
        primary = study_rows.targets(df)[0]
        df = df[df["target"].astype(str) == primary]
        for scene, sd in df.groupby("scene", sort=True):
            ok = sd[np.isfinite(sd["error"])].reset_index(drop=True)
            front = ok[fronts.front_mask(ok)].sort_values(["cost", "error"])
            out.append(f"### Front (error against `{primary}`; no point beats one of these in both error and time): {scene}\n")
            out.append(markdown(front[["sampler", "spp", "filter_name", "radius", "reconstruction", "cost",
                                       "error", "error_se", "flagged"]].rename(columns={"filter_name": "filter",
                                                                                        "cost": "time_ms"})))
            out.append("")
        cols = ["undefined_pixels", "negative_pixels", "nan_pixels", "flagged"]
        bad = df.groupby(["filter_name", "radius", "reconstruction"])[cols].sum().reset_index()
        bad = bad[(bad[cols] > 0).any(axis=1)].rename(columns={"filter_name": "filter"})
        out.append("### Stability (counts summed over scenes, samplers and spp)\n")
        out.append(markdown(bad) if len(bad) else "No undefined, negative or NaN pixels and no flagged rows.")
        out.append("")
    slopes = os.path.join(results, "convergence", "slopes.md")
    if os.path.isfile(slopes):
        with open(slopes, encoding="utf-8") as f:
            rows = [l for l in f if l.startswith("| ") and not l.startswith("| sampler")]
        verdicts = pd.Series([l.strip().strip("|").split("|")[-1].strip() for l in rows]).value_counts()
        out.append("### Convergence slopes against theory\n")
        out.append(", ".join(f"{k}: {v}" for k, v in verdicts.items()) + " (details: convergence/slopes.md)")
    print("\n".join(out))
