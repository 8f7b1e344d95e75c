"""The `report` command (options in report/__init__.py's doc)."""
import argparse
import os
import sys

from ..io import errors
from ..charts import figures
from .page import build_report, shown_path
from .studies import csv_of
from .tables import tables


def default_study(results):
    """The results folder's study CSV: study/study.csv or study.csv (or either .csv.gz), else None."""
    return csv_of(results)


def findings_markdown(study, margin=None):
    """The findings section of results/README.md, generated from the study CSV."""
    from .. import findings
    from ..io import study_csv
    from . import findings_text as render
    df, notes = study_csv.load_study(study)
    text = render.markdown_section(findings.compute(df, notes, margin=margin), shown_path(study))
    return text + ("\n" + " ".join(f"_{n}_" for n in notes) if notes else "")


def main(argv=None, prog=None):
    ap = argparse.ArgumentParser(prog=prog, description="The HTML report of an aliaslab study (findings first); "
                                 "definitions in docs/science.md")
    ap.add_argument("results", help="folder the report is written into (index.html, engineering.html)")
    ap.add_argument("--study", help="study CSV, gzipped or not (default RESULTS/study/study.csv, else "
                    "RESULTS/study.csv, each also as .csv.gz)")
    ap.add_argument("--charts", help="folder of the charts, drawn there from the study (default RESULTS/charts)")
    ap.add_argument("--images", help="folder of the sweep's images (default: the study CSV's folder/images)")
    ap.add_argument("--label", help="how the page names the study (default: 'the quick study PATH' or "
                    "'the study PATH', read from the CSV)")
    ap.add_argument("--link", action="store_true", help="refer to images by relative path, decoded lazily (the "
                    "default; kept for old scripts)")
    ap.add_argument("--embed", action="store_true", help="embed images as data URIs: one file to share, larger")
    ap.add_argument("--reuse-charts", action="store_true", help="do not redraw the charts already in --charts")
    ap.add_argument("--margin", type=float, default=None, metavar="DELTA",
                    help="the margin of practical equivalence: a method is equivalent to a scene's best when the 95 %% "
                    "interval of its error ratio lies below 1 + DELTA (default 0.10, printed on the page)")
    ap.add_argument("--quick", metavar="CSV", help="the quick study to reconcile this one with (same scenes at "
                    "another size; default RESULTS/study/study.csv[.gz] when it exists and is not --study)")
    ap.add_argument("--tables", action="store_true", help="print Markdown tables for results/README.md")
    ap.add_argument("--findings-md", action="store_true",
                    help="print the generated findings as Markdown (results/README.md's findings section)")
    figures.add_svg_option(ap)
    args = ap.parse_args(argv)
    figures.write_svg(args.svg)
    if not os.path.isdir(args.results):
        errors.fail(f"{args.results}: not a folder")
    if args.link and args.embed:
        errors.fail("--link and --embed: choose one")
    if args.margin is not None and not (0 < args.margin < 10):
        errors.fail(f"--margin: {args.margin:g} is not a margin (give a number between 0 and 10, e.g. 0.10 for 10 %)")
    study = args.study or default_study(args.results)
    if args.quick is not None and not os.path.isfile(args.quick):
        errors.fail(f"--quick: {args.quick}: no such file")
    if args.study is not None and not os.path.isfile(args.study):
        errors.fail(f"--study: {args.study}: no such file")
    try:
        if args.findings_md:
            if study is None:
                errors.fail(f"{args.results}: no study/study.csv or study.csv in it: give --study")
            print(findings_markdown(study, args.margin))
            return 0
        if args.tables:
            if study is None:
                print(f"note: no study CSV in {args.results}: only the convergence table", file=sys.stderr)
            tables(args.results, study)
            return 0
        if study is None:
            errors.fail(f"{args.results}: no study/study.csv or study.csv in it: give --study")
        path = build_report(args.results, study, args.charts, args.images, args.label, embed=args.embed,
                            draw=not args.reuse_charts, margin=args.margin, quick=args.quick)
    except errors.InputError as e:
        errors.fail(str(e))
    print(f"wrote {path}")
    return 0
