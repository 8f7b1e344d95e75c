"""aliaslab's analysis of a study: charts, the report and the comparison of two runs, in Python.

Run from the repository root with Debian's /usr/bin/python3 (numpy, pandas, matplotlib):
    /usr/bin/python3 -m analysis COMMAND [options]      (COMMAND -h for its options)
COMMAND is report, charts, compare, convergence, pointsets, filters, viewer or teaching (cli.py).

Layers, lowest first; a module imports only from its own layer and those below (analysis/tests/test_layers.py):
  io/        reading and checking the files taken in: study CSVs, the experiments' CSVs, EXR images, bad input
  stats/     estimates: effect sizes and a margin of equivalence (paired within a sample set), heavy tails, the
             answer by factor, strict fronts of error against time, slope fits, the degenerate rule
  findings/  the findings generated from a study: numbers (claims) and text, data only (no HTML or Markdown);
             two studies compared (`compare`)
  charts/    computing and drawing figures: the study's charts (`charts`), the experiments' (`convergence`,
             `pointsets`, `filters`), the error spectra, the motion loop; the palette
  report/    the HTML pages (and README's Markdown): findings, scene sections, page assembly (`report`)
  viewer/    the page's comparison viewer: chosen configurations rendered, checked against the CSV, exported
             per scene (`viewer`); x-t slices of the motion study
  teaching/  the teaching strand from the viewer's renders (`teaching`), the negative control's record
cli.py, the one entry point, sits above them all. Modules import each other relatively (from . import ...):
no sys.path edits anywhere.
"""
