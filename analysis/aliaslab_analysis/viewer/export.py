"""The viewer's data: two JavaScript files per scene, RESULTS/viewer/<scene>.js, loaded by a <script> element when
the reader opens that scene, and RESULTS/viewer/<scene>_whole.js, loaded the same way only when the reader asks
for a whole image or a FLIP map against a target other than the primary one (a page opened from file:// may not read files with fetch, and Chromium taints a canvas
drawn from a file:// image; images from data: URIs it does not taint). The first file calls
ALIASLAB_VIEWER_ADD(scene data) with:

  crop      {x, y, size, how}: the window where the default view's methods differ most relative to their noise
            (plan.crop_window over their mean images at the lowest spp and the noise of those means: choose_crop)
  default   {cfg, pins, why, target}: the view opened first (answer.default_view: the leading method at the lowest
            spp, the runner-up family's best, jittered at its own best)
  images    id -> {w, h, c, bits, lo, hi, src[, src2]} (ids short numbers; equal entries stored once): PNG data URIs holding one image's values (one channel
            when R = G = B, as in the grey scenes, else three), value = lo + q (hi - lo) / (2^bits - 1) with q the
            stored integer: 8 bits for a method's image and the references, 16 bits for the targets' crops (the
            error is taken against them) (png_entry);
            lo, hi the image's own minimum and maximum, so the step is stated per image
  configs   per configuration: sampler, spp, filter, radius, the seeds rendered, its image ids (crop per seed;
            whole: the whole image of seed 0, 8 bits), its own reference and its CSV rows, one per target: the
            CSV's values of the columns rowColumns (ROW_COLUMNS present in the CSV), in that order; why: the
            answer's reasons it is shown; flip: {primary target: the FLIP map's crop id}, flipWhole: {target:
            the whole FLIP map's id} for every target (seed 0; in the second file)
  targets   the target images (crop and whole); refs: each filter x radius's own reference G (crop and whole)
  wholeFile the second file's name; its ids (prefix "w": every whole image, every whole FLIP map) are not in `images` until it is loaded: it calls
            ALIASLAB_VIEWER_WHOLE(scene, {id: entry}) (WHOLE_DOC)
  scales    the signed error's colour scale per (spp, target): the 99th percentile of |I_0 - T| (the mean over
            the channels) over the answer's methods (sets E, P) at that spp in the crop
  verified  every image's per-seed mse_target recomputed from the EXRs against the CSV's mse_target_seeds

RESULTS/viewer/index.json says what was chosen (plan.describe()) and the verification."""
import json
import os

import numpy as np
from ..io import errors
from ..charts import figures
from .encoding import channels, decode, png_entry  # noqa: F401 (decode: the tests' inverse of png_entry)
from ..io.exr import read_exr, read_exrs
from .flip import flip_maps, map_path
from . import view
from .plan import image_stem
from .view import config_id

ROW_COLUMNS = ("mse_target", "mse_target_se", "aliasing", "noise", "blur", "cross", "flip", "flagged", "deterministic",
               "cpu_ms")  # the CSV columns shown beside an image
WHOLE_DOC = ("whole images (seed 0 of every configuration shown, every own reference, every target; 8 bits over "
             "each image's own range) and the whole FLIP maps against every target")
TOLERANCE = 1e-5  # relative: the EXR images against the sweep's per-seed mse_target (float images, double sums)


def crop_size(width, height):
    return int(max(8, min(24, min(width, height) // 2)))


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
        self.later, self.same_later = {}, {}  # the second file's entries (ids "w0", "w1", ...)
        self.describe = {}
        self.row_columns = [c for c in ROW_COLUMNS if c in self.sd.columns]

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

    def add(self, key, values, bits, region, scale=None, later=None):
        """Stores an image entry; an entry equal to one already stored (a deterministic sampler's seeds) is
        stored once: the id returned is the first one's. Whole images, and entries with later=True, go to the
        second file (loaded on demand); an entry of the first file is never replaced by one of the second."""
        x, y, n = self.crop
        part = values[y:y + n, x:x + n] if region == "crop" else values
        e = png_entry(part, bits, scale)
        same = json.dumps(e, sort_keys=True)
        if same in self.same:
            return self.same[same]
        if later or (later is None and region == "whole"):
            if same not in self.same_later:
                self.same_later[same] = f"w{len(self.later)}"
                self.later[self.same_later[same]] = e
            return self.same_later[same]
        self.same[same] = str(len(self.images))  # a short id (the size budget); `key` names it in this comment only
        self.images[self.same[same]] = e
        return self.same[same]

    def flip_ids(self, configs):
        """{config index: ({target: crop id}, {target: whole id})}: the FLIP map of each configuration's seed-0
        image against every target (imgdiff over the whole image, 8 bits over the fixed scale FLIP 0..1): the
        crops (the primary target's in the first file, the others' in the second), the whole maps (second file)
        of the configurations whose whole image is held (view.holds_whole)."""
        if not self.imgdiff:
            return {}
        pairs, where = [], []
        for i, c in enumerate(configs):
            image = os.path.join(self.work, image_stem(c, 0) + ".exr")
            for t in self.targets:
                f, r = t.split(":")
                pairs.append((image, self.reference_path(f, float(r)), map_path(image, t)))
                where.append((i, t))
        out = {}
        for (i, t), m in zip(where, flip_maps(self.imgdiff, pairs, (self.width, self.height))):
            base = image_stem(configs[i], 0)
            crop, whole = out.setdefault(i, ({}, {}))
            if view.holds_whole(self.plan, configs[i]):
                whole[t] = self.add(f"{base}-flip-{t}-whole", m[..., None], 8, "whole", (0.0, 1.0))
            crop[t] = self.add(f"{base}-flip-{t}-crop", m[..., None], 8, "crop", (0.0, 1.0),
                               later=t != self.targets[0])
        return out

    def rows_of(self, c):
        """({target: the CSV values of row_columns}, {target: per-seed mse_target}) of a configuration."""
        rows = self.sd[(self.sd["sampler"] == c["sampler"]) & (self.sd["spp"] == c["spp"])
                       & (self.sd["filter_name"] == c["filter"]) & (self.sd["radius"] == c["radius"])]
        per_target, per_seed = {}, {}
        for _, r in rows.iterrows():
            vals = row_values(r)
            per_target[str(r["target"])] = [vals[k] for k in self.row_columns]
            per_seed[str(r["target"])] = [float(x) for x in str(r["mse_target_seeds"]).split(";") if x]
        return per_target, per_seed

    def verify(self, img, target_imgs, target_var, per_seed, k, base):
        """Each target's mse_target of seed k's image (its variance subtracted) against the CSV's per-seed value;
        fails when one differs by more than TOLERANCE; returns [(target, from the image, the CSV's)]."""
        out = []
        for t in self.targets:
            mine = float(np.mean((img - target_imgs[t]) ** 2)) - target_var[t]
            theirs = per_seed[t][k]
            rel = abs(mine - theirs) / max(abs(theirs), 1e-12)
            self.worst, self.checked = max(self.worst, rel), self.checked + 1
            if rel > TOLERANCE:
                errors.fail(f"{self.scene}: {base} seed {k}: mse_target against {t} from the image "
                            f"{mine:.9g}, the CSV says {theirs:.9g}: the image is not the one measured")
            out.append((t, mine, theirs))
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
        # the crop: where the default view's methods differ most relative to their noise (choose_crop)
        n = crop_size(self.width, self.height)
        cx, cy, crop_how = view.choose_crop(self.plan, configs, seeds, n)
        self.crop = (cx, cy, n)
        out_configs, refs = [], {}
        scales, flips = {}, self.flip_ids(configs)
        for i, c in enumerate(configs):
            per_target, per_seed = self.rows_of(c)
            base = image_stem(c, 0)[:-len("-seed0")]
            for k in c["seeds"]:
                self.verify(seeds[(image_stem(c, 0), k)], target_imgs, target_var, per_seed, k, base)
            ref_key = f"{c['filter']}|{c['radius']:g}"
            whole = self.add(f"{base}-seed0-whole", seeds[(image_stem(c, 0), 0)], 8, "whole") \
                if view.holds_whole(self.plan, c) else None
            if ref_key not in refs:
                g, _, describe = self.reference(c["filter"], c["radius"])
                refs[ref_key] = {"crop": self.add(f"ref-{ref_key}-crop", g, 8, "crop"),
                                 "whole": self.add(f"ref-{ref_key}-whole", g, 8, "whole"), "describe": describe}
            crops = {str(k): self.add(f"{base}-seed{k}-crop", seeds[(image_stem(c, 0), k)], 8, "crop")
                     for k in c["seeds"]}
            flip_crop, flip_whole = flips.get(i, ({}, {}))
            out_configs.append({"id": config_id(c), "why": c.get("why", []),
                                "sampler": c["sampler"], "spp": c["spp"], "filter": c["filter"],
                                "radius": c["radius"], "sets": c["sets"], "seeds": c["seeds"], "crop": crops,
                                "whole": whole, "ref": ref_key, "rows": per_target, "flip": flip_crop, "flipWhole": flip_whole})
            if {"E", "P"} & set(c["sets"]):
                e0 = seeds[(image_stem(c, 0), 0)][cy:cy + n, cx:cx + n]
                for t in self.targets:  # the error shown: the mean over the channels of I - T
                    err = np.mean(e0 - target_imgs[t][cy:cy + n, cx:cx + n], axis=2)
                    scales.setdefault(f"{c['spp']}|{t}", []).append(np.abs(err))
        scale = {k: float(np.percentile(np.concatenate([a.ravel() for a in v]), 99)) for k, v in scales.items()}
        targets = {t: {"crop": self.add(f"target-{t}-crop", target_imgs[t], 16, "crop"),
                       "whole": self.add(f"target-{t}-whole", target_imgs[t], 8, "whole")} for t in self.targets}
        return {"scene": self.scene, "width": self.width, "height": self.height,
                "crop": {"x": cx, "y": cy, "size": n, "how": crop_how},
                "default": view.default_view(self.plan, out_configs),
                "wholeHow": WHOLE_DOC,
                "levels": plan.levels, "targets": self.targets, "primary": self.targets[0], "configs": out_configs,
                "refs": refs, "targetImages": targets, "rowColumns": self.row_columns, "scales": scale,
                "flipHow": "per-pixel LDR-FLIP of the seed-0 image against the target (imgdiff "
                           "--flip-output, the flip column's map; its mean over the whole image and the seeds is "
                           "the CSV's flip), 8 bits over 0..1; whole maps loaded on demand",
                "scaleHow": "99th percentile of |I - T| over the crop of every method the answer names at that spp (seed 0)",
                "plan": plan.describe(), "not_rendered": self.missing, "verified": {"images": len(seeds), "comparisons": self.checked,
                                                      "max_relative_difference": self.worst},
                "images": self.images}


def write_js(path, data, call="ALIASLAB_VIEWER_ADD({})"):
    tmp = path + ".partial"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(call.format(json.dumps(data, separators=(",", ":"))) + ";\n")
    os.replace(tmp, path)


def write_scene(out, scene, data, later):
    """Writes OUT/<scene>.js (data, naming the second file) and OUT/<scene>_whole.js (the `later` entries);
    returns their paths."""
    slug = figures.slug(scene)
    first, second = os.path.join(out, slug + ".js"), os.path.join(out, slug + "_whole.js")
    write_js(second, later, "ALIASLAB_VIEWER_WHOLE(" + json.dumps(scene) + ", {})")
    data["wholeFile"], data["wholeBytes"] = os.path.basename(second), os.path.getsize(second)
    write_js(first, data)
    return first, second


def export_study(results, study, df, plan, scenes, work, cache=None, quiet=False, imgdiff=None):
    out = os.path.join(results, "viewer")
    errors.prepare_out(out, "RESULTS/viewer")
    index = {"study": os.path.relpath(os.path.abspath(study), os.path.abspath(results)).replace(os.sep, "/"),
             "plan": plan.describe(), "whole": getattr(plan, "whole", "all"), "scenes": {}}
    for scene in scenes:
        e = SceneExport(study, df, plan, scene, work, cache, imgdiff)
        data = e.run()
        path, whole = write_scene(out, scene, data, e.later)
        index["scenes"][scene] = {"file": os.path.basename(path), "bytes": os.path.getsize(path),
                                  "whole_file": os.path.basename(whole), "whole_bytes": os.path.getsize(whole),
                                  "crop": data["crop"], "verified": data["verified"]}
        if not quiet:
            print(f"{scene}: {os.path.getsize(path) / 1e3:.0f} kB (+ {os.path.getsize(whole) / 1e3:.0f} kB on demand), "
                  f"{data['verified']['comparisons']} per-seed "
                  f"mse_target values recomputed, largest relative difference "
                  f"{data['verified']['max_relative_difference']:.2g}", flush=True)
    with open(os.path.join(out, "index.json"), "w", encoding="utf-8") as f:
        json.dump(index, f, indent=1)
    return out
