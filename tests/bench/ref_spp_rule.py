#!/usr/bin/python3
"""The reference-spp rule (docs/science.md, "Choosing the reference spp") applied to a finished study's CSV.

For each row the seed part of mse_target_se^2 is the variance of its per-seed terms (mse_target_seeds) / K;
the rest of mse_target_se^2 is the reference part, which falls as 1 / ref_spp (to leading order; the
second-order term falls faster). The rule: the smallest power of two R such that, at the study's highest spp,
the reference part is at most a quarter of the seed part (the standard error at most 12 % above what an
exact reference would give) in at least three rows of four. Deterministic rows (no seed part) are left out.

usage: /usr/bin/python3 tests/bench/ref_spp_rule.py results/presented/study.csv
"""
import sys

import numpy as np
import pandas as pd


def main(path):
    d = pd.read_csv(path)
    d = d[d.deterministic == 0]
    seeds = d.mse_target_seeds.str.split(';').apply(lambda v: np.array([float(x) for x in v]))
    seed2 = seeds.apply(lambda v: v.var(ddof=1) / len(v))
    ratio = (d.mse_target_se ** 2 - seed2) / seed2  # reference part / seed part at the study's ref_spp
    r0 = int(d.ref_spp.iloc[0])
    top = d.spp == d.spp.max()
    print(f'{len(d)} rows, ref_spp {r0}; share of rows whose reference part is <= 1/4 of the seed part:')
    print('R       all    ' + '  '.join(f'spp {s:<4}' for s in sorted(d.spp.unique())))
    chosen = None
    for R in [256, 512, 1024, 2048, 4096, 8192, 16384]:
        ok = ratio * r0 / R <= 0.25
        shares = [ok[d.spp == s].mean() for s in sorted(d.spp.unique())]
        print(f'{R:<7} {ok.mean():.3f}  ' + '  '.join(f'{x:.3f}   ' for x in shares))
        if chosen is None and ok[top].mean() >= 0.75:
            chosen = R
    print(f'rule: ref_spp {chosen}' if chosen else 'rule: more than 16384')


if __name__ == '__main__':
    main(sys.argv[1])
