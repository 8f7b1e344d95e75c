"""The viewer's section of the page: the element #alv (data-base: the data folder relative to the page,
data-scenes: the scenes and their files, from RESULTS/viewer/index.json), its style and its script, both
inline. '' when the folder has no viewer data (run `python3 -m analysis viewer` first)."""
import html
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def asset(name):
    with open(os.path.join(HERE, name), encoding="utf-8") as f:
        return f.read()


def viewer_section(page_dir, data_dir=None):
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
    checked = sum(v["verified"]["comparisons"] for v in meta["scenes"].values())
    worst = max(v["verified"]["max_relative_difference"] for v in meta["scenes"].values())
    return (f"<h2 id='viewer'>Compare by eye</h2><p>The study's own images, side by side on the same region: "
            "per scene a crop where the methods differ most and the whole image, magnified without smoothing. "
            "Switch the sampler, spp, filter, radius and target with the buttons or keys (click in the viewer "
            "first); show the image, its own reference, the target, the signed error against the target or the "
            "FLIP map (the project's imgdiff, seed 0, against the primary target), each with its colour bar; pin methods to compare them with zoom and pan in step; point at a pixel "
            "for its value and error; flip through the seeds (aliasing stays put, noise moves). The numbers "
            "beside each image are its CSV row's. Which configurations are shown: "
            f"{html.escape(meta['plan'])}. Each image was rendered by the raytracer with the sweep's sampler, "
            f"seed and filter; its per-seed error against every target was recomputed from it and equals the CSV's "
            f"({checked} values, largest relative difference {worst:.1g}).</p>"
            f"<style>{asset('viewer.css')}</style>"
            f"<div id='alv' tabindex='0' data-base='{html.escape(rel)}' data-scenes='{html.escape(json.dumps(scenes))}'>"
            "<div class='alv-scenes'></div><div class='alv-controls'></div><div class='alv-status'></div>"
            "<canvas class='alv-bar' width='384' height='12'></canvas><span class='alv-bar-label'></span>"
            "<div class='alv-panels'></div></div>"
            f"<script>{asset('viewer.js')}</script>" + teaching(data_dir))


def teaching(data_dir):
    """The teaching strand's fragment written beside the data (teaching/build.py), or ''."""
    path = os.path.join(data_dir, "teaching.html")
    if not os.path.isfile(path):
        return ""
    with open(path, encoding="utf-8") as f:
        return ".teach-ps img{width:160px;image-rendering:pixelated}".join(["<style>", "</style>"]) + f.read()
