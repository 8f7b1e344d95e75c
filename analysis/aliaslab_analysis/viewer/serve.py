"""The viewer served on localhost: `python3 -m analysis viewer RESULTS --study CSV --serve
[--port N] [--exr FILE ...]` serves the page folder RESULTS (its viewer as exported) over http://127.0.0.1 and
answers the viewer's requests under /alv-api/:

  info                      {scenes: {scene: [[sampler, spp, filter, radius, seeds], ...]} (every weighted,
                            un-prefiltered configuration of the CSV), exrs: [the names of the --exr files]}
  render?scene&sampler&spp&filter&radius&seed&x&y&n
                            renders that CSV row's seed with the raytracer (render.command: the sweep's sampler,
                            seed and filter), checks its mse_target against every target with the CSV's per-seed
                            value (export.SceneExport.verify, as the export does; a mismatch is an error), and
                            returns the configuration as the viewer's data holds one (config), its image entries
                            (images: the whole image and the crop x, y, n at 16 bits, the whole FLIP maps against
                            every target) and the check (verified: [[target, from the image, the CSV's]])
  exr?scene&name&x&y&n      a user's EXR (one of --exr, the scene's size) as a configuration of its own, with its
                            FLIP maps against every target
  xt?scene&sampler&spp&filter&radius&seed&row&frames
                            the x-t slice of that row's image row `row` over frames of a moving camera registered
                            to the content, beside the primary target's (serve_xt.py)

Renders go to the work folder as the export's do (kept; a second request reuses the file)."""
import json
import os
import threading
import urllib.parse
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer

import numpy as np

from ..io import errors
from ..charts import figures
from . import render, serve_xt
from .encoding import channels, png_entry
from ..io.exr import read_exr
from .export import SceneExport
from .view import key_id
from .flip import flip_maps, map_path
from .plan import image_stem, shown_rows


class Served:
    def __init__(self, results, study, df, raytracer, imgdiff, work, cache, exrs):
        self.results, self.study, self.df, self.raytracer = results, study, df, os.path.abspath(raytracer)
        self.imgdiff, self.work, self.cache = imgdiff, work, cache
        self.exrs = {os.path.basename(p): os.path.abspath(p) for p in exrs}
        self.lock, self.scenes = threading.Lock(), {}

    def scene(self, name):
        if name not in self.scenes:
            if name not in set(self.df["scene"].astype(str)):
                raise errors.InputError(f"no scene {name!r} in {self.study}")
            e = SceneExport(self.study, self.df, None, name, self.work, self.cache, self.imgdiff)
            e.tv = {t: e.reference(*self.target(t))[:2] for t in e.targets}
            self.scenes[name] = e
        return self.scenes[name]

    @staticmethod
    def target(t):
        f, r = t.split(":")
        return f, float(r)

    def info(self):
        rows = shown_rows(self.df)
        out = {}
        for (scene, s, spp, f, r), g in rows.groupby(["scene", "sampler", "spp", "filter_name", "radius"], sort=True):
            out.setdefault(str(scene), []).append([str(s), int(spp), str(f), float(r), int(g["seeds"].max())])
        return {"scenes": out, "exrs": sorted(self.exrs)}

    def entries(self, e, path, img, crop):
        """The image entries of one image (whole, crop) and its whole FLIP maps against every target."""
        x, y, n = crop
        out = {"whole": png_entry(img, 16), "crop": png_entry(img[y:y + n, x:x + n], 16), "flip": {}}
        if self.imgdiff:
            pairs = [(path, e.reference_path(*self.target(t)), map_path(path, t)) for t in e.targets]
            for t, m in zip(e.targets, flip_maps(self.imgdiff, pairs, (e.width, e.height), jobs=1)):
                out["flip"][t] = png_entry(m[..., None], 8, (0.0, 1.0))
        return out

    def render(self, q):
        e = self.scene(q["scene"])
        c = {"sampler": q["sampler"], "spp": int(q["spp"]), "filter": q["filter"], "radius": float(q["radius"])}
        k = int(q.get("seed", 0))
        per_target, per_seed = e.rows_of(c)
        if not per_seed:
            raise errors.InputError(f"{q['scene']}: no row {key_id((c['sampler'], c['spp'], c['filter'], c['radius']))}"
                                    f" in {self.study}")
        if not 0 <= k < min(len(v) for v in per_seed.values()):
            raise errors.InputError(f"seed {k}: the row has {min(len(v) for v in per_seed.values())} seeds")
        work = os.path.join(self.work, figures.slug(e.scene) + f"-{e.width}x{e.height}")
        path = os.path.join(work, image_stem(c, k) + ".exr")
        with self.lock:
            cmd = render.command(self.raytracer, e.manifest["scene_path"], (e.width, e.height), e.manifest, c, k, path)
            render.render_all(self.raytracer, [(cmd, path)], 1, quiet=True)
            img = channels(read_exr(path))
            try:
                checked = e.verify(img, {t: v[0] for t, v in e.tv.items()}, {t: v[1] for t, v in e.tv.items()},
                                   per_seed, k, image_stem(c, k))
            except SystemExit:  # not the image measured: not kept for the next request either
                os.remove(path)
                raise
            ent = self.entries(e, path, img, crop_of(q))
        cid = "served:" + key_id((c["sampler"], c["spp"], c["filter"], c["radius"])) + f":seed{k}"
        config = dict(c, id=cid, sets=["served"], seeds=[k], why=[f"rendered on request, seed {k}, its mse_target "
                                                                   "checked against the CSV's"],
                      ref=f"{c['filter']}|{c['radius']:g}", rows=per_target, path=path)
        return {"config": config, "images": ent, "verified": checked, "rowColumns": e.row_columns}

    def user_exr(self, q):
        e = self.scene(q["scene"])
        name = q["name"]
        if name not in self.exrs:
            raise errors.InputError(f"{name}: not one of the --exr files ({', '.join(sorted(self.exrs)) or 'none'})")
        path = self.exrs[name]
        img = channels(read_exr(path))
        if img.shape[:2] != (e.height, e.width):
            raise errors.InputError(f"{path}: {img.shape[1]} x {img.shape[0]}, the scene is {e.width} x {e.height}")
        if img.shape[2] == 1 and e.tv and next(iter(e.tv.values()))[0].shape[2] == 3:
            img = np.repeat(img, 3, axis=2)
        with self.lock:
            ent = self.entries(e, path, img, crop_of(q))
        mse = {t: float(np.mean((img - v[0]) ** 2)) - v[1] for t, v in e.tv.items()}
        config = {"id": "exr:" + name, "sampler": name, "spp": 0, "filter": "user EXR", "radius": 0, "sets": ["exr"],
                  "seeds": [0], "why": [f"your image {path}; mse_target {', '.join(f'{t} {v:.4g}' for t, v in mse.items())}"],
                  "ref": None, "rows": {}, "path": path}
        return {"config": config, "images": ent, "mse_target": mse, "rowColumns": e.row_columns}


def crop_of(q):
    return int(q.get("x", 0)), int(q.get("y", 0)), int(q.get("n", 8))


def handler(served):
    class Handler(SimpleHTTPRequestHandler):
        def __init__(self, *a, **k):
            super().__init__(*a, directory=served.results, **k)

        def log_message(self, *a):
            pass

        def do_GET(self):
            u = urllib.parse.urlparse(self.path)
            if u.path == "/favicon.ico":  # none: answered empty, not a 404 in the browser's console
                self.send_response(204)
                self.end_headers()
                return None
            if not u.path.startswith("/alv-api/"):
                return super().do_GET()
            q = {k: v[0] for k, v in urllib.parse.parse_qs(u.query).items()}
            what = u.path[len("/alv-api/"):]
            try:
                if what == "info":
                    body = served.info()
                elif what == "xt":
                    body = serve_xt.xt(served, q)
                elif what in ("render", "exr"):
                    body = (served.render if what == "render" else served.user_exr)(q)
                else:
                    raise KeyError(what)
                code = 200
            except KeyError as ex:
                body, code = {"error": f"unknown request or missing parameter {ex}"}, 400
            except (errors.InputError, ValueError) as ex:
                body, code = {"error": str(ex)}, 400
            except SystemExit:  # errors.fail: its message is on the server's stderr
                body, code = {"error": "failed: the server's messages say why"}, 500
            data = json.dumps(body).encode("utf-8")
            self.send_response(code)
            self.send_header("Content-Type", "application/json")
            self.send_header("Content-Length", str(len(data)))
            self.end_headers()
            self.wfile.write(data)
    return Handler


def serve(served, port, quiet=False):
    """Serves until interrupted; port 0 takes a free one (printed)."""
    httpd = ThreadingHTTPServer(("127.0.0.1", port), handler(served))
    print(f"serving {served.results} on http://127.0.0.1:{httpd.server_address[1]}/index.html (Ctrl-C stops)",
          flush=True)
    try:
        httpd.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        httpd.server_close()
    return 0
