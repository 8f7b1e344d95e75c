"""An animated image of a short loop of frames (definitions docs/science.md "Motion"): for one
scene, each method's frames beside the reference's, the signed error of each frame against that frame's
reference, and each frame's error (the mean squared difference over pixels and channels) written on it.

Frames are EXR files NAME_0000.exr, NAME_0001.exr, ... as `raytracer -frames F -motion dx,dy -output NAME.exr`
writes them (results/motion/make_study.sh), read with io/exr.py (oiiotool). Each frame's error is the
library's, not computed again here: `imgdiff NAME_t.exr REF_t.exr` (its mse line) for every method and frame,
gathered in the --errors CSV (name,frame,mse; make_study.sh writes it). Writes an animated PNG (Pillow, Debian's
python3-pil) and beside it a CSV of the errors (method, frame, mse), which the report's motion section shows
(report/motion.py).

  python3 -m analysis.aliaslab_analysis.charts.motion_loop --frames DIR --reference ref --errors DIR/errors.csv
      --methods box=box r 0.5,gauss=gaussian r 1.5 --out results/motion/loop.png"""
import argparse
import csv
import glob
import os
import sys

import numpy as np

from ..io import errors
from ..io.exr import read_exrs

SCALE = 2           # pixels per image pixel in the animation (nearest neighbour)
ERROR_RANGE = 0.2   # the signed error map's full scale (red positive, blue negative)
FRAME_MS = 300


def frame_paths(folder, name):
    """The frames of NAME in order (NAME_0000.exr, ...); InputError when there are none."""
    paths = sorted(glob.glob(os.path.join(folder, glob.escape(name) + "_[0-9][0-9][0-9][0-9].exr")))
    if not paths:
        raise errors.InputError(f"{folder}: no frames {name}_0000.exr ... (raytracer -frames F -output {name}.exr)")
    return paths


def read_errors(path, names, frames):
    """{name: [mse of frame 0, 1, ...]} from the library's errors CSV (name,frame,mse); InputError naming the file
    and line for a bad value, and the file for a missing or repeated (name, frame)."""
    out = {n: [None] * frames for n in names}
    try:
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
    except OSError as e:
        raise errors.InputError(f"{path}: cannot read: {e.strerror or e}") from e
    if not rows or rows[0] != ["name", "frame", "mse"]:
        raise errors.InputError(f"{path}: line 1: expected the header name,frame,mse")
    for line, r in enumerate(rows[1:], start=2):
        if not r:
            continue
        try:
            name, t, mse = r[0], int(r[1]), float(r[2])
        except (ValueError, IndexError):
            raise errors.InputError(f"{path}: line {line}: expected name,frame,mse, found {','.join(r)!r}") from None
        if name not in out:
            continue
        if not 0 <= t < frames or out[name][t] is not None or not np.isfinite(mse):
            raise errors.InputError(f"{path}: line {line}: frame {t} of {name}: out of range, repeated or not finite")
        out[name][t] = mse
    for n, v in out.items():
        if None in v:
            raise errors.InputError(f"{path}: no error for frame {v.index(None)} of {n} (imgdiff's mse per frame)")
    return out


def display(image):
    """Linear radiance to 8-bit sRGB (clipped to [0, 1])."""
    x = np.clip(image[..., :3], 0.0, 1.0)
    s = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
    return (s * 255 + 0.5).astype(np.uint8)


def error_map(diff):
    """Signed error (mean over channels) as white -> red (positive) / blue (negative), full at ERROR_RANGE."""
    e = np.clip(diff[..., :3].mean(axis=2) / ERROR_RANGE, -1, 1)
    out = np.full(e.shape + (3,), 255.0)
    pos, neg = np.maximum(e, 0), np.maximum(-e, 0)
    out[..., 1] -= 255 * (pos + neg)
    out[..., 2] -= 255 * pos
    out[..., 0] -= 255 * neg
    return out.astype(np.uint8)


def compose(panels, labels):
    """One frame of the animation: the panels side by side, each scaled SCALE times, its label above it."""
    from PIL import Image, ImageDraw
    h, w = panels[0].shape[:2]
    pad, text = 4, 14
    canvas = Image.new("RGB", (len(panels) * (w * SCALE + pad) + pad, h * SCALE + text + 2 * pad), "white")
    draw = ImageDraw.Draw(canvas)
    for k, (p, label) in enumerate(zip(panels, labels)):
        x = pad + k * (w * SCALE + pad)
        canvas.paste(Image.fromarray(p).resize((w * SCALE, h * SCALE), Image.NEAREST), (x, text + pad))
        draw.text((x, 2), label, fill="black")
    return canvas


def write_loop(folder, reference, methods, out, errors_csv):
    """Reads the frames and their errors, writes the animated PNG `out` and out's .csv (method, frame, mse); returns
    the rows."""
    ref_paths = frame_paths(folder, reference)
    refs = read_exrs(ref_paths)
    measured = read_errors(errors_csv, [name for name, _ in methods], len(ref_paths))
    shown, rows = [], []
    for name, label in methods:
        paths = frame_paths(folder, name)
        if len(paths) != len(ref_paths):
            raise errors.InputError(f"{folder}: {len(paths)} frames of {name}, {len(ref_paths)} of {reference}")
        images = read_exrs(paths)
        errs = measured[name]
        rows += [(label, t, e) for t, e in enumerate(errs)]
        shown.append((label, images, errs))
    frames = []
    for t, r in enumerate(refs):
        panels, labels = [display(r)], [f"reference, frame {t}"]
        for label, images, errs in shown:
            panels += [display(images[t]), error_map(images[t] - r)]
            labels += [label, f"error {errs[t]:.2e}"]
        frames.append(compose(panels, labels))
    tmp = out + ".partial.png"
    frames[0].save(tmp, format="PNG", save_all=True, append_images=frames[1:], duration=FRAME_MS, loop=0,
                   optimize=True)
    os.replace(tmp, out)
    with open(os.path.splitext(out)[0] + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["method", "frame", "mse"])
        w.writerows((label, t, f"{e:.9g}") for label, t, e in rows)
    return rows


def main(argv=None):
    p = argparse.ArgumentParser(prog="motion_loop", description=__doc__.split("\n\n")[0])
    p.add_argument("--frames", required=True, help="folder of the EXR frames")
    p.add_argument("--reference", required=True, help="NAME of the reference frames (NAME_0000.exr, ...)")
    p.add_argument("--methods", required=True, help="NAME=label pairs, comma-separated")
    p.add_argument("--errors", required=True, help="CSV name,frame,mse: imgdiff's mse of each frame against the "
                   "reference's")
    p.add_argument("--out", required=True, help="the animated PNG (its .csv is written beside it)")
    a = p.parse_args(argv)
    methods = []
    for item in a.methods.split(","):
        name, _, label = item.partition("=")
        if not name or not label:
            p.error(f"--methods: expected NAME=label, found '{item}'")
        methods.append((name, label))
    try:
        rows = write_loop(a.frames, a.reference, methods, a.out, a.errors)
    except errors.InputError as e:
        print(f"motion_loop: {e}", file=sys.stderr)
        return 2
    print(f"motion_loop: {len(rows)} frame errors -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
