"""Each filter's 1-D profile and the magnitude of its frequency response.

Usage: /usr/bin/python3 -m analysis filters --out DIR
           [--csv profiles.csv | --bin build/bin/filterprofile]

The numbers come from the C++ experiment `filterprofile` (the library's own
Filter::eval, one source of truth): either a CSV it wrote (--csv) or the
binary, run here (--bin). Writes DIR/filter_profiles.png (and .svg with --svg) and, when the
binary was run, DIR/filter_profiles.csv. Left: the 1-D profile g(x) (x in
pixels; f = g(x) g(y) or g(|d|)) at each
filter's natural radius; right: |H(nu)|, the 2-D filter's normalised Fourier
transform along the x axis, with the pixel Nyquist frequency 0.5 marked:
response below 0.5 lost is blur, response above 0.5 kept is aliasing,
overshoot of the profile below 0 is ringing.
"""
import argparse
import io
import os
import subprocess

import pandas as pd

from ..io import csv_tables, errors
from . import figures, palette
from .figures import plt

COLUMNS = ["filter", "radius", "describe", "kind", "x", "value"]
NUMERIC = ["radius", "x", "value"]


def chart(df, out_dir):
    fig, (a, b) = plt.subplots(1, 2, figsize=(14, 5))
    for name, g in df.groupby("filter", sort=False):
        label = g["describe"].iloc[0]
        p = g[g["kind"] == "profile"]
        r = g[g["kind"] == "response"]
        style = dict(color=palette.filter_colour(name), lw=1.2, label=label, marker=palette.filter_marker(name),
                     markevery=0.1, ms=4)
        a.plot(p["x"], p["value"], **style)
        b.plot(r["x"], r["value"], **style)
    a.axhline(0, color="k", lw=0.6)
    a.set_xlabel("offset x (pixels)")
    a.set_ylabel("1-D profile g(x)")
    a.set_title("Profiles at the natural radius (below 0: negative lobes, ringing)")
    b.axvline(0.5, color="grey", ls="--", lw=0.8, label="Nyquist (0.5 cycles/pixel)")
    b.set_yscale("log")
    b.set_ylim(1e-4, 1.5)
    b.set_xlabel("frequency (cycles per pixel)")
    b.set_ylabel("|H| (normalised, H(0) = 1)")
    b.set_title("Frequency response along x: blur below Nyquist, leakage above")
    for ax in (a, b):
        ax.grid(True, which="major", alpha=0.3)
    b.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    return figures.save_figure(fig, out_dir, "filter_profiles")


def main(argv=None, prog=None):
    ap = argparse.ArgumentParser(prog=prog, description="Filter profiles and frequency responses")
    ap.add_argument("--out", required=True)
    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--csv", help="CSV written by filterprofile")
    src.add_argument("--bin", help="the filterprofile executable, run here")
    figures.add_svg_option(ap)
    args = ap.parse_args(argv)
    figures.write_svg(args.svg)
    errors.prepare_out(args.out)
    try:
        if args.csv:
            df = csv_tables.read_table(args.csv, COLUMNS, NUMERIC)
        else:
            text = subprocess.run([args.bin], check=True, capture_output=True, text=True).stdout
            df = csv_tables.check_table(pd.read_csv(io.StringIO(text), dtype=str, keep_default_na=False),
                                    f"output of {args.bin}", COLUMNS, NUMERIC)
            df.to_csv(os.path.join(args.out, "filter_profiles.csv"), index=False)
    except errors.InputError as e:
        errors.fail(str(e))
    except (OSError, subprocess.CalledProcessError, pd.errors.ParserError, pd.errors.EmptyDataError) as e:
        errors.fail(f"{args.csv or args.bin}: {e}")
    chart(df, args.out)
    return 0
