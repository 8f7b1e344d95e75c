"""The `charts` command: every chart and table of one study CSV into --out."""
import argparse
import sys

from ..io import errors, study_csv, study_rows
from . import figures
from . import draw_all


def main(argv=None, prog=None):
    ap = argparse.ArgumentParser(prog=prog,
                                 description="Charts of an aliaslab sweep CSV (definitions: docs/science.md)")
    ap.add_argument("csv", help="study CSV")
    ap.add_argument("--out", required=True, help="output folder")
    ap.add_argument("--filter", default=None,
                    help="filter of the convergence chart (default: that of each scene's best method)")
    figures.add_svg_option(ap)
    args = ap.parse_args(argv)
    figures.write_svg(args.svg)
    try:
        df, notes = study_csv.load_study(args.csv)
    except errors.InputError as e:
        errors.fail(str(e))
    if args.filter is not None and not (df["filter_name"] == args.filter).any():
        errors.fail(f"--filter: no rows with filter '{args.filter}'")
    for n in notes:
        print(f"note: {n}", file=sys.stderr)
    shown = study_rows.targets(df)
    if len(shown) > 1:
        print(f"note: {len(shown)} targets in the CSV; the charts are drawn against the primary one, {shown[0]} "
              "(the report shows the answer under each)", file=sys.stderr)
        df = df[df["target"].astype(str) == shown[0]]
    draw_all(df, args.out, args.filter)
    print(f"charts written to {args.out}")
    return 0
