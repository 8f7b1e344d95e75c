"""The `viewer` command: renders the chosen configurations of a study (plan.py) with the raytracer into a work
folder and exports the viewer's data beside the page (export.py).

  /usr/bin/python3 -m analysis viewer results --study results/presented/study.csv.gz \\
      --raytracer build/bin/raytracer [--imgdiff build/bin/imgdiff] [--work results/cache/viewer] [--jobs 2]

writes RESULTS/viewer/<scene>.js (one per scene, loaded by the page when that scene is opened) and
RESULTS/viewer/index.json (what was chosen and how); the FLIP maps (imgdiff) are kept in the work folder too;
`teaching` then builds the teaching strand from these renders, and `report` shows the viewer when
RESULTS/viewer exists. With --serve [--port N] [--exr FILE ...] it renders
nothing first: it serves RESULTS on localhost and renders any CSV row on request (serve.py)."""
import argparse
import json
import os

from ..io import errors, study_csv
from ..charts import figures
from . import export, render, serve
from .flip import imgdiff_beside
from .plan import WHOLE, Plan


def manifest_of(study, scene):
    path = os.path.join(os.path.dirname(os.path.abspath(study)), "references", f"{scene}.json")
    if not os.path.isfile(path):
        errors.fail(f"{path}: no reference manifest for scene {scene} (written by the sweep beside its CSV)")
    with open(path, encoding="utf-8") as f:
        return json.load(f), path


def main(argv=None, prog=None):
    ap = argparse.ArgumentParser(prog=prog, description="Render and export the comparison viewer's data of a study")
    ap.add_argument("results", help="folder of the page; the data goes to RESULTS/viewer")
    ap.add_argument("--study", required=True, help="study CSV (its references/ manifests beside it)")
    ap.add_argument("--raytracer", default="build/bin/raytracer", help="the raytracer program (default %(default)s)")
    ap.add_argument("--imgdiff", help="the imgdiff program computing the FLIP maps (default: beside --raytracer)")
    ap.add_argument("--cache", help="reference cache folder holding the manifests' keys (default: the manifests' "
                    "own paths)")
    ap.add_argument("--work", default=os.path.join("results", "cache", "viewer"),
                    help="folder of the rendered EXR images, kept between runs (default %(default)s)")
    ap.add_argument("--jobs", type=int, default=2, help="raytracer processes at once (default %(default)s)")
    ap.add_argument("--scenes", help="comma list of scenes (default: every scene of the study)")
    ap.add_argument("--flip-seeds", type=int, default=2, help="seeds rendered for the flip-book (default %(default)s)")
    ap.add_argument("--no-render", action="store_true", help="export from the images already rendered (a "
                    "configuration's missing flip-book seeds are left out; seed 0 is required)")
    ap.add_argument("--render-only", action="store_true", help="render the images, export nothing")
    ap.add_argument("--whole", choices=sorted(WHOLE), default="answer", help="whose whole image and whole FLIP "
                    "maps are stored (the crops are stored for all): " + "; ".join(f"{k}: {v}" for k, v in
                                                                               sorted(WHOLE.items())) +
                    " (default %(default)s; 'all' is about 18 MB per 256 x 256 scene)")
    ap.add_argument("--serve", action="store_true", help="serve RESULTS (the page and its viewer) on "
                    "http://127.0.0.1:PORT and render any CSV row on request (serve.py); renders nothing first")
    ap.add_argument("--port", type=int, default=8765, help="--serve's port (0: any free one; default %(default)s)")
    ap.add_argument("--exr", nargs="*", default=[], help="with --serve: EXR files of your own the viewer can load "
                    "beside the study's (the scene's size)")
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args(argv)
    if not os.path.isfile(args.study):
        errors.fail(f"--study: {args.study}: no such file")
    if not (os.path.isfile(args.raytracer) and os.access(args.raytracer, os.X_OK)):
        errors.fail(f"--raytracer: {args.raytracer}: not an executable program")
    if args.flip_seeds < 1:
        errors.fail("--flip-seeds: must be at least 1")
    if args.jobs < 1:
        errors.fail("--jobs: must be at least 1")
    for p in args.exr:
        if not os.path.isfile(p):
            errors.fail(f"--exr: {p}: no such file")
    if args.serve:
        df, _ = study_csv.load_study(args.study)
        imgdiff = args.imgdiff or imgdiff_beside(args.raytracer)
        return serve.serve(serve.Served(args.results, args.study, df, args.raytracer,
                                        imgdiff if os.path.isfile(imgdiff) else None, args.work, args.cache,
                                        args.exr), args.port)
    try:
        df, notes = study_csv.load_study(args.study)
        plan = Plan(df, args.flip_seeds, notes)
        plan.whole = args.whole
        scenes = sorted(plan.configs)
        if args.scenes:
            wanted = args.scenes.split(",")
            missing = [s for s in wanted if s not in plan.configs]
            if missing:
                errors.fail(f"--scenes: {', '.join(missing)} not in {args.study}")
            scenes = wanted
        jobs = []
        for scene in scenes:
            manifest, _ = manifest_of(args.study, scene)
            sd = df[df["scene"] == scene]
            size = (int(sd["width"].iloc[0]), int(sd["height"].iloc[0]))
            work = os.path.join(args.work, figures.slug(scene) + f"-{size[0]}x{size[1]}")
            jobs += render.scene_jobs(os.path.abspath(args.raytracer), manifest["scene_path"], size, manifest,
                                      plan.configs[scene], work)
        if not args.quiet:
            print(f"{len(jobs)} images in {args.work}", flush=True)
        if not args.no_render:
            render.render_all(args.raytracer, jobs, args.jobs, args.quiet)
        if args.render_only:
            return 0
        out = export.export_study(args.results, args.study, df, plan, scenes, args.work, args.cache,
                                  quiet=args.quiet, imgdiff=args.imgdiff or imgdiff_beside(args.raytracer))
    except errors.InputError as e:
        errors.fail(str(e))
    print(f"wrote {out}")
    return 0
