"""aliaslab's analysis of a study: charts, the report and the comparison of two runs, in Python.

Run from the repository root with Debian's /usr/bin/python3 (numpy, pandas, matplotlib):
    /usr/bin/python3 -m analysis COMMAND [options]      (COMMAND -h for its options)
COMMAND is report, charts, compare, convergence, pointsets, filters or viewer (cli.py).

Layout, a concept a module:
  study_csv.py       reading a study CSV: load_study(path) -> (DataFrame, notes)
  csv_tables.py      reading the experiments' small CSVs, checked
  errors.py          bad input: InputError, exit 2 with a message naming the file or option
  fits.py            the log-log slope fit and the Pareto front
  figures.py         matplotlib (Agg), file-name-safe names, saving PNG (+ SVG with --svg)
  palette.py         the one palette: each sampler's colour, each filter's marker (every chart, the page)
  degenerate.py      the rule that marks degenerate configurations (weight sums near zero) on the charts
  charts/            the study's charts, one module per chart family (the `charts` command)
  study_rows.py      the columns load_study adds (deterministic, cost, per-seed values), the targets
  stats/             effect sizes and a margin of equivalence (paired within a sample set), heavy tails, the
                     answer by factor, strict fronts of error against time
  findings/          the findings generated from a study: numbers (claims) and text, for the page and README
  report/            the HTML report: findings, scene sections, page assembly, Markdown (`report`)
  spectra.py         the error spectra beside a study CSV, read and drawn (for the report)
  viewer/            the page's comparison viewer: chosen configurations rendered, checked against the CSV,
                     exported per scene (`viewer`); its section of the page
  teaching/          the teaching strand (grid against jittered, point sets, ringing, blur, broken filters)
  compare.py         two study CSVs compared (`compare`; exit 1 on an accuracy regression)
  convergence_chart.py, pointset_chart.py, filter_profiles.py
                     the charts of the convergence, pointsets and filterprofile experiments
Modules import each other relatively (from . import ...): no sys.path edits anywhere.
"""
