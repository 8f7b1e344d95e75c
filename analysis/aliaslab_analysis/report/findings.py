"""The page's findings: the generated findings (the findings package: every number from the CSV, each
recomputed by the tests) as HTML paragraphs, and the page's statement of the rules behind every verdict."""
from .. import findings as generated
from . import findings_text as render
from ..findings.study import method_name  # noqa: F401  (the name the report's modules use)
from ..stats import bootstrap, effect, factors, tails


def equivalence_rules(margin):
    """The rules behind every verdict on the page, in words (stats/effect.py, tails.py, equivalence.py,
    factors.py, fronts.py)."""
    m = f"{100 * margin:g} %"
    return (f"<p class='note' id='rules'><b>How a verdict is reached.</b> In each scene, spp level and target every "
            f"method's error is a ratio to the scene's best (the lowest error told from zero, not heavy-tailed; the "
            f"fixed grid is ranked like any method, deterministic) with a 95 % interval, judged against a margin of "
            f"<b>{m}</b>: <i>equivalent</i> when the interval lies below 1 + {m} (a difference that is significant "
            f"but inside the margin is equivalent), <i>worse</i> when it lies above, <i>undetermined</i> otherwise. "
            "The interval is Student's t on the log ratio (delta method; K &minus; 1 degrees of freedom from the "
            "K seeds, Welch-Satterthwaite when the rows are independent): filters and radii of one sampler share "
            "their samples and are compared paired over the per-seed errors, other samplers as independent; the "
            "references' part of each row's standard error is counted for both rows (the rows of a scene share "
            "its references: conservative). A row is <i>heavy-tailed</i> when its largest seed carries more than "
            f"{tails.SHARE_FACTOR:g}x an equal share of its summed error: its interval is then a bootstrap over "
            f"seeds ({effect.N_BOOT} resamples, seed {effect.BOOT_SEED}) and it is never equivalent. Across scenes a "
            "method's median ratio comes with a 95 % bootstrap interval over scenes "
            f"({bootstrap.N_BOOT} resamples, seed {bootstrap.SEED}), judged by the same rule (equivalent across "
            "scenes also needs equivalence in at least half of them), and the number of scenes where it is "
            "equivalent. A sampler is judged at its best filter and radius (its lowest median); "
            "the leading samplers are those equivalent across scenes or in at least half of them; a family "
            f"({', '.join(f'{k}: {chr(44).join(v)}' for k, v in factors.FAMILIES.items())}) is named when all of it "
            "leads. A point is on a front when no other point has both a lower error and a lower time.</p>")


def findings(df, notes, target=None, study=None):
    """The answer in HTML paragraphs (target: unused, kept for older callers; study: a findings.Study)."""
    return render.html_paragraphs(generated.compute(df, notes, study))
