"""The served viewer's x-t slice (docs/science.md "Motion", "Looking at it: x-t slices"):

  xt?scene&sampler&spp&filter&radius&seed&row&frames
      renders F frames (2 .. MAX_FRAMES, default DEFAULT_FRAMES) of that CSV row's configuration and seed with a
      moving camera, registered to the content (xt_slice.render_frames: raytracer -frames -motion -register), and
      the primary target's frames (its filter and radius, the reference's sampler and seed at up to TARGET_SPP
      samples per pixel: the reference's own count would take minutes a frame), and returns the slices of image
      row `row` (from the top) side by side as xt_slice.compose draws them: {png: a data URI, labels, row, frames,
      motion, margin, paths: {"target": [frame paths], "method": [...]}}.
The motion is the study's (its motion_dx, motion_dy) when its CSV has frames, else DEFAULT_MOTION pixels per
frame. Frames go to the work folder (kept: a second request for the same slice reuses them)."""
import base64
import io
import os

from ..io import errors
from ..charts import figures
from . import xt_slice
from ..io.exr import read_exrs
from .plan import image_stem
from .view import key_id

DEFAULT_FRAMES, MAX_FRAMES = 16, 64
DEFAULT_MOTION = (0.25, 0.0)  # pixels per frame, as the committed motion study moves
TARGET_SPP = 256


def motion_of(df):
    """The study's motion (dx, dy) when its CSV has frames, else DEFAULT_MOTION."""
    if "frames" in df.columns and "motion_dx" in df.columns:
        moving = df[df["frames"].astype(float) > 1]
        if not moving.empty:
            return float(moving["motion_dx"].iloc[0]), float(moving["motion_dy"].iloc[0])
    return DEFAULT_MOTION


def frames_of(e, cfg, seed, frames, motion, raytracer, work):
    """The registered frames of one configuration, rendered unless already in the work folder."""
    folder = os.path.join(work, f"xt-f{frames}-m{motion[0]:g}_{motion[1]:g}")
    os.makedirs(folder, exist_ok=True)
    out = os.path.join(folder, image_stem(cfg, seed) + ".exr")
    paths = [f"{out[:-4]}_{t:04d}.exr" for t in range(frames)]
    if all(os.path.isfile(p) for p in paths):
        return paths
    return xt_slice.render_frames(raytracer, e.manifest, (e.width, e.height), cfg, seed, frames, motion, out)


def xt(served, q):
    e = served.scene(q["scene"])
    c = {"sampler": q["sampler"], "spp": int(q["spp"]), "filter": q["filter"], "radius": float(q["radius"])}
    seed = int(q.get("seed", 0))
    if not e.rows_of(c)[1]:
        raise errors.InputError(f"{q['scene']}: no row {key_id((c['sampler'], c['spp'], c['filter'], c['radius']))} "
                                f"in {served.study}")
    frames = int(q.get("frames", DEFAULT_FRAMES))
    if not 2 <= frames <= MAX_FRAMES:
        raise errors.InputError(f"frames {frames}: from 2 to {MAX_FRAMES}")
    row = int(q.get("row", e.height // 2))
    if not 0 <= row < e.height:
        raise errors.InputError(f"row {row}: the image has rows 0 .. {e.height - 1} (from the top)")
    motion = motion_of(served.df)
    m = xt_slice.margin(frames, *motion)
    if 2 * m >= e.width:
        raise errors.InputError(f"frames {frames}: the registration margin ({m} px a side) leaves no column of "
                                f"{e.width}; ask for fewer frames")
    filt, radius = xt_slice.parse_target(e.targets[0])
    spp = min(int(e.manifest["spp"]), TARGET_SPP)
    target = {"sampler": e.manifest["sampler"], "spp": spp, "filter": filt, "radius": radius}
    work = os.path.join(served.work, figures.slug(e.scene) + f"-{e.width}x{e.height}")
    with served.lock:
        paths = {"target": frames_of(e, target, int(e.manifest["seed"]), frames, motion, served.raytracer, work),
                 "method": frames_of(e, c, seed, frames, motion, served.raytracer, work)}
    slices = [xt_slice.slice_rows(read_exrs(paths[k]), row)[..., :3] for k in ("target", "method")]
    labels = [(f"target: {filt} r={radius:g}", f"{target['sampler']} {spp} spp"),
              (f"{c['sampler']} {c['spp']} spp {c['filter']} r={c['radius']:g}", f"seed {seed}")]
    buf = io.BytesIO()
    xt_slice.compose(slices, labels, (m, e.width - m)).save(buf, format="PNG")
    return {"png": "data:image/png;base64," + base64.b64encode(buf.getvalue()).decode("ascii"),
            "labels": labels, "row": row, "frames": frames, "motion": list(motion), "margin": m, "paths": paths,
            "scale": list(xt_slice.scales(e.width - 2 * m, frames)),
            "origin": list(xt_slice.panel_origin(1, e.width - 2 * m, frames, 2))}
