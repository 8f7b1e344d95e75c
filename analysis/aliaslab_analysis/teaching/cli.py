"""The `teaching` command: the teaching strand (build.py) from a study's CSV and the images the `viewer` command
rendered and exported, written as RESULTS/viewer/teaching.html for the page to show.

  /usr/bin/python3 -m analysis viewer results --study results/presented/study.csv.gz --raytracer build/bin/raytracer
  /usr/bin/python3 -m analysis teaching results --study results/presented/study.csv

The chosen configurations are the viewer's (viewer/plan.py, with the same --flip-seeds), read from --work."""
import argparse
import os

from ..io import errors, study_csv
from ..viewer.plan import Plan
from . import build


def main(argv=None, prog=None):
    ap = argparse.ArgumentParser(prog=prog, description="Build the teaching strand of a study's page from the "
                                 "viewer's renders (run `viewer` first)")
    ap.add_argument("results", help="folder of the page; writes RESULTS/viewer/teaching.html")
    ap.add_argument("--study", required=True, help="study CSV (its references/ manifests beside it)")
    ap.add_argument("--cache", help="reference cache folder holding the manifests' keys (default: the manifests' "
                    "own paths)")
    ap.add_argument("--work", default=os.path.join("results", "cache", "viewer"),
                    help="folder of the viewer's rendered EXR images (default %(default)s)")
    ap.add_argument("--flip-seeds", type=int, default=2, help="the viewer's --flip-seeds (default %(default)s)")
    args = ap.parse_args(argv)
    if not os.path.isfile(args.study):
        errors.fail(f"--study: {args.study}: no such file")
    if args.flip_seeds < 1:
        errors.fail("--flip-seeds: must be at least 1")
    out = os.path.join(args.results, "viewer")
    if not os.path.isdir(out):
        errors.fail(f"{out}: no such folder (run `python3 -m analysis viewer {args.results} ...` first)")
    try:
        df, notes = study_csv.load_study(args.study)
        path = build.build(args.results, args.study, df, Plan(df, args.flip_seeds, notes), args.work, args.cache,
                           out)
    except errors.InputError as e:
        errors.fail(str(e))
    print(f"wrote {path}")
    return 0
