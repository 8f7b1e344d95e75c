"""The viewer's data: one JavaScript file per scene, RESULTS/viewer/<scene>.js, loaded by a <script> element when
the reader opens that scene (a page opened from file:// may not read files with fetch, and Chromium taints a canvas
drawn from a file:// image; images from data: URIs it does not taint). Each file calls
ALIASLAB_VIEWER_ADD(scene data) with:

  crop      {x, y, size, how}: the window where the methods differ most (plan.crop_window over set A's seed-0
            images at the lowest spp: the largest summed variance across methods)
  images    id -> {w, h, c, bits, lo, hi, src[, src2]} (ids short numbers; equal entries stored once): PNG data URIs holding one image's values (one channel
            when R = G = B, as in the grey scenes, else three), value = lo + q (hi - lo) / (2^bits - 1) with q the
            stored integer: 8 bits for a method's image and the references, 16 bits for the targets' crops (the
            error is taken against them) (png_entry);
            lo, hi the image's own minimum and maximum, so the step is stated per image
  configs   per configuration: sampler, spp, filter, radius, the seeds rendered, its image ids (crop per seed;
            the whole image of seed 0 only for the grid (uniform) at the lowest spp with set A's filter: the
            size budget), its own reference and its CSV rows, one per target: the CSV's values of the columns
            rowColumns (ROW_COLUMNS present in the CSV), in that order; flip: {primary target: the FLIP map's id}
  targets   the target images (crop and whole); refs: each filter x radius's own reference G
  scales    the signed error's colour scale per (spp, target): the 99th percentile of |I_0 - T| (the mean over
            the channels) over set A's methods at that spp in the crop
  verified  every image's per-seed mse_target recomputed from the EXRs against the CSV's mse_target_seeds

RESULTS/viewer/index.json says what was chosen (plan.describe()) and the verification."""
import base64
import io
import json
import os

import numpy as np
from PIL import Image

from .. import errors, figures
from .exr import read_exr, read_exrs
from .flip import flip_maps, map_path
from .plan import crop_window, image_stem

ROW_COLUMNS = ("mse_target", "mse_target_se", "aliasing", "noise", "blur", "cross", "flip", "flagged", "deterministic",
               "cpu_ms")  # the CSV columns shown beside an image
WHOLE = ("uniform",)  # the samplers whose whole image is stored (the size budget: the grid, where it aliases)
FLIP_TARGETS = 1  # FLIP maps against the primary target only (imgdiff's time, about 0.5 s a map, and the size)
TOLERANCE = 1e-5  # relative: the EXR images against the sweep's per-seed mse_target (float images, double sums)


def crop_size(width, height):
    return int(max(8, min(24, min(width, height) // 2)))


def encode(q, mode):
    buf = io.BytesIO()
    Image.fromarray(q.astype(np.uint8), mode).save(buf, "PNG", optimize=True)
    return "data:image/png;base64," + base64.b64encode(buf.getvalue()).decode("ascii")


def png_entry(values, bits, scale=None):
    """An image entry {w, h, c, bits, lo, hi, src[, src2]} of an (h, w, c) array (c = 1 grey or 3 colour)
    quantised to `bits` between its own minimum and maximum (or the fixed (lo, hi) `scale`, values clipped to it):
    8 bits in a grey or RGB PNG; 16 bits grey in one RGB
    PNG (red the high byte, green the low byte), colour in two RGB PNGs (src the high bytes, src2 the low)."""
    v = np.nan_to_num(np.asarray(values, dtype=np.float64), nan=0.0, posinf=0.0, neginf=0.0)
    h, w, c = v.shape
    lo, hi = (float(v.min()), float(v.max())) if scale is None else (float(scale[0]), float(scale[1]))
    v = np.clip(v, lo, hi)
    top = (1 << bits) - 1
    q = np.zeros(v.shape, dtype=np.int64) if hi <= lo else np.rint((v - lo) / (hi - lo) * top).astype(np.int64)
    e = {"w": int(w), "h": int(h), "c": int(c), "bits": bits, "lo": lo, "hi": hi}
    if bits == 8:
        e["src"] = encode(q[..., 0], "L") if c == 1 else encode(q, "RGB")
    elif c == 1:
        e["src"] = encode(np.stack([q[..., 0] >> 8, q[..., 0] & 255, np.zeros_like(q[..., 0])], axis=-1), "RGB")
    else:
        e["src"], e["src2"] = encode(q >> 8, "RGB"), encode(q & 255, "RGB")
    return e


def decode(entry):
    """The (h, w, c) values an image entry stores (the inverse of png_entry; the tests use it)."""
    def pixels(src):
        return np.asarray(Image.open(io.BytesIO(base64.b64decode(src.split(",", 1)[1])))).astype(np.int64)
    a = pixels(entry["src"])
    if entry["bits"] == 8:
        q = a[..., None] if a.ndim == 2 else a[..., :3]
    elif entry["c"] == 1:
        q = ((a[..., 0] << 8) + a[..., 1])[..., None]
    else:
        q = (a[..., :3] << 8) + pixels(entry["src2"])[..., :3]
    top = (1 << entry["bits"]) - 1
    return entry["lo"] + q * (entry["hi"] - entry["lo"]) / top


def channels(img):
    """The image's channels as stored: one when R, G and B are equal (the grey scenes), else three."""
    if img.shape[2] >= 3 and not (np.array_equal(img[..., 0], img[..., 1]) and np.array_equal(img[..., 0], img[..., 2])):
        return img[..., :3]
    return img[..., :1]


def row_values(r):
    out = {}
    for c in ROW_COLUMNS:
        if c not in r:
            continue
        v = r[c]
        if c == "mse_target_seeds":
            out[c] = [float(x) for x in str(v).split(";") if x]
        elif c in ("flagged", "deterministic"):
            out[c] = int(v)
        else:
            out[c] = None if not np.isfinite(float(v)) else float(v)
    return out


class SceneExport:
    def __init__(self, study, df, plan, scene, work, cache, imgdiff=None):
        self.scene, self.plan = scene, plan
        self.sd = df[(df["scene"] == scene) & (df["reconstruction"].astype(str) == "weighted")
                     & (df["prefilter"].astype(str).isin(["none", ""]))]
        self.width, self.height = int(self.sd["width"].iloc[0]), int(self.sd["height"].iloc[0])
        self.work = os.path.join(work, figures.slug(scene) + f"-{self.width}x{self.height}")
        mpath = os.path.join(os.path.dirname(os.path.abspath(study)), "references", f"{scene}.json")
        with open(mpath, encoding="utf-8") as f:
            self.manifest = json.load(f)
        self.mdir, self.cache = os.path.dirname(mpath), cache
        self.targets = [str(t) for t in dict.fromkeys(self.sd["target"].astype(str))]
        self.images, self.checked, self.worst, self.imgdiff, self.same = {}, 0, 0.0, imgdiff, {}
        self.describe = {}
        self.row_columns = [c for c in ROW_COLUMNS if c in self.sd.columns]

    def whole(self, c):
        """Whether the whole image of a configuration is stored (the size budget): the grid (uniform) at the
        lowest spp with set A's filter (the references' whole images are not stored; the primary target's is)."""
        return "A" in c["sets"] and c["spp"] == self.plan.levels[0] and c["sampler"] in WHOLE

    def has_reference(self, filt, radius):
        return any(e["filter"] == filt and abs(float(e["radius"]) - radius) < 1e-9 for e in self.manifest["filters"])

    def reference(self, filt, radius):
        path = self.reference_path(filt, radius)
        img = channels(read_exr(path))
        diff = read_exr(path[:-4] + ".diff.exr")
        return img, float(np.mean(diff ** 2)), self.describe[(filt, radius)]

    def reference_path(self, filt, radius):
        for e in self.manifest["filters"]:
            if e["filter"] == filt and abs(float(e["radius"]) - radius) < 1e-9:
                self.describe[(filt, radius)] = e.get("describe", f"{filt} r={radius:g}")
                return os.path.join(self.cache, e["key"] + ".exr") if self.cache else \
                    os.path.normpath(os.path.join(self.mdir, e["image"]))
        errors.fail(f"{self.scene}: no reference {filt} r={radius:g} in its manifest")

    def add(self, key, values, bits, region, scale=None):
        """Stores an image entry; an entry equal to one already stored (a deterministic sampler's seeds) is
        stored once: the id returned is the first one's."""
        x, y, n = self.crop
        part = values[y:y + n, x:x + n] if region == "crop" else values
        e = png_entry(part, bits, scale)
        same = json.dumps(e, sort_keys=True)
        if same not in self.same:  # a short id (the size budget); `key` says what it is in this comment only
            self.same[same] = str(len(self.images))
            self.images[self.same[same]] = e
        return self.same[same]

    def flip_crops(self, configs):
        """{config index: {target: image id}}: the FLIP map of each configuration's seed-0 image against the
        primary target (FLIP_TARGETS; imgdiff over the whole image, the crop stored, 8 bits over the fixed scale
        FLIP 0..1)."""
        if not self.imgdiff:
            return {}
        pairs, where = [], []
        for i, c in enumerate(configs):
            image = os.path.join(self.work, image_stem(c, 0) + ".exr")
            for t in self.targets[:FLIP_TARGETS]:
                f, r = t.split(":")
                pairs.append((image, self.reference_path(f, float(r)), map_path(image, t)))
                where.append((i, t))
        out = {}
        for (i, t), m in zip(where, flip_maps(self.imgdiff, pairs, (self.width, self.height))):
            base = image_stem(configs[i], 0)
            out.setdefault(i, {})[t] = self.add(f"{base}-flip-{t}-crop", m[..., None], 8, "crop", (0.0, 1.0))
        return out

    def run(self):
        plan = self.plan
        target_imgs, target_var = {}, {}
        for t in self.targets:
            f, r = t.split(":")
            target_imgs[t], target_var[t], _ = self.reference(f, float(r))
        seeds, configs, self.missing = {}, [], []
        for c in plan.configs[self.scene]:  # what was rendered: seed 0 required, flip-book seeds where present
            have = [k for k in c["seeds"] if os.path.isfile(os.path.join(self.work, image_stem(c, k) + ".exr"))]
            if 0 not in have:
                self.missing.append(image_stem(c, 0))
                continue
            configs.append(dict(c, seeds=have))
            for k in have:
                seeds[(image_stem(c, 0), k)] = os.path.join(self.work, image_stem(c, k) + ".exr")
        keys = list(seeds)
        for key, img in zip(keys, read_exrs([seeds[k] for k in keys])):
            seeds[key] = channels(img)
        if not configs:
            errors.fail(f"{self.scene}: no rendered image in {self.work} (run without --no-render)")
        # the crop: where set A's seed-0 images at the lowest spp differ most
        n = crop_size(self.width, self.height)
        stack = [seeds[(image_stem(c, 0), 0)] for c in configs if "A" in c["sets"] and c["spp"] == plan.levels[0]]
        stack = stack or [seeds[(image_stem(c, 0), 0)] for c in configs]
        cx, cy = crop_window(np.array([a.mean(axis=2) for a in stack]), n)
        self.crop = (cx, cy, n)
        out_configs, refs = [], {}
        scales, flips = {}, self.flip_crops(configs)
        for i, c in enumerate(configs):
            rows = self.sd[(self.sd["sampler"] == c["sampler"]) & (self.sd["spp"] == c["spp"])
                           & (self.sd["filter_name"] == c["filter"]) & (self.sd["radius"] == c["radius"])]
            per_target, per_seed = {}, {}
            for _, r in rows.iterrows():
                vals = row_values(r)
                per_target[str(r["target"])] = [vals[k] for k in self.row_columns]
                per_seed[str(r["target"])] = [float(x) for x in str(r["mse_target_seeds"]).split(";") if x]
            base = image_stem(c, 0)[:-len("-seed0")]
            for k in c["seeds"]:
                img = seeds[(image_stem(c, 0), k)]
                for t in self.targets:
                    mine = float(np.mean((img - target_imgs[t]) ** 2)) - target_var[t]
                    theirs = per_seed[t][k]
                    rel = abs(mine - theirs) / max(abs(theirs), 1e-12)
                    self.worst, self.checked = max(self.worst, rel), self.checked + 1
                    if rel > TOLERANCE:
                        errors.fail(f"{self.scene}: {base} seed {k}: mse_target against {t} from the image "
                                    f"{mine:.9g}, the CSV says {theirs:.9g}: the image is not the one measured")
            ref_key = f"{c['filter']}|{c['radius']:g}"
            whole = None
            if self.whole(c):
                whole = self.add(f"{base}-seed0-whole", seeds[(image_stem(c, 0), 0)], 8, "whole")
            if ref_key not in refs:
                g, _, describe = self.reference(c["filter"], c["radius"])
                refs[ref_key] = {"crop": self.add(f"ref-{ref_key}-crop", g, 8, "crop"), "describe": describe}
            crops = {str(k): self.add(f"{base}-seed{k}-crop", seeds[(image_stem(c, 0), k)], 8, "crop")
                     for k in c["seeds"]}
            out_configs.append({"id": f"{c['sampler']}|{c['spp']}|{c['filter']}|{c['radius']:g}",
                                "sampler": c["sampler"], "spp": c["spp"], "filter": c["filter"],
                                "radius": c["radius"], "sets": c["sets"], "seeds": c["seeds"], "crop": crops,
                                "whole": whole, "ref": ref_key, "rows": per_target, "flip": flips.get(i, {})})
            if "A" in c["sets"]:
                e0 = seeds[(image_stem(c, 0), 0)][cy:cy + n, cx:cx + n]
                for t in self.targets:  # the error shown: the mean over the channels of I - T
                    err = np.mean(e0 - target_imgs[t][cy:cy + n, cx:cx + n], axis=2)
                    scales.setdefault(f"{c['spp']}|{t}", []).append(np.abs(err))
        scale = {k: float(np.percentile(np.concatenate([a.ravel() for a in v]), 99)) for k, v in scales.items()}
        targets = {t: {"crop": self.add(f"target-{t}-crop", target_imgs[t], 16, "crop")} for t in self.targets}
        targets[self.targets[0]]["whole"] = self.add(f"target-{self.targets[0]}-whole", target_imgs[self.targets[0]],
                                                     8, "whole")  # the primary target's only (size budget)
        return {"scene": self.scene, "width": self.width, "height": self.height,
                "crop": {"x": cx, "y": cy, "size": n,
                         "how": f"the {n} x {n} window with the largest summed variance across the methods of set A "
                                f"(seed 0, {plan.levels[0]} spp)"},
                "wholeHow": f"{', '.join(WHOLE)} at {plan.levels[0]} spp, {plan.filter} r={plan.radius:g}",
                "levels": plan.levels, "targets": self.targets, "primary": self.targets[0], "configs": out_configs,
                "refs": refs, "targetImages": targets, "rowColumns": self.row_columns, "scales": scale,
                "flipHow": "per-pixel LDR-FLIP of the seed-0 image against the primary target (imgdiff "
                           "--flip-output, the "
                           "flip column's map; its mean over the whole image and the seeds is the CSV's flip), "
                           "crop only, 8 bits over 0..1",
                "scaleHow": "99th percentile of |I - T| over the crop of every sampler of set A at that spp (seed 0)",
                "plan": plan.describe(), "not_rendered": self.missing, "verified": {"images": len(seeds), "comparisons": self.checked,
                                                      "max_relative_difference": self.worst},
                "images": self.images}


def write_js(path, data):
    tmp = path + ".partial"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write("ALIASLAB_VIEWER_ADD(" + json.dumps(data, separators=(",", ":")) + ");\n")
    os.replace(tmp, path)


def export_study(results, study, df, plan, scenes, work, cache=None, quiet=False, imgdiff=None):
    out = os.path.join(results, "viewer")
    errors.prepare_out(out, "RESULTS/viewer")
    index = {"study": os.path.relpath(os.path.abspath(study), os.path.abspath(results)).replace(os.sep, "/"),
             "plan": plan.describe(), "scenes": {}}
    for scene in scenes:
        data = SceneExport(study, df, plan, scene, work, cache, imgdiff).run()
        path = os.path.join(out, figures.slug(scene) + ".js")
        write_js(path, data)
        index["scenes"][scene] = {"file": os.path.basename(path), "bytes": os.path.getsize(path),
                                  "crop": data["crop"], "verified": data["verified"]}
        if not quiet:
            print(f"{scene}: {os.path.getsize(path) / 1e3:.0f} kB, {data['verified']['comparisons']} per-seed "
                  f"mse_target values recomputed, largest relative difference "
                  f"{data['verified']['max_relative_difference']:.2g}", flush=True)
    with open(os.path.join(out, "index.json"), "w", encoding="utf-8") as f:
        json.dump(index, f, indent=1)
    return out
