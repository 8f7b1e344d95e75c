"""Statistics of a study's rankings: which methods are tied with the best, across scenes, at equal time
and on the error-vs-time front (issue 29 item 2). Every rule compares differences with their standard
errors; none picks a winner by the point estimate alone.

  ties.py       the standard error of the difference of two rows' errors (paired over seeds when the rows
                share their samples, else independent) and the top group of one (scene, spp, target) cell
  rankings.py   the top group of every cell, each row's ratio to the cell's best, and per method across
                scenes: scenes in the top group and a seeded bootstrap interval of its median ratio
  fronts.py     the error-vs-time front with ties (a point leaves it only when another is significantly
                better and not significantly slower) and the top groups at equal time
  bootstrap.py  the seeded bootstrap of a median over scenes
  flags.py      why a flagged row is flagged: unstable (heavy-tailed) or reference-limited
The rules and their constants (Z, the bootstrap's seed and size) are stated in each module's doc and on
the page.
"""
