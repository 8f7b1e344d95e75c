"""The x-t slices of the motion section (docs/science.md "Motion", "Looking at it: x-t slices"):
per scene, the PNG xt_slice.py wrote in the folder xt/ beside the study CSV, with a caption naming each panel's
configuration, why it was chosen, and its shimmer (and the target's own) with the standard error, read from the
study CSV's rows. '' when xt/xt.csv is missing or does not list the scene."""
import csv
import html
import os

import numpy as np

from .elements import figure


def read_panels(folder):
    """{scene: [xt.csv rows in panel order]} of folder/xt/xt.csv, {} when it is missing."""
    path = os.path.join(folder, "xt", "xt.csv")
    if not os.path.isfile(path):
        return {}
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    out = {}
    for r in sorted(rows, key=lambda r: int(r["panel"])):
        out.setdefault(r["scene"], []).append(r)
    return out


def shimmer_text(rows, scene, p):
    """'shimmer V ± SE' of the study row a panel shows ('(no seed noise)' for a standard error of zero: every seed
    alike), the target's own shimmer for panel 0; '' when absent."""
    sd = rows[rows["scene"] == scene]
    if p["panel"] == "0":
        v = sd["target_shimmer"].astype(float)
        v = v[np.isfinite(v)]
        return "" if v.empty else f"its own shimmer {float(v.median()):.2g}"
    r = sd[(sd["sampler"] == p["sampler"]) & (sd["spp"].astype(float) == float(p["spp"]))
           & (sd["filter_name"] == p["filter"]) & np.isclose(sd["radius"].astype(float), float(p["radius"]))
           & (sd["reconstruction"].astype(str) == "weighted")]
    if r.empty or not np.isfinite(float(r["shimmer"].iloc[0])):
        return ""
    se = float(r["shimmer_se"].iloc[0])
    return f"shimmer {float(r['shimmer'].iloc[0]):.2g}" + (f" ± {se:.1g}" if np.isfinite(se) and se > 0 else
                                                          " (no seed noise)")


def xt_figure(c, rows, scene, panels):
    """The scene's x-t figure with its caption, '' when xt_slice.py made none for it."""
    mine = panels.get(str(scene))
    if not mine:
        return ""
    first = mine[0]
    png = os.path.join(os.path.dirname(os.path.abspath(c.study)), "xt", first["png"])
    parts = []
    for p in mine:
        s = shimmer_text(rows, scene, p)
        parts.append(f"<b>{html.escape(p['label'])}</b> ({html.escape(p['why'])}{'; ' + s if s else ''})")
    caption = (f"x-t slices of {html.escape(str(scene))}: image row {int(first['row'])} (from the top) in each of "
               f"{int(first['frames'])} frames of the camera moving ({float(first['motion_dx']):g}, "
               f"{float(first['motion_dy']):g}) pixels per frame, frame 0 at the top, each frame registered to the "
               "content (<code>raytracer -register</code>, the library's band-limited shift). Vertical streaks: "
               "the picture holds still where the eye follows it, blur included; slanted or crawling texture: "
               "shimmer; speckle: noise. Below each slice its change (each row minus the mean of the rows; red "
               "above, blue below). Panels, left to right: " + "; ".join(parts) + ". Seed 0 of each; shimmer "
               "from the study CSV (its own seeds and frames). Made by <code>xt_slice.py</code>.")
    return figure(c.results, png, caption, c.embed, anchor=f"xt-{first['png'][3:-4]}", toc=f"motion: x-t {scene}")
