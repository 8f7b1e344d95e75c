"""The assembly of the report: index.html from the list SECTIONS (the header and the other studies, the answer
table (read from the answer.csv written beside the page), the scene gallery, the findings, the summary chart,
the trade-off per target, the scenes, stability, the samplers and filters in isolation, engineering), with a sticky table of contents; engineering.html (the benchmark and
fuzzing records); docs/*.html (the definitions rendered from the repository's docs/*.md; one copy in
results/docs for every page inside results/: docs_html.docs_folder)."""
import html
import os
import re
from dataclasses import dataclass

import numpy as np

from .. import charts
from ..io import errors, study_csv
from ..charts import figures, spectra
from ..findings import Study
from ..findings.study import facts as facts_of, is_quick
from . import docs_html, navigation, studies
from .adaptive import adaptive_section
from .contract import contract_section
from .elements import figure, image_src, write_page
from . import answer_csv
from .answer_table import answer_table
from .findings import equivalence_rules, findings, method_name
from .markdown import markdown_tables
from .motion import motion_section
from .scene import scene_notes, scene_section
from .sizes import sizes_section
from .viewer_section import viewer_section
from .summary_chart import summary_chart
from .targets_table import targets_text
from .tradeoff import tradeoff_section

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
SCIENCE = os.path.join(REPO, "docs", "science.md")


def study_label(study, label, quick=False):
    """How the page names its study: --label, else "the quick study PATH" or "the study PATH" (PATH relative
    to the repository when inside it); whether it is quick is read from its CSV (findings/study.is_quick)."""
    if label:
        return label
    return f"{'the quick study' if quick else 'the study'} {shown_path(study)}"


def shown_path(path):
    """path relative to the repository when inside it, else absolute."""
    full = os.path.realpath(path)
    rel = os.path.relpath(full, os.path.realpath(REPO))
    return full if rel.startswith("..") else rel


ENGINEERING = re.compile(r"(_speed|^fuzzing)\.md$")


def engineering_page(results, science_href):
    files = sorted(f for f in os.listdir(results) if ENGINEERING.search(f))
    if not files:
        return None
    body = ["<h1>aliaslab: engineering records</h1>",
            "<p><a href='index.html'>Back to the report</a>. Measured benchmarks and fuzzing counts, as recorded "
            f"in the results folder (definitions: <a href='{science_href}'>docs/science.md</a>).</p>"]
    for f in files:
        with open(os.path.join(results, f), encoding="utf-8", errors="replace") as fh:
            anchor = figures.slug(f).replace(".", "-")
            body.append(f"<h2 id='{anchor}'>{html.escape(f)}</h2><div class='docs'>"
                        + docs_html.md_links_to_html(docs_html.to_html(fh.read())) + "</div>")
    return write_page(os.path.join(results, "engineering.html"), "aliaslab engineering records", "\n".join(body),
                      toc=True)


def isolation_section(results, embed):
    """Samplers and filters on their own (convergence on integrands, point sets, filter profiles)."""
    parts = []
    for rel, caption, toc in (("convergence/convergence.png", "RMSE against N on analytic integrands, fitted slopes.",
                               "convergence on integrands"),
                              ("pointsets/discrepancy.png", "Point sets: discrepancy and minimum distance.",
                               "discrepancy"),
                              ("pointsets/spectra.png", "Point sets: radial power spectra.", "point-set spectra"),
                              ("filters/filter_profiles.png", "Filter profiles and frequency responses.",
                               "filter profiles")):
        parts.append(figure(results, os.path.join(results, rel), caption, embed,
                            anchor="iso-" + figures.slug(rel).replace(".", "-"), toc=toc))
    slopes = os.path.join(results, "convergence", "slopes.md")
    if os.path.isfile(slopes):
        with open(slopes, encoding="utf-8") as f:
            table = markdown_tables(f.read())
        if table:
            parts.append(f"<details><summary>Convergence slopes against theory</summary>{table}</details>")
    parts = [p for p in parts if p]
    return ("<h2 id='isolation'>Samplers and filters in isolation</h2>" + "\n".join(parts)) if parts else ""


@dataclass
class Context:
    """What the page's sections share, built once by build_report."""
    results: str
    study: str
    df: object
    notes: list
    s: Study
    primary: object
    charts_dir: str
    images: str
    embed: bool
    science: str
    name: str
    spec: object = None
    answer_path: str = ""
    quick: str = None  # report --quick: the quick study to reconcile with (report/sizes.py)


def header_section(c):
    df, s = c.df, c.s
    target = ", ".join(study_csv.describe_target(t) for t in s.targets)
    csv_href = html.escape(os.path.relpath(os.path.abspath(c.study), c.results).replace(os.sep, "/"))
    facts = (f"{len(s.scenes)} scene(s); samplers {', '.join(sorted(df['sampler'].unique()))}; filters "
             f"{', '.join(sorted(df['filter_name'].unique()))}; radii "
             f"{', '.join(f'{r:g}' for r in sorted(df['radius'].unique()))}; spp {', '.join(map(str, s.levels))}; "
             f"seeds {', '.join(str(int(k)) for k in sorted(df['seeds'].unique()))}; target(s) {target}. "
             f"Read from <a href='{csv_href}'><code>{html.escape(shown_path(c.study))}</code></a>. "
             f"Definitions: <a href='{c.science}'>docs/science.md</a>. Click a chart to see it at full size.")
    return (f"<h1>aliaslab report: {html.escape(c.name)}</h1><p class='facts'>{facts}</p>"
            + studies.links_html(studies.other_studies(c.results, c.study, REPO)))


def answer_section(c):
    """The answer at a glance (report/answer_table.py), read from the answer.csv beside the page."""
    s = c.s
    return ("<h2 id='answer'>The answer at a glance</h2>"
            + answer_table(c.answer_path, s.targets, s.levels, sorted(c.df["sampler"].unique()), len(s.scenes),
                           s.margin, c.science) + targets_text(s, c.science))


def gallery_card_text(c, scene):
    """The scene's best at its highest spp and how many methods are equivalent to it (stats/effect.py)."""
    r = c.s.ranked
    r = r[(r["target"].astype(str) == c.s.primary) & (r["scene"] == scene)]
    if r.empty or not r["best"].any():
        return "no row with an error told from zero"
    spp = int(r.loc[r["best"], "spp"].max())
    g = r[r["spp"] == spp]
    best = g[g["best"]].iloc[0]
    eq = g[(g["verdict"] == "equivalent") & ~g["best"]]
    samplers = sorted(set(eq["sampler"]) - {best["sampler"]})
    more = f"; {len(eq)} more within {100 * c.s.margin:g} %" if len(eq) else f"; none other within {100 * c.s.margin:g} %"
    also = (" (" + ", ".join(samplers[:3]) + (f" +{len(samplers) - 3}" if len(samplers) > 3 else "") + ")") if samplers else ""
    return f"at {spp} spp: {html.escape(method_name(best))}, error {best['error']:.2g}{more}{html.escape(also)}"


def gallery_section(c):
    """A card per scene: its image (the study's pixel-area reference or thumbnail) and its best method with the
    number of methods equivalent to it."""
    folder = os.path.dirname(os.path.abspath(c.study))
    cards = []
    for scene in c.s.scenes:
        slug = figures.slug(scene)
        src, small = None, False
        for p in (os.path.join(c.images, slug, "reference-area.png"), os.path.join(folder, "thumbnails", slug + ".png")):
            if os.path.isfile(p):
                src = image_src(c.results, p, c.embed)
                small = int(c.primary.loc[c.primary["scene"] == scene, ["width", "height"]].to_numpy().max()) < 160
                break
        cards.append((f"scene-{slug}", str(scene), src, gallery_card_text(c, scene), small))
    return "<h2 id='gallery'>The scenes</h2>" + navigation.gallery(cards)


def findings_section(c):
    body = ["<h2 id='findings'>Findings</h2>",
            "<p><b>Question.</b> Which sampler, filter and radius give the lowest error against the target "
            "for the time they take? The error of a configuration is its mean squared difference from the target "
            "over seeds, pixels and channels (the references' own error subtracted where the CSV says so); it "
            "splits into noise (changes with the seed), aliasing (structured error that stays), blur (the "
            f"filter's own reference against the target) and a cross term. Definitions: <a href='{c.science}'>"
            "docs/science.md</a>.</p>",
            "<div class='answer'><b>Answer for this study</b> (every number below is computed from the CSV)."
            + "".join(findings(c.df, c.notes, study=c.s)) + "</div>", equivalence_rules(c.s.margin)]
    if c.notes:
        body.append("<div class='note'><b>About this CSV.</b> " + " ".join(html.escape(n) for n in c.notes) + "</div>")
    return "\n".join(body)


def summary_section(c):
    summary_png, _, _ = summary_chart(c.s, c.charts_dir)
    return figure(c.results, summary_png, f"Every method at every spp level against <code>{html.escape(c.s.primary)}"
                  "</code>: the median over scenes of its error relative to each scene's best at that spp, "
                  "against its time (mean over scenes); one panel per spp level, its time range shaded. The front "
                  "(the points no other point beats in both) is numbered and listed, with its 95 % bootstrap "
                  "interval and &plusmn;2 standard errors of its time. Hollow: heavy-tailed in at least one scene; "
                  "crosses: the fixed grid (deterministic, ranked like any method).",
                  c.embed, anchor="summary-chart", toc="every method: error vs time")


def scenes_section(c):
    s = c.s
    body = ["<h2 id='scenes'>Per scene</h2>"]
    if len(s.targets) > 1:
        body.append(f"<p class='note'>Per scene, against the primary target <code>{html.escape(s.primary)}</code>; "
                    "the answer under the other targets is in the table above.</p>")
    body.append(scene_notes(c.images, c.spec))
    ranked = s.ranked[s.ranked["target"].astype(str) == s.primary]
    for scene in s.scenes:
        body.append(scene_section(c.results, scene, c.primary[c.primary["scene"] == scene], c.charts_dir, c.images,
                                  c.embed, c.spec, ranked[ranked["scene"] == scene], s.margin))
    return "\n".join(body)


def stability_section(c):
    counts = {k: int(np.nansum(c.primary[k].to_numpy(dtype=float))) for k in
              ("undefined_pixels", "negative_pixels", "nan_pixels")}
    return ("<h2 id='stability'>Stability</h2>"
            f"<p>Over all configurations: {counts['undefined_pixels']} undefined, {counts['negative_pixels']} "
            f"negative and {counts['nan_pixels']} NaN/Inf pixels; {int((c.df['flagged'] == 1).sum())} of {len(c.df)} "
            "row(s) flagged (listed in charts/flagged.csv; drawn hollow, kept in every ranking).</p>"
            + figure(c.results, os.path.join(c.charts_dir, "stability.png"), "Pixel failure counts per method and "
                     "sampler, summed over scenes and spp; empty panels: no such pixel.", c.embed,
                     anchor="stability-chart", toc="pixel failures"))


def engineering_section(c):
    if not engineering_page(c.results, c.science):
        return ""
    return ("<h2 id='engineering'>Engineering</h2><p>Benchmarks and fuzzing records are on their own page: "
            "<a href='engineering.html'>engineering.html</a>.</p>")


# The page, in order: each entry a function of the Context returning HTML ('' to leave it out). A new section
# (an <h2 id=...> heading and its content) is one line here; the table of contents follows its anchors.
SECTIONS = [
    header_section,
    answer_section,  # the answer at a glance, from answer.csv
    contract_section,  # the samplers' variance bounds checked on this study; a violation first (report/contract.py)
    gallery_section,
    findings_section,
    summary_section,
    tradeoff_section,  # per target: noise + aliasing against blur, every filter over its radii
    sizes_section,  # the quick study (48 px) against this one: what changes with size (report/sizes.py)
    motion_section,  # aliasing in motion (studies with frames; report/motion.py)
    lambda c: viewer_section(c.results),  # the comparison viewer and the teaching strand (viewer/)
    scenes_section,
    adaptive_section,  # the adaptive samplers against their base: wins, losses and why
    stability_section,
    lambda c: isolation_section(c.results, c.embed),
    engineering_section,
]


def build_report(results, study, charts_dir=None, images=None, label=None, embed=False, draw=True, margin=None,
                 quick=None):
    """Writes RESULTS/index.html and RESULTS/answer.csv (and engineering.html, and docs/*.html: the definitions
    rendered); margin: the margin of equivalence (default stats/effect.MARGIN); returns the index path. Raises
    errors.InputError."""
    df, notes = study_csv.load_study(study)
    study_csv.require_finite_errors(df, study)  # findings need at least one error to rank
    charts_dir = charts_dir or os.path.join(results, "charts")
    images = images or os.path.join(os.path.dirname(os.path.abspath(study)), "images")
    s = Study(df, notes) if margin is None else Study(df, notes, margin)
    primary = s.rows()  # the charts and scene sections: the primary target's rows
    if draw:
        charts.draw_all(primary, charts_dir)
    errors.prepare_out(charts_dir, "--charts")
    docs = docs_html.docs_folder(results, REPO)  # one copy of the definitions under results/ (docs_html.py)
    docs_html.render_docs(os.path.dirname(SCIENCE), docs, write_page, "../index.html")
    science = os.path.relpath(os.path.realpath(os.path.join(docs, "science.html")), os.path.realpath(results)).replace(os.sep, "/")
    c = Context(results, study, df, notes, s, primary, charts_dir, images, embed,
                html.escape(science), study_label(study, label, is_quick(facts_of(df))))
    c.spec = spectra.load(study)
    c.quick = quick
    c.answer_path = answer_csv.write(s.answer, results)
    body = [part for part in (section(c) for section in SECTIONS) if part]
    return write_page(os.path.join(results, "index.html"), f"aliaslab report: {c.name}", "\n".join(body), toc=True)
