"""x-t slices (definitions docs/science.md "Motion"): one image row followed over the frames of
a moving camera, the frames registered to the content, stacked top to bottom (frame 0 at the top).

The frames are rendered by the project's raytracer, `-frames F -motion dx,dy -register`: frame t is written moved
back by t (dx, dy) with the library's band-limited shift (measure/registration.h), so every frame shows frame 0's
content where the content is the same; nothing is registered again here. In the slice, what holds still in the
content's frame (the picture, and a filter's blur, which moves with it) draws vertical streaks; shimmer (aliasing
that turns from frame to frame) crawls or flickers across them, and noise speckles them. Below each slice: its
change, each frame's row minus the mean of the rows (red above, blue below, full at motion_loop.ERROR_RANGE).
Columns within the registration margin (the content entering the picture over the F frames, and the guard of the
interpolation's border error) are left out.

Which rows are shown is chosen from the study CSV by choose(): per scene, the target's own slice; point sampling
(box r = 0.5) on the fixed grid and jittered at the lowest spp (the grid's aliasing is the same in every frame's
sample positions, jitter turns it into noise); the grid's still-best method (lowest mse_target) and its steadiest
(lowest shimmer) at the lowest spp where they differ. Seed 0 of each, as the viewer renders it (viewer/render.py).

  python3 -m analysis.aliaslab_analysis.viewer.xt_slice --study results/motion/study/study.csv --bin build/bin
      --frames 32 --out results/motion/study/xt
writes OUT/xt-SCENE.png per scene and OUT/xt.csv (scene, panel, label, why, the configuration, the row, the
frames and the motion), which the report's motion section shows (report/motion_xt.py)."""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from ..io import errors, study_rows
from ..charts import figures
from ..charts.motion_loop import display, error_map
from ..report.motion import best, motion_rows
from ..io.study_csv import load_study
from . import render
from ..io.exr import read_exrs

GUARD = 8         # measure/registration.h kRegistrationGuard: pixels kept clear of the interpolation's border error
SCALE_X, SCALE_Y = 2, 3  # pixels per image pixel and per frame in the PNG (at least)
MIN_WIDTH, MIN_HEIGHT = 160, 48  # a slice drawn at least this large (a label's width; a few frames still visible)
PAD, TEXT = 6, 12        # gap between panels; height of a line of label
FIELDS = ["scene", "panel", "label", "why", "sampler", "spp", "filter", "radius", "seed", "row", "frames",
          "motion_dx", "motion_dy", "png"]


def margin(frames, dx, dy):
    """Columns (and rows) left out on each side: the content entering over frames 0 .. F - 1, plus GUARD."""
    return math.ceil((frames - 1) * max(abs(dx), abs(dy)) - 1e-9) + GUARD


def slice_rows(images, y):
    """(F, width, channels): row y (counted from the top, as the image is shown) of each frame, frame 0 first."""
    return np.stack([im[y] for im in images])


def parse_target(target):
    """'box:0.5' -> ('box', 0.5): the target's filter and radius (the pixel-area target is box r = 0.5)."""
    name, _, radius = str(target).partition(":")
    try:
        return name, float(radius)
    except ValueError:
        raise errors.InputError(f"target '{target}': expected FILTER:RADIUS (e.g. box:0.5)") from None


def choose(df, target):
    """{scene: [(label, why, sampler, spp, filter, radius)]} of the rows the slices show (module doc), from the
    study's rows with frames against `target`; the target's own slice comes first, as ('target', ...)."""
    rows = motion_rows(df, target)
    if rows is None or rows.empty:
        raise errors.InputError("the study has no rows with frames (sweep --frames F > 1)")
    out = {}
    filt, radius = parse_target(target)
    for scene, sd in rows.groupby("scene", sort=True):
        sd = sd[sd["reconstruction"].astype(str) == "weighted"]
        low = int(sd["spp"].min())
        grid = "uniform" if "uniform" in set(sd["sampler"]) else sorted(sd["sampler"])[0]
        panels = [(f"target: {filt} r={radius:g}", "the reference's samples", None, None, filt, radius)]
        for sampler in (grid, "jittered"):
            if ((sd["sampler"] == sampler) & (sd["spp"] == low) & (sd["filter_name"] == "box")
                    & (np.isclose(sd["radius"].astype(float), 0.5))).any():
                panels.append((f"{sampler} {low} spp box r=0.5", "point sampling",
                               sampler, low, "box", 0.5))
        cells = [(int(spp), cell) for (s, spp), cell in sd.groupby(["sampler", "spp"]) if s == grid]
        pick = next(((spp, c) for spp, c in sorted(cells, key=lambda x: x[0])
                     if best(c, "mse_target") not in (None, best(c, "shimmer"))), None) or min(cells, key=lambda x: x[0])
        spp, cell = pick
        for column, why in (("mse_target", "still-best"), ("shimmer", "steadiest")):
            v = cell[column].astype(float)
            if not np.isfinite(v).any():
                continue
            r = cell.loc[v[np.isfinite(v)].idxmin()]
            key = (grid, spp, str(r["filter_name"]), float(r["radius"]))
            label = f"{grid} {spp} spp {key[2]} r={key[3]:g}"
            if any(p[2:] == key for p in panels):  # the same row twice: one panel, both reasons
                panels = [p if p[2:] != key else (p[0], f"{p[1]}; {why}", *p[2:]) for p in panels]
            else:
                panels.append((label, why, *key))
        out[str(scene)] = panels
    return out


def render_frames(raytracer, manifest, size, cfg, seed, frames, motion, out, register=True):
    """Renders the frames of one configuration (`cfg`: sampler, spp, filter, radius) with `seed`; returns the
    frame paths out_0000.exr, ... (the raytracer's names)."""
    cmd = render.command(raytracer, manifest["scene_path"], size, manifest, cfg, seed, out)
    cmd += ["--frames", str(frames), "--motion", f"{motion[0]:.17g},{motion[1]:.17g}"] + (["--register"] if register else [])
    run = subprocess.run(cmd, capture_output=True, text=True)
    stem = out[:-4]
    paths = [f"{stem}_{t:04d}.exr" for t in range(frames)]
    if run.returncode != 0 or not all(os.path.isfile(p) for p in paths):
        raise errors.InputError(f"{' '.join(cmd)}: {run.stderr.strip()[-400:]}")
    return paths


def scales(width, frames):
    """(pixels per image pixel, pixels per frame) of a slice of `width` columns and `frames` rows in the PNG."""
    return max(SCALE_X, math.ceil(MIN_WIDTH / width)), max(SCALE_Y, math.ceil(MIN_HEIGHT / frames))


def panel_origin(k, width, frames, lines):
    """(x, y) of the top-left pixel of panel k's slice (width columns kept, frames rows) in compose()'s PNG with
    `lines` lines of label."""
    return PAD + k * (width * scales(width, frames)[0] + PAD), TEXT * lines + PAD


def compose(slices, labels, keep):
    """The PNG of one scene: per slice, its label (lines of text), the slice (columns keep[0]:keep[1]) and below it
    its change."""
    from PIL import Image, ImageDraw
    pictures = []
    for s in slices:
        part = s[:, keep[0]:keep[1]]
        pictures.append((display(part), error_map(part - part.mean(axis=0, keepdims=True))))
    f, w = pictures[0][0].shape[:2]
    sx, sy = scales(w, f)
    pw, ph, pad = w * sx, f * sy, PAD
    top = TEXT * max(len(lines) for lines in labels)
    canvas = Image.new("RGB", (len(slices) * (pw + pad) + pad, top + TEXT + 2 * ph + 3 * pad), "white")
    draw = ImageDraw.Draw(canvas)
    for k, ((picture, change), lines) in enumerate(zip(pictures, labels)):
        x, y = panel_origin(k, w, f, len(lines))
        for i, line in enumerate(lines):
            draw.text((x, 2 + i * TEXT), line, fill="black")
        canvas.paste(Image.fromarray(picture).resize((pw, ph), Image.NEAREST), (x, top + pad))
        draw.text((x, top + ph + pad + 2), "change: row - mean of rows", fill="black")
        canvas.paste(Image.fromarray(change).resize((pw, ph), Image.NEAREST), (x, top + TEXT + ph + 2 * pad))
    return canvas


def write_slices(study, raytracer, out, frames, row=None, jobs=2):
    """Chooses, renders and composes every scene's slices; writes OUT/xt-SCENE.png and OUT/xt.csv; returns the
    CSV's rows (dicts)."""
    df, _ = load_study(study)
    target = study_rows.targets(df)[0]  # the primary target
    chosen = choose(df, target)
    os.makedirs(out, exist_ok=True)
    records = []
    with tempfile.TemporaryDirectory(prefix="aliaslab-xt-") as tmp:
        for scene, panels in chosen.items():
            with open(os.path.join(os.path.dirname(os.path.abspath(study)), "references", f"{scene}.json"),
                      encoding="utf-8") as fh:
                manifest = json.load(fh)
            sd = df[df["scene"] == scene]
            size = (int(sd["width"].iloc[0]), int(sd["height"].iloc[0]))
            motion = (float(sd["motion_dx"].iloc[0]), float(sd["motion_dy"].iloc[0]))
            y = size[1] // 2 if row is None else row
            if not 0 <= y < size[1]:
                raise errors.InputError(f"--row {y}: {scene} has rows 0 .. {size[1] - 1}")
            jobs_list = []
            for k, (label, why, sampler, spp, filt, radius) in enumerate(panels):
                cfg = {"sampler": sampler or manifest["sampler"], "spp": spp or int(manifest["spp"]),
                       "filter": filt, "radius": radius}
                seed = int(manifest["seed"]) if sampler is None else 0
                jobs_list.append((k, label, why, cfg, seed))
            with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
                paths = list(pool.map(lambda j: render_frames(raytracer, manifest, size, j[3], j[4], frames, motion,
                                                              os.path.join(tmp, f"{figures.slug(scene)}-{j[0]}.exr")),
                                      jobs_list))
            slices = [slice_rows(read_exrs(p), y)[..., :3] for p in paths]
            m = margin(frames, *motion)
            png = os.path.join(out, f"xt-{figures.slug(scene)}.png")
            compose(slices, [(j[1], j[2]) for j in jobs_list], (m, size[0] - m)).save(png + ".partial.png", optimize=True)
            os.replace(png + ".partial.png", png)
            for k, label, why, cfg, seed in jobs_list:
                records.append(dict(scene=scene, panel=k, label=label, why=why, sampler=cfg["sampler"],
                                    spp=cfg["spp"], filter=cfg["filter"], radius=f"{cfg['radius']:g}", seed=seed,
                                    row=y, frames=frames, motion_dx=f"{motion[0]:g}", motion_dy=f"{motion[1]:g}",
                                    png=os.path.basename(png)))
    with open(os.path.join(out, "xt.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, FIELDS)
        w.writeheader()
        w.writerows(records)
    return records


def main(argv=None):
    p = argparse.ArgumentParser(prog="xt_slice", description=__doc__.split("\n\n")[0])
    p.add_argument("--study", required=True, help="the study CSV (sweep --frames F > 1), its references/ beside it")
    p.add_argument("--bin", default="build/bin", help="folder of the built raytracer")
    p.add_argument("--frames", type=int, default=32, help="frames to render (default 32)")
    p.add_argument("--row", type=int, help="the image row, counted from the top (default: the middle)")
    p.add_argument("--out", required=True, help="folder for xt-SCENE.png and xt.csv")
    a = p.parse_args(argv)
    if a.frames < 2:
        p.error("--frames: at least 2")
    raytracer = os.path.join(a.bin, "raytracer")
    if not os.access(raytracer, os.X_OK):
        p.error(f"--bin: no raytracer in {a.bin} (build it first)")
    try:
        rows = write_slices(a.study, raytracer, a.out, a.frames, a.row)
    except errors.InputError as e:
        print(f"xt_slice: {e}", file=sys.stderr)
        return 2
    print(f"xt_slice: {len(rows)} slices -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
