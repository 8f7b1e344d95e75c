"""Log-log chart of RMSE against N from the `convergence` experiment.

Usage: /usr/bin/python3 -m analysis convergence convergence.csv --out DIR
           [--fit-min 16] [--fit-max 4096]

The CSV is the `convergence` program's (which prints this command with its fit range). As the program does,
--fit-max is capped at the CSV's largest N and --fit-min defaults to at most half of it.

One panel per integrand, one line per sampler; the legend gives the slope
fitted by least squares on log-log over the powers of two in
[fit-min, fit-max] (the same fit as lib/measure/convergence.h). Counts that are
not powers of two are drawn as crosses. Writes DIR/convergence.png (and .svg with --svg).
"""
import argparse

import numpy as np

from ..io import csv_tables, errors
from . import figures, palette
from ..stats import fits
from .figures import plt

COLUMNS = ["sampler", "integrand", "n", "rmse", "realisations"]


def read(path):
    """The convergence CSV, checked (columns, rows, numbers); raises errors.InputError naming file and column."""
    return csv_tables.read_table(path, COLUMNS, ["n", "rmse", "realisations"])


def chart(df, out_dir, fit_min, fit_max):
    integrands = list(dict.fromkeys(df["integrand"]))
    samplers = list(dict.fromkeys(df["sampler"]))
    cols = min(3, len(integrands))
    rows = (len(integrands) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(6 * cols, 4.8 * rows), squeeze=False)
    for ax in axes.flat[len(integrands):]:
        ax.axis("off")
    for ax, integrand in zip(axes.flat, integrands):
        for sampler in samplers:
            g = df[(df["integrand"] == integrand) & (df["sampler"] == sampler)].sort_values("n")
            g = g[(g["rmse"] > 0) & np.isfinite(g["rmse"]) & (g["n"] > 0)]
            if g.empty:
                continue
            pow2 = np.abs(np.log2(g["n"]) - np.round(np.log2(g["n"]))) < 1e-9
            try:
                slope = fits.fit_loglog_slope(g["n"], g["rmse"], fit_min, fit_max, True)[0]
                label = f"{sampler} ({slope:+.2f})"
            except ValueError:
                label = f"{sampler} (no fit)"
            c = palette.sampler_colour(sampler)
            ax.plot(g["n"][pow2], g["rmse"][pow2], "-o", ms=3, color=c, label=label, lw=1)
            ax.plot(g["n"][~pow2], g["rmse"][~pow2], "x", ms=5, color=c)
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xlabel("N (points per estimate)")
        ax.set_ylabel("RMSE of the estimate (lower is better)")
        ax.set_title(integrand)
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize=6, ncol=2, title="sampler (fitted slope)", title_fontsize=6)
    fig.suptitle(f"Convergence on analytic integrands (slopes: least squares on log-log, powers of two, "
                 f"{fit_min:g} <= N <= {fit_max:g}; x: non-powers of two)")
    return figures.save_figure(fig, out_dir, "convergence")


def main(argv=None, prog=None):
    ap = argparse.ArgumentParser(prog=prog, description="RMSE against N chart with fitted slopes")
    ap.add_argument("csv")
    ap.add_argument("--out", required=True)
    ap.add_argument("--fit-min", type=float, help="smallest N of the slope fit (default 16, at most half the "
                    "largest N)")
    ap.add_argument("--fit-max", type=float, default=4096, help="largest N of the slope fit (capped at the largest "
                    "N; default %(default)s)")
    figures.add_svg_option(ap)
    args = ap.parse_args(argv)
    figures.write_svg(args.svg)
    try:
        df = read(args.csv)
    except errors.InputError as e:
        errors.fail(str(e))
    errors.prepare_out(args.out)
    largest = float(df["n"].max())
    fit_min = min(16.0, largest / 2) if args.fit_min is None else args.fit_min
    chart(df, args.out, fit_min, min(args.fit_max, largest))
    return 0
