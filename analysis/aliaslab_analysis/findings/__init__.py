"""The findings of a study, generated from its CSV: structured numbers and the text that
states them, for the report's page and for results/README.md's findings section.

compute(df, notes) -> [Finding]. A Finding has a `key`, a `title`, a `text` (Markdown-light: **bold** and
`code`, turned into HTML by the page) and `claims`: every number the text states, each a dict with a
`kind`, the parameters that say what it is (target, spp, method, scene, ...) and its `value`. The tests
(analysis/tests/test_findings.py) recompute every claim from the CSV by a separate code path (plain loops
over csv rows, no pandas groupby) and compare.

  study.py    Study: the loaded rows and what every finding shares (targets, verdicts, across-scene
              records), and the finding that says what study this is
  answer.py   the answer under each target by factor: the samplers equivalent to each scene's best (each at
              its best filter and radius, families named), jittered and random against them, what changes
              from the lowest to the highest spp
  factors.py  the filter and radius under each target, and what holds under every target
  time.py     what sets the cost (spp, or the method), the strict front across scenes
  terms.py    where the error comes from under every target, what an own-mse ranking would pick, aliasing
              within error, flagged and heavy-tailed rows
  grid.py     the fixed grid ranked as deterministic, its alignment, the shifted grid; samplers against random
  prefilter.py  pre-filtering against plain sampling (studies with pre-filtered rows)
  compare.py  two study CSVs compared (`compare`; exit 1 on an accuracy regression)
(the findings as HTML or Markdown: report/findings_text.py)
"""
from . import answer, factors, grid, prefilter, study, terms, time
from .study import Finding, Study


def compute(df, notes, s=None, margin=None):
    """Every finding of the study, in the order the page shows them (s: a Study of df, made when None, with
    the margin of equivalence `margin`, default stats/effect.MARGIN)."""
    s = s or (Study(df, notes) if margin is None else Study(df, notes, margin))
    out = [study.describe(s)]
    out += answer.findings(s)
    out += factors.findings(s)
    out += time.findings(s)
    out += terms.findings(s)
    out += grid.findings(s)
    out += prefilter.findings(s)
    return [f for f in out if f is not None]


__all__ = ["compute", "Finding", "Study"]
