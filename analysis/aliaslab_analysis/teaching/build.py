"""The teaching strand: written by `python3 -m analysis teaching` (after `viewer`) as RESULTS/viewer/teaching.html,
a fragment the page includes after the viewer, its pictures embedded. Built from the study's own images (the
viewer's renders, the references) and the point sets of RESULTS/pointsets; every number in its prose is computed
from the CSV here (facts.py)."""
import base64
import html
import os

import numpy as np

from ..io import text_file
from ..io.exr import read_exr
from ..viewer.export import SceneExport, channels
from ..viewer.plan import image_stem
from ..io.study_csv import load_study
from . import facts, figures, negative

TRIO = ("uniform", "jittered", "sobol")
EDGE_FILTERS = (("box", 0.5), ("mitchell", 2.0), ("catmullrom", 2.0), ("lanczos", 2.0))


def uri(path):
    with open(path, "rb") as f:
        return "data:image/png;base64," + base64.b64encode(f.read()).decode("ascii")


def png_size(path):
    """(width, height) of a PNG file, from its IHDR chunk."""
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        return None
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def img(path, caption, cls=""):
    """A figure embedding the PNG at path, its <img> sized (width, height: the page lays out before it decodes)."""
    if not os.path.isfile(path):
        return ""
    size = png_size(path)
    dims = f" width='{size[0]}' height='{size[1]}'" if size else ""
    return (f"<figure class='{cls}'><img src='{uri(path)}'{dims} alt='{html.escape(caption)}'>"
            f"<figcaption>{caption}</figcaption></figure>")


def name(r):
    return f"{r['sampler']} {r['filter_name']} r={float(r['radius']):g}"


def value(r, col="mse_target"):
    se = r.get(col + "_se", np.nan)
    det = bool(int(r.get("deterministic", 0)))
    return f"{r[col]:.3g}" + ("" if det or not np.isfinite(se) else f" &plusmn; {se:.1g}")


REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))


def negative_control(results):
    """negative.control of the negative-control study beside the page (RESULTS/negative_control/study.csv, else the
    repository's), or {}."""
    for folder in (results, os.path.join(REPO, "results")):
        path = text_file.existing(os.path.join(folder, "negative_control", "study.csv"))  # or study.csv.gz
        if os.path.isfile(path):
            return negative.control(load_study(path)[0])
    return {}


def grid_part(rows, target, g, study, df, plan, work, cache, out, control=None):
    scene, spp = g["scene"], g["spp"]
    ex = SceneExport(study, df, plan, scene, work, cache)
    samplers = [s for s in TRIO if s in plan.teaching]
    paths = [os.path.join(ex.work, image_stem({"sampler": s, "spp": spp, "filter": "box", "radius": 0.5}, 0) + ".exr")
             for s in samplers]
    gspp, grid = negative.grid_vs_jittered(rows)
    opening = "<h3 id='teach-grid'>Where a grid aliases</h3>" + negative.html(control or {}, gspp, grid)
    if not all(os.path.isfile(p) for p in paths):
        return opening + "<p class='note'>The crop needs the viewer's renders (run `analysis viewer`).</p>"
    images = [channels(read_exr(p)) for p in paths]
    tf, tr = target.split(":")
    t = ex.reference(tf, float(tr))[0]
    size = max(8, min(40, min(images[0].shape[:2]) // 2))
    png = os.path.join(out, "teaching-grid.png")
    x, y, scale = figures.trio(png, images, t, [f"{s}, {spp} spp, box r=0.5, seed 0" for s in samplers], size)
    cells = []
    for s in samplers + (["uniform-shifted"] if "uniform-shifted" in set(rows["sampler"]) else []):
        r = facts.one(rows, scene=scene, sampler=s, spp=spp, filter_name="box", radius=0.5)
        if r is not None:
            cells.append(f"<tr><td>{html.escape(s)}</td><td>{value(r)}</td><td>{r['aliasing']:.3g}</td>"
                         f"<td>{r['noise']:.3g}</td></tr>")
    return (opening + f"<p>In this study the fixed grid comes off worst against jittered in <b>{html.escape(scene)}</b> "
            f"({g['ratio']:.3g} times jittered's error at {spp} spp). Below, the {size} x {size} crop at ({x}, {y}) "
            "where the grid's error (seed 0) is largest: the fixed grid's error is structured (the same for every "
            "seed: all aliasing, noise 0), jittered and Sobol' turn it into noise that moves with the seed (flip the "
            "seeds in the viewer above). The shifted grid (<code>uniform-shifted</code>) is a randomised lattice: "
            "one random offset of every cell's point per image, not the grid's average over alignments.</p>"
            f"<table><tr><th>{spp} spp, box r=0.5</th><th>mse_target &plusmn; se</th><th>aliasing</th><th>noise</th>"
            f"</tr>{''.join(cells)}</table>" + img(png, f"{html.escape(scene)}: the same crop, images (top) and "
                                                       f"signed errors against {html.escape(target)} (bottom, "
                                                       f"&plusmn;{scale:.2g})."))


def pointset_part(results):
    parts = []
    for s in TRIO:
        for kind in ("points", "periodogram"):
            p = os.path.join(results, "pointsets", f"{kind}_{s}_256.png")
            parts.append(img(p, f"{s}: {'256 points' if kind == 'points' else 'periodogram of 256 points'}",
                             "teach-ps"))
    parts = [p for p in parts if p]
    if not parts:
        return ""
    return ("<h3 id='teach-points'>The point sets and their spectra</h3><p>The same three patterns as point sets "
            "(results/pointsets, made by the <code>pointsets</code> experiment) with their periodograms (the power "
            "spectrum; the centre is frequency 0): the grid's energy sits in isolated spikes, which fold scene "
            "frequencies onto the same wrong frequency (aliasing); jittered and Sobol' spread it into a noisy ring "
            "with little energy at low frequencies, so the error becomes noise.</p><div class='pair'>"
            + "".join(parts) + "</div>")


def edge_part(rows, study, df, plan, work, cache, out):
    best = None
    for scene in sorted(rows["scene"].unique()):
        ex = SceneExport(study, df, plan, scene, work, cache)
        if not all(ex.has_reference(f, r) for f, r in EDGE_FILTERS):
            continue
        refs = [ex.reference(f, r)[0] for f, r in EDGE_FILTERS]
        x, y = figures.edge_point(refs[0])
        step = abs(float(np.mean(refs[0][y, x + 1] - refs[0][y, x])))
        if best is None or step > best[0]:
            best = (step, scene, refs, x, y)
    if best is None:
        return ""
    _, scene, refs, x, y = best
    half = 10
    prof = [np.mean(r[y, x - half:x + half + 1], axis=1) for r in refs]
    lo, hi = float(min(prof[0])), float(max(prof[0]))
    png = os.path.join(out, "teaching-edge.png")
    labels = [f"{f} r={r:g}" for f, r in EDGE_FILTERS]
    figures.edge_profile(png, prof, labels, x, y, half)
    rowsd = []
    for p, lab in zip(prof, labels):
        over = (float(p.max()) - hi) / (hi - lo) * 100 if hi > lo else 0.0
        under = (lo - float(p.min())) / (hi - lo) * 100 if hi > lo else 0.0
        rowsd.append(f"<tr><td>{lab}</td><td>{max(over, 0):.1f}%</td><td>{max(under, 0):.1f}%</td></tr>")
    return (f"<h3 id='teach-ringing'>Ringing and overshoot at an edge</h3><p>The references (4096 spp: no noise) of "
            f"<b>{html.escape(scene)}</b> along row {y}, across its sharpest edge (the largest step of the box r = 0.5 "
            "reference): the box follows the edge within a pixel; Mitchell-Netravali, Catmull-Rom and Lanczos have "
            "negative lobes, so they overshoot beyond the edge's two levels and ring beside it. Overshoot and "
            "undershoot as a share of the edge's height (the box's range in this window):</p><table><tr><th>filter"
            "</th><th>overshoot</th><th>undershoot</th></tr>" + "".join(rowsd) + "</table>"
            + img(png, f"{html.escape(scene)}, row {y}: each filter's reference across the edge (grey lines: the "
                       "box's lowest and highest value)."))


def blur_part(rows, g, study, df, plan, work, cache, out):
    scene = g["scene"] if g else sorted(rows["scene"].unique())[0]
    ex = SceneExport(study, df, plan, scene, work, cache)
    if not (ex.has_reference("box", 0.5) and ex.has_reference("box", 2.0)):
        return ""
    a, b = ex.reference("box", 0.5)[0], ex.reference("box", 2.0)[0]
    size = max(8, min(40, min(a.shape[:2]) // 2))
    png = os.path.join(out, "teaching-blur.png")
    x, y = figures.pair(png, [a, b], ["box r=0.5 (reference)", "box r=2 (reference)"], size,
                        np.mean((a - b) ** 2, axis=2))
    spp = int(rows["spp"].max())
    r1 = facts.one(rows, scene=scene, sampler="jittered", spp=spp, filter_name="box", radius=0.5)
    r2 = facts.one(rows, scene=scene, sampler="jittered", spp=spp, filter_name="box", radius=2.0)
    nums = ""
    if r1 is not None and r2 is not None:
        nums = (f" With jittered at {spp} spp: box r=0.5 has blur {r1['blur']:.3g}, noise {r1['noise']:.3g} and error "
                f"{value(r1)}; box r=2 has blur {r2['blur']:.3g}, noise {r2['noise']:.3g} and error {value(r2)}.")
    return (f"<h3 id='teach-blur'>A wide filter blurs</h3><p>The box of radius 2 averages a 4 x 4 pixel area: less "
            f"noise, but the detail is gone, and the error against the target keeps that loss as <i>blur</i> (the "
            f"filter's own reference against the target, measured without noise).{nums} The crop of "
            f"{html.escape(scene)} at ({x}, {y}) where the two references differ most:</p>"
            + img(png, "The same crop of two references: box r=0.5 and box r=2."))


def extremes_part(rows, target):
    bad = facts.degenerate(rows)
    ext, spp = facts.extremes(rows, bad)
    lines = []
    for scene, (best, worst, degen) in sorted(ext.items()):
        names = sorted({f"{r.filter_name} r={float(r.radius):g}" for r in degen.itertuples()})
        lines.append(f"<tr><td>{html.escape(scene)}</td><td>{html.escape(name(best))}: {value(best)}</td>"
                     f"<td>{html.escape(name(worst))}: {value(worst)}</td><td>{len(degen)} row(s): "
                     f"{html.escape(', '.join(names)) or 'none'}</td></tr>")
    kinds = {}
    for reason in bad.values():
        k = "undefined pixels" if "undefined" in reason else "weight sums near zero"
        kinds[k] = kinds.get(k, 0) + 1
    return (f"<h3 id='teach-worst'>Best, worst, and broken</h3><p>Per scene at {spp} spp against "
            f"{html.escape(target)}: the best method and the worst among the methods that work. Filters that break "
            f"the weighted average are listed apart, as what they are, not as the worst: a configuration is broken "
            f"when it has undefined pixels (no sample with a non-zero weight) or its noise is at least "
            f"{facts.DEGENERATE_NOISE:g} times the box r = 0.5's with the same scene, sampler and spp (weight sums "
            f"near zero amplify the noise into salt-and-pepper). Over the study: "
            + ", ".join(f"{v} configuration(s) with {k}" for k, v in sorted(kinds.items())) + ".</p>"
            "<table><tr><th>scene</th><th>best</th><th>worst that works</th><th>broken (apart)</th></tr>"
            + "".join(lines) + "</table>")


def build(results, study, df, plan, work, cache, out):
    """Writes OUT/teaching.html (and its PNGs); returns its path."""
    rows, target = facts.primary_rows(df)
    g = facts.grid_scene(rows)
    parts = ["<h2 id='teaching'>Where a grid aliases, and what filters do: a teaching strand</h2>"
             "<p>Built from this study's own images and numbers; every number below is computed from the CSV.</p>"]
    if g:
        parts.append(grid_part(rows, target, g, study, df, plan, work, cache, out, negative_control(results)))
    parts.append(pointset_part(results))
    parts.append(edge_part(rows, study, df, plan, work, cache, out))
    parts.append(blur_part(rows, g, study, df, plan, work, cache, out))
    parts.append(extremes_part(rows, target))
    path = os.path.join(out, "teaching.html")
    with open(path + ".partial", "w", encoding="utf-8") as f:
        f.write("\n".join(p for p in parts if p))
    os.replace(path + ".partial", path)
    for p in ("teaching-grid.png", "teaching-edge.png", "teaching-blur.png"):  # embedded in the fragment
        if os.path.isfile(os.path.join(out, p)):
            os.remove(os.path.join(out, p))
    return path
