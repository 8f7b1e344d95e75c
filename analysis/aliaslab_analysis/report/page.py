"""The assembly of the report: index.html (findings first, then the scenes, stability and the samplers
and filters in isolation) and engineering.html (the benchmark and fuzzing records)."""
import html
import os
import re

import numpy as np

from .. import charts, errors, figures, spectra, study_csv
from ..findings import Study
from ..findings.study import facts as facts_of, is_quick
from . import studies
from .elements import figure, write_page
from .findings import findings, tie_rules
from .markdown import markdown_blocks, markdown_tables
from .scene import scene_section
from .summary_chart import summary_chart
from .targets_table import targets_section

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
            body.append(f"<h2>{html.escape(f)}</h2>" + "\n".join(b for _, b in markdown_blocks(fh.read())))
    return write_page(os.path.join(results, "engineering.html"), "aliaslab engineering records", "\n".join(body))


def isolation_section(results, embed):
    """Samplers and filters on their own (convergence on integrands, point sets, filter profiles)."""
    parts = []
    for rel, caption in (("convergence/convergence.png", "RMSE against N on analytic integrands, fitted slopes."),
                         ("pointsets/discrepancy.png", "Point sets: discrepancy and minimum distance."),
                         ("pointsets/spectra.png", "Point sets: radial power spectra."),
                         ("filters/filter_profiles.png", "Filter profiles and frequency responses.")):
        parts.append(figure(results, os.path.join(results, rel), caption, embed))
    slopes = os.path.join(results, "convergence", "slopes.md")
    if os.path.isfile(slopes):
        with open(slopes, encoding="utf-8") as f:
            table = markdown_tables(f.read())
        if table:
            parts.append(f"<details><summary>Convergence slopes against theory</summary>{table}</details>")
    parts = [p for p in parts if p]
    return ("<h2 id='isolation'>Samplers and filters in isolation</h2>" + "\n".join(parts)) if parts else ""


def build_report(results, study, charts_dir=None, images=None, label=None, embed=True, draw=True):
    """Writes RESULTS/index.html (and engineering.html); returns the index path. Raises errors.InputError."""
    df, notes = study_csv.load_study(study)
    study_csv.require_finite_errors(df, study)  # findings need at least one error to rank
    spec = spectra.load(study)
    charts_dir = charts_dir or os.path.join(results, "charts")
    images = images or os.path.join(os.path.dirname(os.path.abspath(study)), "images")
    s = Study(df, notes)
    primary = s.rows()  # the charts and scene sections: the primary target's rows
    if draw:
        charts.draw_all(primary, charts_dir)
    errors.prepare_out(charts_dir, "--charts")
    summary_png, _, _ = summary_chart(s, charts_dir)
    name = study_label(study, label, is_quick(facts_of(df)))
    target = ", ".join(study_csv.describe_target(t) for t in s.targets)
    science = html.escape(os.path.relpath(SCIENCE, results).replace(os.sep, "/"))
    scenes = s.scenes
    levels = s.levels
    facts = (f"{len(scenes)} scene(s); samplers {', '.join(sorted(df['sampler'].unique()))}; filters "
             f"{', '.join(sorted(df['filter_name'].unique()))}; radii "
             f"{', '.join(f'{r:g}' for r in sorted(df['radius'].unique()))}; spp {', '.join(map(str, levels))}; "
             f"seeds {', '.join(str(int(k)) for k in sorted(df['seeds'].unique()))}; target(s) {target}. "
             f"Read from <code>{html.escape(shown_path(study))}</code>.")
    body = [f"<h1>aliaslab report: {html.escape(name)}</h1>", f"<p class='facts'>{facts}</p>",
            studies.links_html(studies.other_studies(results, study, REPO)),
            "<nav><a href='#findings'>Findings</a><a href='#targets'>Targets</a><a href='#scenes'>Scenes</a>"
            "<a href='#stability'>Stability</a>"
            + ("<a href='#isolation'>Samplers and filters</a>" if os.path.isdir(os.path.join(results, "pointsets"))
               else "") + f"<a href='{science}'>Definitions (docs/science.md)</a></nav>",
            "<h2 id='findings'>Findings</h2>",
            "<p><b>Question.</b> Which sampler, filter and radius give the lowest error against the target "
            "for the time they take? The error of a configuration is its mean squared difference from the target "
            "over seeds, pixels and channels (the references' own error subtracted where the CSV says so); it "
            "splits into noise (changes with the seed), aliasing (structured error that stays), blur (the "
            f"filter's own reference against the target) and a cross term. Definitions: <a href='{science}'>"
            "docs/science.md</a>.</p>",
            "<div class='answer'><b>Answer for this study</b> (every number below is computed from the CSV)."
            + "".join(findings(df, notes, study=s)) + "</div>", tie_rules()]
    if notes:
        body.append("<div class='note'><b>About this CSV.</b> " + " ".join(html.escape(n) for n in notes) + "</div>")
    body.append(targets_section(s, science))
    body.append(figure(results, summary_png, f"Every method at every spp level against <code>{html.escape(s.primary)}"
                       "</code>: the median over scenes of its error relative to each scene's best at that spp, "
                       "with its bootstrap interval, against its time; the front with ties is numbered and listed. "
                       "Hollow: flagged or undetermined in at least one scene (kept, counted as is).", embed))
    body.append("<h2 id='scenes'>Per scene</h2><p>" + " ".join(
        f"<a href='#scene-{html.escape(figures.slug(x))}'>{html.escape(x)}</a>" for x in scenes) + "</p>")
    if len(s.targets) > 1:
        body.append(f"<p class='note'>Per scene, against the primary target <code>{html.escape(s.primary)}</code>; "
                    "the answer under the other targets is in the table above.</p>")
    ranked = s.ranked[s.ranked["target"].astype(str) == s.primary]
    for scene in scenes:
        body.append(scene_section(results, scene, primary[primary["scene"] == scene], charts_dir, images, embed,
                                  spec, ranked[ranked["scene"] == scene]))
    body.append("<h2 id='stability'>Stability</h2>")
    counts = {c: int(np.nansum(primary[c].to_numpy(dtype=float))) for c in
              ("undefined_pixels", "negative_pixels", "nan_pixels")}
    body.append(f"<p>Over all configurations: {counts['undefined_pixels']} undefined, {counts['negative_pixels']} "
                f"negative and {counts['nan_pixels']} NaN/Inf pixels; {int((df['flagged'] == 1).sum())} of {len(df)} "
                "row(s) flagged (listed in charts/flagged.csv; drawn hollow, kept in every ranking).</p>")
    body.append(figure(results, os.path.join(charts_dir, "stability.png"), "Pixel failure counts per method and "
                       "sampler, summed over scenes and spp; empty panels: no such pixel.", embed))
    body.append(isolation_section(results, embed))
    eng = engineering_page(results, science)
    if eng:
        body.append("<h2>Engineering</h2><p>Benchmarks and fuzzing records are on their own page: "
                    "<a href='engineering.html'>engineering.html</a>.</p>")
    return write_page(os.path.join(results, "index.html"), f"aliaslab report: {name}", "\n".join(body))
