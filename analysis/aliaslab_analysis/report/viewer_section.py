"""The viewer's section of the page: the element #alv (data-base: the data folder relative to the page,
data-scenes: the scenes and their files, from RESULTS/viewer/index.json), its style and its script, copied from
the viewer package's folder (aliaslab_analysis/viewer/) into the data folder once (viewer.css, viewer.js: written
when they differ) and referred to by <link> and <script src> (both work from file://). '' when the folder has no viewer data (run `python3 -m
analysis viewer` first)."""
import html
import json
import os

ASSET_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "viewer")
SCRIPTS = ("viewer_kit.js", "viewer_panels.js", "viewer.js", "viewer_serve.js")  # in load order; viewer_serve.js: active only when served (serve.py)
ASSETS = SCRIPTS + ("viewer.css",)


def asset(name):
    with open(os.path.join(ASSET_DIR, name), encoding="utf-8") as f:
        return f.read()


def write_assets(data_dir):
    """Copies the scripts and viewer.css into data_dir where missing or different."""
    for name in ASSETS:
        path, text = os.path.join(data_dir, name), asset(name)
        if os.path.isfile(path):
            with open(path, encoding="utf-8") as f:
                if f.read() == text:
                    continue
        with open(path + ".partial", "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(path + ".partial", path)


def megabytes(n):
    return f"{n / 1e6:.1f} MB" if n >= 100_000 else f"{n / 1e3:.0f} kB"


def viewer_section(page_dir, data_dir=None, write=True):
    """The section's HTML; with write, the assets are copied beside the data first (write_assets)."""
    data_dir = data_dir or os.path.join(page_dir, "viewer")
    index = os.path.join(data_dir, "index.json")
    if not os.path.isfile(index):
        return ""
    with open(index, encoding="utf-8") as f:
        meta = json.load(f)
    scenes = [{"scene": s, "file": v["file"]} for s, v in meta["scenes"].items()
              if os.path.isfile(os.path.join(data_dir, v["file"]))]
    if not scenes:
        return ""
    rel = os.path.relpath(data_dir, page_dir).replace(os.sep, "/").rstrip("/") + "/"
    if write:
        write_assets(data_dir)
    checked = sum(v["verified"]["comparisons"] for v in meta["scenes"].values())
    first = sum(v["bytes"] for v in meta["scenes"].values())
    later = sum(v.get("whole_bytes", 0) for v in meta["scenes"].values())
    loads = (f"What is loaded when: a scene's crops, its FLIP maps against the primary target and its numbers when "
             f"the scene is opened (one file per scene, {megabytes(first)} for all); its whole images (every "
             "configuration's seed 0, the own references, the targets) and the FLIP maps against the other targets "
             f"only when you ask for the whole image or such a FLIP map (one more file per scene, {megabytes(later)} "
             "for all).") if later else ""
    worst = max(v["verified"]["max_relative_difference"] for v in meta["scenes"].values())
    return (f"<h2 id='viewer'>Compare by eye</h2><p>The study's own images, side by side on the same region: "
            "it opens on the answer (the leading method at the lowest spp beside the runner-up family's best and "
            "jittered, on the crop where their mean images differ most relative to their noise) and holds every "
            "method the answer names (equivalent to the best, the best of each sampler); the whole image too, "
            "magnified without smoothing. "
            "Switch the sampler, spp, filter, radius and target with the buttons or keys (click in the viewer "
            "first); show the image, its own reference, the target, the signed error against the target or the "
            "FLIP map (the project's imgdiff, seed 0), each with its colour bar; pin methods to "
            "compare them with zoom and pan in step (b flips the first panel between two methods in place); point at a pixel "
            "for its value and error; flip through the seeds (aliasing stays put, noise moves). The numbers "
            "beside each image are its CSV row's. Which configurations are shown: "
            f"{html.escape(meta['plan'])}. Each image was rendered by the raytracer with the sweep's sampler, "
            f"seed and filter; its per-seed error against every target was recomputed from it and equals the CSV's "
            f"({checked} values, largest relative difference {worst:.1g}). {loads}</p>"
            f"<link rel='stylesheet' href='{html.escape(rel)}viewer.css'>"
            f"<div id='alv' tabindex='0' data-base='{html.escape(rel)}' data-scenes='{html.escape(json.dumps(scenes))}'>"
            "<div class='alv-scenes'></div><div class='alv-controls'></div><div class='alv-status'></div>"
            "<canvas class='alv-bar' width='384' height='12'></canvas><span class='alv-bar-label'></span>"
            "<div class='alv-panels'></div></div>"
            + "".join(f"<script src='{html.escape(rel)}{name}'></script>" for name in SCRIPTS) + teaching(data_dir))


def teaching(data_dir):
    """The teaching strand's fragment written beside the data (teaching/build.py), or ''."""
    path = os.path.join(data_dir, "teaching.html")
    if not os.path.isfile(path):
        return ""
    with open(path, encoding="utf-8") as f:
        return ".teach-ps img{width:160px;image-rendering:pixelated}".join(["<style>", "</style>"]) + f.read()
