"""The page's findings: the generated findings (the findings package: every number from the CSV, each
recomputed by the tests) as HTML paragraphs, and the page's statement of the tie rules."""
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
    return render.html_paragraphs(generated.compute(df, notes, study))
