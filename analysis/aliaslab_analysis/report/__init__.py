"""The report of a study: an HTML page that answers the study's question first.

Usage:
  /usr/bin/python3 -m analysis report RESULTS_DIR [--study CSV] [--charts DIR] [--images DIR]
                                       [--label TEXT] [--embed] [--reuse-charts]
  /usr/bin/python3 -m analysis report RESULTS_DIR --tables [--study CSV]
  /usr/bin/python3 -m analysis report RESULTS_DIR --findings-md [--study CSV]

Writes RESULTS_DIR/index.html, and RESULTS_DIR/engineering.html when
RESULTS_DIR holds benchmark or fuzzing records (*_speed.md, fuzzing.md).
Defaults: --study RESULTS_DIR/study/study.csv (else RESULTS_DIR/study.csv),
--charts RESULTS_DIR/charts, --images = the study CSV's folder + /images.
Only the one study CSV is read: shard CSVs lying beside it are ignored, and a
CSV that repeats a configuration is refused (exit 2).

The page, in order (page.SECTIONS: a section is one line there), beside a sticky table of contents built
from its anchors (navigation.py; every scene and every chart has one), click-to-enlarge on every chart:
  0. what study it shows (size, spp, seeds, references, targets; "a quick
     study" when below 256 px or references below 64x its highest spp) and
     links to the other studies in RESULTS_DIR (each folder with an
     study CSV: its page, else its CSV; report/studies.py), then the scene
     gallery (a card per scene: the study's reference image or
     thumbnails/<scene>.png beside the CSV, and its best method);
  1. the question and this study's answer, generated from the CSV by the
     findings package (the top groups per spp under each target, what holds
     under all targets, the front with ties, equal time, where the error
     comes from, the grid, flagged rows; every number recomputed by the
     tests), the tie rules (stats/), the answer per target as a table, and
     one chart: the median error relative to each scene's best against time,
     every method kept (flagged hollow, the fixed grid as crosses);
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

Modules: findings.py (the generated findings as HTML, the tie rules in words), targets_table.py (the
answer under each target), studies.py (the other studies linked), summary_chart.py (the findings' chart),
scene.py (a scene's section), elements.py (HTML building blocks), page.py (the pages' assembly),
markdown.py (--tables' Markdown, the fallback reader), docs_html.py (Markdown to HTML: docs/, engineering.html),
navigation.py (contents, gallery, lightbox), tables.py (--tables), cli.py (the command).
"""



