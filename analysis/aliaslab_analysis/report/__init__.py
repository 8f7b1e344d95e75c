"""The report of a study: an HTML page that answers the study's question first.

Usage:
  /usr/bin/python3 -m analysis report RESULTS_DIR [--study CSV] [--charts DIR] [--images DIR]
                                       [--label TEXT] [--link] [--reuse-charts]
  /usr/bin/python3 -m analysis report RESULTS_DIR --tables [--study CSV]

Writes RESULTS_DIR/index.html, and RESULTS_DIR/engineering.html when
RESULTS_DIR holds benchmark or fuzzing records (*_speed.md, fuzzing.md).
Defaults: --study RESULTS_DIR/study/study.csv (else RESULTS_DIR/study.csv),
--charts RESULTS_DIR/charts, --images = the study CSV's folder + /images.
Only the one study CSV is read: shard CSVs lying beside it are ignored, and a
CSV that repeats a configuration is refused (exit 2).

The page, in order:
  1. the question and this study's answer, computed from the CSV (lowest
     error against the common target per spp level, the error-vs-time front,
     what an own-mse ranking would have picked, where the error comes from),
     with one chart: error relative to each scene's best against time;
  2. per scene: the decomposition (stacked bars), the radius trade-off, the
     convergence with spp, the error-vs-time chart, the heatmap, the contact
     sheet and the images of the best and the worst method;
  3. stability (undefined / negative / NaN pixels, flagged rows);
  4. samplers and filters in isolation (analytic convergence, point sets,
     filter profiles) when RESULTS_DIR has them;
  5. a link to engineering.html (benchmarks, fuzzing).
The charts are (re)drawn from the study into --charts first (the charts
package), unless --reuse-charts. The page is self-contained (images
embedded as data URIs) unless --link, which refers to the files by relative
path. It names the study it reports: "the reference study" only for the
repository's results/study/study.csv, otherwise the CSV's path (or --label).
Definitions: docs/science.md, linked from the page.

--tables prints Markdown for results/README.md instead (the Pareto front of
every scene by the error against the target, and the stability counts).

Modules: findings.py (the numbers and sentences computed from the CSV), summary_chart.py (the findings'
chart), scene.py (a scene's section), elements.py (HTML building blocks), page.py (the pages' assembly),
markdown.py (the records' Markdown), tables.py (--tables), cli.py (the command).
"""



