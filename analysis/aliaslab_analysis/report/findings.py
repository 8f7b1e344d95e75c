"""The page's findings: the generated findings (the findings package: every number from the CSV, each
recomputed by the tests) as HTML paragraphs, plus the pre-filtering comparison when the study has it, and
the page's statement of the tie rules."""
import html

import numpy as np

from .. import findings as generated
from ..findings import render
from ..findings.study import method_name  # noqa: F401  (the name the report's modules use)
from ..stats import bootstrap, ties


def tie_rules():
    """The rules behind every 'top group' on the page, in words (stats/ties.py, rankings.py, fronts.py)."""
    return (f"<p class='note'><b>How ties are decided.</b> In each scene, spp level and target, the top group is "
            f"every method not significantly worse than the best: its error exceeds the best's by at most "
            f"{ties.Z:g} standard errors of the difference. Different samplers have independent samples "
            "(se of the difference = sqrt(se<sub>1</sub><sup>2</sup> + se<sub>2</sub><sup>2</sup>)); filters and "
            "radii of one sampler share their samples and are compared paired, over the per-seed errors. "
            "A method whose error cannot be told from zero joins the top group only if even its upper bound "
            "is below the best's; otherwise it is <i>undetermined</i> and not ranked. Across scenes a method is "
            "in the answer when it is in the top group of at least half of the scenes; its median ratio to each "
            f"scene's best comes with a {int(bootstrap.LEVEL * 100)} % bootstrap interval over scenes "
            f"({bootstrap.N_BOOT} resamples, seed {bootstrap.SEED}). Times within {ties.Z:g} standard errors are "
            "ties too. Flagged rows stay on every chart (hollow) and in every count.</p>")


def findings(df, notes, target=None, study=None):
    """The answer in HTML paragraphs (target: unused, kept for older callers; study: a findings.Study)."""
    found = generated.compute(df, notes, study)
    out = render.html_paragraphs(found)
    if (df["prefilter"] != "none").any():
        out.append(prefilter_finding(df))
    return out


def prefilter_finding(df):
    """Pre-filtered at the lowest spp against plain sampling at each spp (medians over scenes of per-scene
    ratios, the primary target's rows, each side's lowest error per scene)."""
    from ..study_rows import targets
    ok = df[(df["target"].astype(str) == targets(df)[0]) & np.isfinite(df["error"].to_numpy(dtype=float))]
    low = ok["spp"].min()
    pre = ok[(ok["prefilter"] != "none") & (ok["spp"] == low)]
    if pre.empty:
        return "<p>No pre-filtered row with a finite error at the lowest spp.</p>"
    pre_best = pre.loc[pre.groupby("scene")["error"].idxmin()].set_index("scene")
    parts = []
    for spp in sorted(ok["spp"].unique()):
        plain = ok[(ok["prefilter"] == "none") & (ok["spp"] == spp)]
        if plain.empty:
            continue
        pb = plain.loc[plain.groupby("scene")["error"].idxmin()].set_index("scene")
        common = pre_best.index.intersection(pb.index)
        if not len(common):
            continue
        er = np.median(pre_best.loc[common, "error"] / pb.loc[common, "error"])
        tr = np.median(pre_best.loc[common, "time_ms"] / pb.loc[common, "time_ms"])
        parts.append(f"plain {int(spp)} spp: error x{er:.2f}, time x{tr:.2f}")
    return (f"<p>Pre-filtered at {int(low)} spp (best pre-filtered method per scene) against the best plain "
            f"sampling: " + html.escape("; ".join(parts)) + " (medians over scenes of per-scene ratios; below 1 = "
            "the pre-filtered image is better or faster). The error-vs-time chart of each scene rings "
            "pre-filtered rows in black.</p>")
