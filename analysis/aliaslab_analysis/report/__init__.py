"""The report of a study: an HTML page that answers the study's question first.

Usage:
  /usr/bin/python3 -m analysis report RESULTS_DIR [--study CSV] [--charts DIR] [--images DIR]
                                       [--label TEXT] [--embed] [--reuse-charts] [--margin DELTA]
                                       [--quick CSV]
  /usr/bin/python3 -m analysis report RESULTS_DIR --tables [--study CSV]
  /usr/bin/python3 -m analysis report RESULTS_DIR --findings-md [--study CSV]

Writes RESULTS_DIR/index.html and RESULTS_DIR/answer.csv.gz, and RESULTS_DIR/engineering.html when
RESULTS_DIR holds benchmark or fuzzing records (*_speed.md, fuzzing.md).
Defaults: --study RESULTS_DIR/study/study.csv (else RESULTS_DIR/study.csv; each also as .csv.gz),
--charts RESULTS_DIR/charts, --images = the study CSV's folder + /images.
Only the one study CSV is read: shard CSVs lying beside it are ignored, and a
CSV that repeats a configuration is refused (exit 2).

The page, in order (page.SECTIONS: a section is one line there), beside a sticky table of contents built
from its anchors (navigation.py; every scene and every chart has one), click-to-enlarge on every chart:
  0. what study it shows (size, spp, seeds, references, targets; "a quick
     study" when below 256 px or references below 64x its highest spp) and
     links to the other studies in RESULTS_DIR (each folder with a study
     CSV: its page, else its CSV; report/studies.py); then the answer at a
     glance: a table (a row per spp, a column per target) of the leading
     samplers, their filter and radius and jittered's and random's error
     against the best, read from RESULTS_DIR/answer.csv.gz, which the report
     writes (answer_csv.py, answer_table.py; the margin of equivalence:
     --margin, default 0.10); then the scene gallery (a card per scene: the
     study's reference image or thumbnails/<scene>.png beside the CSV, its
     best method and how many are equivalent to it);
  1. the question and this study's answer, generated from the CSV by the
     findings package (the answer by factor under each target, what changes
     with spp, what holds under all targets, what sets the cost, the strict
     front, where the error comes from, the grid, flagged and heavy-tailed
     rows; every number recomputed by the tests), the rules of the verdicts,
     one chart (the median error relative to each scene's best against
     time, every method kept: heavy-tailed hollow, the fixed grid as
     crosses), and the targets as a trade-off (tradeoff.py: per target,
     noise plus aliasing against blur for every filter over its radii);
     then, when a quick study of smaller images is found, it against this one
     (sizes.py: the same scenes at another size, --quick CSV, default
     RESULTS_DIR/study/study.csv: whether the answer is the same, the rank
     agreement of the methods, what moves with size, what cannot be compared);
  2. per scene: the decomposition (stacked bars), the radius trade-off, the
     convergence with spp, the error-vs-time chart, the heatmap, the contact
     sheet and the images of the best and the worst method;
  3. stability (undefined / negative / NaN pixels, flagged rows);
  4. samplers and filters in isolation (analytic convergence, point sets,
     filter profiles) when RESULTS_DIR has them;
  5. a link to engineering.html (benchmarks, fuzzing).
The charts are (re)drawn from the study into --charts first (the charts
package), unless --reuse-charts. The page refers to its images by relative
path, decoded lazily (--link, the default); --embed embeds them as data URIs
(one self-contained file). docs/*.md are rendered into RESULTS/docs/*.html
(docs_html.py, Debian's python3-markdown), which the page links; a page inside the repository's results/
(results/study, results/prefilter) links to the one copy in results/docs instead of writing its own. It names the study it reports: "the quick study PATH" when the CSV is
below 256 px or its references below 64x its highest spp, else "the study
PATH" (or --label).
Definitions: docs/science.md, linked from the page as docs/science.html.

--tables prints Markdown for results/README.md instead (the Pareto front of
every scene by the error against the target, and the stability counts);
--findings-md prints the generated findings as README.md's findings section.
With several targets in the CSV, the charts and scene sections show the
primary target (box:0.5 when present, else the CSV's first).

Modules: findings.py (the generated findings as HTML, the rules of the verdicts in words), answer_csv.py
(answer.csv written and read), answer_table.py (the answer at a glance), targets_table.py (what each target
favours), tradeoff.py (the targets as a trade-off), sizes.py (the quick study against this one), studies.py (the other studies linked), summary_chart.py (the findings' chart),
scene.py (a scene's section), elements.py (HTML building blocks), page.py (the pages' assembly),
markdown.py (--tables' Markdown, the fallback reader), docs_html.py (Markdown to HTML: docs/, engineering.html),
navigation.py (contents, gallery, lightbox), tables.py (--tables), findings_text.py (the findings as HTML
paragraphs or README's Markdown section), viewer_section.py (the viewer's section of the page),
adaptive_record.py (results/adaptive.md's generated section), cli.py (the command).
"""



