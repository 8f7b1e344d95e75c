"""Charts of the `pointsets` experiment's tables.

Usage: /usr/bin/python3 -m analysis pointsets DIR_WITH_CSVS --out DIR [--svg]

Reads pointsets.csv and spectra.csv; writes spectra.png (radial mean
periodogram against k / sqrt(N), one panel per N) and discrepancy.png
(L2-star discrepancy and normalised minimum toroidal distance against N); with --svg each also as .svg.
"""
import argparse
import os

import pandas as pd

from ..io import csv_tables, errors
from . import figures, palette
from .figures import plt


def spectra_chart(sp, out_dir):
    counts = sorted(sp["n"].unique())
    samplers = list(dict.fromkeys(sp["sampler"]))
    fig, axes = plt.subplots(1, len(counts), figsize=(5 * len(counts), 4.2), squeeze=False, sharey=True)
    for ax, n in zip(axes.flat, counts):
        for s in samplers:
            g = sp[(sp["n"] == n) & (sp["sampler"] == s)]
            ax.plot(g["k_norm"], g["power"], lw=1, color=palette.sampler_colour(s), label=s)
        ax.axhline(1.0, color="grey", lw=0.8, ls=":")
        ax.set_yscale("log")
        ax.set_ylim(1e-3, None)  # exact zeros of the regular grid would squash the rest
        ax.set_xlabel("radial frequency |k| / sqrt(N)")
        ax.set_title(f"N = {n} ({int(sp[sp['n'] == n]['sets'].iloc[0])} sets)")
        ax.grid(True, alpha=0.3)
    axes.flat[0].set_ylabel("mean periodogram P(k) (1 = white noise; floor 1e-3)")
    axes.flat[-1].legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.suptitle("Radial power spectra of the sampling patterns")
    figures.save_figure(fig, out_dir, "spectra")


def discrepancy_chart(ps, out_dir):
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.5))
    for s, g in ps.groupby("sampler", sort=False):
        g = g.sort_values("n")
        a.errorbar(g["n"], g["l2star_mean"], yerr=g["l2star_sd"], marker="o", ms=3, lw=1, capsize=2,
                   color=palette.sampler_colour(s), label=s)
        b.plot(g["n"], g["min_dist_norm_mean"], marker="o", ms=3, lw=1, color=palette.sampler_colour(s), label=s)
    a.set_xscale("log", base=2)
    a.set_yscale("log")
    a.set_xlabel("N")
    a.set_ylabel("L2-star discrepancy (mean ± sd over sets)\nlower is better")
    a.set_title("L2-star discrepancy (Warnock)")
    b.set_xscale("log", base=2)
    b.set_xlabel("N")
    b.set_ylabel("min toroidal distance / sqrt(2 / (sqrt(3) N))")
    b.set_title("Minimum toroidal distance (1 = hexagonal packing)")
    for ax in (a, b):
        ax.grid(True, which="major", alpha=0.3)
    b.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    figures.save_figure(fig, out_dir, "discrepancy")


def main(argv=None, prog=None):
    ap = argparse.ArgumentParser(prog=prog, description="Point-set charts")
    ap.add_argument("dir", help="folder holding pointsets.csv and spectra.csv")
    ap.add_argument("--out", required=True)
    figures.add_svg_option(ap)
    args = ap.parse_args(argv)
    figures.write_svg(args.svg)
    try:
        ps = pd.read_csv(os.path.join(args.dir, "pointsets.csv"))
        sp = pd.read_csv(os.path.join(args.dir, "spectra.csv"))
    except (OSError, pd.errors.ParserError, pd.errors.EmptyDataError) as e:
        errors.fail(f"{args.dir}: {e}")
    csv_tables.require_rows(ps, os.path.join(args.dir, "pointsets.csv"), ["sampler", "n", "l2star_mean", "l2star_sd", "min_dist_norm_mean"])
    csv_tables.require_rows(sp, os.path.join(args.dir, "spectra.csv"), ["sampler", "n", "sets", "k_norm", "power"])
    errors.prepare_out(args.out)
    spectra_chart(sp, args.out)
    discrepancy_chart(ps, args.out)
    return 0
