"""Statistics of a study's answer (docs/science.md "Answers a practitioner can act on"): effect sizes with a
margin of practical equivalence, heavy tails, the answer by factor, fronts of error against time.

  student.py      Student's t (cdf, quantile, Welch-Satterthwaite) without scipy
  tails.py        the heavy-tail rule: the largest seed carries more than twice an equal share of the error
  effect.py       per cell (target, scene, spp): each row's ratio to the best with a 95 % interval (t on the
                  log ratio, paired within a sample set; a bootstrap over seeds for heavy-tailed rows) and its
                  verdict at the margin: equivalent, worse or undetermined
  equivalence.py  every cell's effects, the across-scene records (median ratio, bootstrap over scenes, scenes
                  equivalent) and answer.csv's table
  factors.py      the answer by factor: each sampler at its best filter and radius, the leading samplers and
                  families, each filter at its best radius
  fronts.py       strict Pareto fronts of error against time, per scene and across scenes; cost set by spp
  sizes.py        two studies of the same scenes at two image sizes on what both hold: the answer at each
                  size, the rank agreement of the methods (Spearman), what moves with size
  bootstrap.py    the seeded bootstrap of a median over scenes
  flags.py        why a flagged row is flagged: unstable or reference-limited
  ties.py         the standard error of a paired or independent difference and tie groups (the motion section)
  rankings.py     the columns naming a method and a cell, a method's label
  fits.py         the log-log slope fit and the Pareto front
  degenerate.py   the rule that marks degenerate configurations (weight sums near zero) on the charts
The constants (the margin, the bootstrap seeds and sizes, the heavy-tail factor) are stated in each module's
doc and on the page.
"""
