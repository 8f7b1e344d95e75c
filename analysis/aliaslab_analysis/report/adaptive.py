"""The report's adaptive section: where an adaptive sampler wins against its base sampler,
and where it loses, by how much and why, with its sample-density image beside the error images.

Per scene and spp, for each base sampler B that some adaptive sampler `adaptive-METHOD:B[+key=value...]` of
the CSV is built on: the best adaptive variant (lowest error) against B at the same spp (equal mean budget:
mean_spp = spp for every adaptive row), both with the primary target's own filter and radius when the CSV
has them (box:0.5: box r = 0.5, each pixel's own estimate), else both with the filter and radius where B
is best in that cell; same reconstruction and prefilter. Against the primary target:
  ratio = e_a / e_b, se = ratio sqrt((se_a / e_a)^2 + (se_b / e_b)^2)   (the delta method)
  z = (e_b - e_a) / sqrt(se_a^2 + se_b^2)                                (independent sample sets: unpaired)
  wins / loses: the difference is more than Z = 2 standard errors of the difference either way
  (stats/ties.tied, the rule of the findings), else tied.
"Why" for a losing cell says only what the CSV holds: whether the extra error is noise (the noise term's
ratio; aliasing zero within two standard errors or not) and whether the sampler moved samples at all
(max_spp against the mean: max_spp = spp means every pixel kept exactly the mean, so the difference is only
how each pixel's samples are drawn and weighted; docs/adaptive.md, "Bias").

Images: a losing cell shows the adaptive sampler's seed-0 `<config>-density.png` (reconstruction, signed
error, samples per pixel) beside the base sampler's seed-0 `<config>-error.png`, found in the study's images
folder (the sweep's layout: SCENE/CONFIG, CONFIG as the sweep names it) or, for a study that kept none, in
results/adaptive/<the study's folder name>/ (the same layout, ':' written '_'), rendered afterwards for the
same seed (results/adaptive.md says how). comparisons() returns the numbers; the test
(analysis/tests/test_adaptive_section.py) recomputes them from the CSV by another path.
"""
import html
import os

import numpy as np

from ..charts import figures
from ..stats import ties
from .elements import figure, image_src

PREFIX = "adaptive-"
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
ADAPTIVE_MD = os.path.join(REPO, "results", "adaptive.md")  # the measured cases and their reasons


def base_of(sampler):
    """The base sampler of an adaptive name ('adaptive-contrast:sobol+first=0.5' -> 'sobol'), else None."""
    s = str(sampler)
    if not s.startswith(PREFIX) or ":" not in s:
        return None
    return s.split(":", 1)[1].split("+", 1)[0]


def target_filter(target):
    """(filter name, radius) of a target 'name:radius' ('box:0.5'), else None."""
    name, _, r = str(target).partition(":")
    try:
        return name, float(r)
    except ValueError:
        return None


def verdict(e_a, se_a, e_b, se_b, z=ties.Z):
    """'wins', 'loses' or 'tied' (module doc), with the ratio, its se and the z of the difference."""
    se = float(np.hypot(se_a, se_b))
    ratio = e_a / e_b
    ratio_se = abs(ratio) * float(np.hypot(se_a / e_a, se_b / e_b))
    gap_z = (e_b - e_a) / se if se > 0 else (np.inf if e_b > e_a else -np.inf if e_b < e_a else 0.0)
    if not bool(ties.tied(e_a - e_b, se, z)):
        word = "loses"  # e_a - e_b > z se
    elif not bool(ties.tied(e_b - e_a, se, z)):
        word = "wins"  # e_b - e_a > z se
    else:
        word = "tied"
    return word, ratio, ratio_se, gap_z


def num(r, column):
    """A row's value as a float, NaN when the column is absent (older CSVs) or empty."""
    try:
        return float(r[column])
    except (KeyError, TypeError, ValueError):
        return np.nan


def comparisons(rows, target):
    """One dict per (scene, spp, base): the best adaptive row against the base row (module doc); rows are one
    target's rows of load_study (columns error, error_se, filter_name, ...). Sorted by scene, spp, base."""
    rows = rows[np.isfinite(rows["error"].to_numpy(dtype=float))]
    bases = rows["sampler"].map(base_of)
    own = target_filter(target)
    out = []
    for (scene, spp), cell in rows.groupby(["scene", "spp"], sort=True):
        cb = bases.loc[cell.index]
        for base in sorted(set(cb.dropna())):
            b_rows = cell[cell["sampler"] == base]
            a_rows = cell[cb == base]
            if b_rows.empty or a_rows.empty:
                continue
            keys = ["filter_name", "radius", "reconstruction", "prefilter"]
            shared = b_rows.merge(a_rows[keys].drop_duplicates(), on=keys)
            if shared.empty:
                continue
            at_own = shared[(shared["filter_name"] == own[0]) & (shared["radius"] == own[1])] if own else shared[:0]
            b = (at_own if not at_own.empty else shared).sort_values("error").iloc[0]
            same = a_rows[(a_rows[keys] == b[keys]).all(axis=1)]
            a = same.sort_values("error").iloc[0]
            word, ratio, ratio_se, gap_z = verdict(float(a["error"]), float(a["error_se"]), float(b["error"]),
                                                   float(b["error_se"]))
            out.append(dict(scene=scene, spp=int(spp), base=base, adaptive=a["sampler"], variants=len(same),
                            filter=b["filter_name"], radius=float(b["radius"]), own_filter=not at_own.empty,
                            reconstruction=b["reconstruction"], prefilter=b["prefilter"],
                            e_a=float(a["error"]), se_a=float(a["error_se"]), e_b=float(b["error"]),
                            se_b=float(b["error_se"]), verdict=word, ratio=ratio, ratio_se=ratio_se, z=gap_z,
                            noise_ratio=num(a, "noise") / num(b, "noise") if num(b, "noise") > 0 else np.nan,
                            aliasing=num(a, "aliasing"), aliasing_se=num(a, "aliasing_se"),
                            mean_spp=num(a, "mean_spp"), max_spp=num(a, "max_spp"), row_a=a, row_b=b))
    return out


def why(c):
    """The sentence on a losing cell: only what its CSV numbers support (module doc)."""
    zero = np.isfinite(c["aliasing_se"]) and abs(c["aliasing"]) <= ties.Z * c["aliasing_se"]
    parts = [f"its noise is {c['noise_ratio']:.2f}x the base's"]
    parts.append(f"aliasing {c['aliasing']:.2g} &plusmn; {c['aliasing_se']:.1g}, "
                 + ("zero within two standard errors: the loss is noise, not bias" if zero else
                    "not zero within two standard errors"))
    most = c["max_spp"]
    if not np.isfinite(most):
        pass  # no max_spp column: nothing said about where the samples went
    elif most <= c["spp"]:
        parts.append(f"no pixel got more than the mean {c['spp']} samples (max_spp {most:g}): nothing was "
                     "moved, so the difference is only how each pixel's samples are drawn and weighted (a pilot "
                     "at a fixed weight and a fresh set)")
    else:
        parts.append(f"it moved samples (up to {most:g} in one pixel, {most / c['spp']:.1f}x the "
                     "mean): see where in the density image")
    return "; ".join(parts)


def image_paths(images, extra, c):
    """(density panel, base error image) of a cell, each None when absent (module doc)."""
    def find(r, suffix):
        stem = f"{r['sampler']}-spp{int(r['spp'])}-{r['filter_name']}-r{r['radius']:g}-{r['reconstruction']}"
        if r["prefilter"] not in ("none", ""):
            stem += f"-{r['prefilter']}"
        for folder in (images, extra):
            for name in (stem, stem.replace(":", "_")):
                p = os.path.join(folder, figures.slug(c["scene"]), name + suffix)
                if folder and os.path.isfile(p):
                    return p
        return None
    return find(c["row_a"], "-density.png"), find(c["row_b"], "-error.png")


def zoom(height):
    """The density panel's zoom of an image `height` pixels high (study/sweep/contact.cpp: at least 128 px high)."""
    return min(max(-(-128 // max(1, height)), 1), 16)


def png_width(path):
    """A PNG's width from its header (0 when unreadable)."""
    with open(path, "rb") as f:
        head = f.read(24)
    return int.from_bytes(head[16:20], "big") if head[:8] == b"\x89PNG\r\n\x1a\n" else 0


def sized(fig, path, z):
    """A figure whose image is shown at z times its width, pixels kept sharp."""
    width = png_width(path) * z
    if not fig or width <= 0:
        return fig
    fig = fig.replace("<figcaption>", f"<figcaption style='max-width:{width}px'>", 1)
    return fig.replace("<img ", f"<img style='width:{width}px;max-width:100%;image-rendering:pixelated' ", 1)


def error_tile(c, path, x):
    """The base's seed-0 error map (the top-left w x h of its -error.png, above its colour bar) at the zoom of
    the density panel's error tile, so the two error maps sit side by side at one scale."""
    w, h = int(x["row_b"]["width"]), int(x["row_b"]["height"])
    z, width = zoom(h), png_width(path)
    caption = f"{html.escape(x['base'])}, {x['spp']} spp: signed error (the same colour scale)"
    return (f"<figure><div style='width:{w * z}px;height:{h * z}px;overflow:hidden'><img src='"
            f"{image_src(c.results, path, c.embed)}' style='width:{width * z}px;max-width:none;"
            f"image-rendering:pixelated' loading='lazy' decoding='async' alt='{caption}'></div>"
            f"<figcaption style='max-width:{w * z}px'>{caption}</figcaption></figure>")


def extra_images(study):
    """results/adaptive/<the study's folder name>: density panels rendered afterwards (module doc)."""
    folder = os.path.dirname(os.path.abspath(study))
    return os.path.join(os.path.dirname(folder), "adaptive", os.path.basename(folder))


def fmt_row(c):
    star = "" if c["own_filter"] else " *"
    return (f"<tr><td>{html.escape(str(c['scene']))}</td><td>{c['spp']}</td><td>{html.escape(c['adaptive'])}</td>"
            f"<td>{html.escape(c['base'])}</td><td>{html.escape(c['filter'])} r={c['radius']:g}{star}</td>"
            f"<td>{c['e_a']:.3g} &plusmn; {c['se_a']:.1g}</td><td>{c['e_b']:.3g} &plusmn; {c['se_b']:.1g}</td>"
            f"<td>{c['ratio']:.2f}x &plusmn; {c['ratio_se']:.2f}</td><td>{c['z']:+.1f}</td><td><b>{c['verdict']}</b>"
            f"</td><td>{c['max_spp']:g}</td><td>{c['noise_ratio']:.2f}x</td></tr>")


def adaptive_section(c):
    """The section's HTML for the report's Context c ('' when the study has no adaptive sampler with its base)."""
    cmp = comparisons(c.s.rows(), c.s.primary)
    if not cmp:
        return ""
    n = {w: sum(x["verdict"] == w for x in cmp) for w in ("wins", "loses", "tied")}
    docs_dir = c.science.rsplit("science.html", 1)[0]  # the rendered definitions' folder, relative to the page
    body = ["<h2 id='adaptive'>Adaptive sampling against its base</h2>",
            "<p>Per scene and spp, the best adaptive variant against its base sampler at the same mean spp, "
            f"error against <code>{html.escape(c.s.primary)}</code>, both with the target's own filter "
            f"(marked * where the CSV lacks it: then the filter and radius where the base is best). Ratio: the "
            "adaptive error over the base's, &plusmn; its standard error; z: the difference in standard errors "
            "(positive: adaptive better); <i>wins</i> or <i>loses</i> beyond two standard errors, else "
            f"<i>tied</i> (the tie rule above). Over the {len(cmp)} cells: it wins {n['wins']}, loses "
            f"{n['loses']}, ties {n['tied']}. Definitions: <a href='{html.escape(docs_dir)}adaptive.html'>"
            "docs/adaptive.md</a>.</p>",
            "<table><tr><th>scene</th><th>spp</th><th>adaptive</th><th>base</th><th>filter</th>"
            "<th>adaptive error</th><th>base error</th><th>ratio</th><th>z</th><th></th><th>max_spp</th>"
            "<th>noise ratio</th></tr>" + "".join(fmt_row(x) for x in cmp) + "</table>"]
    losing = [x for x in cmp if x["verdict"] == "loses"]
    notes = ADAPTIVE_MD if os.path.isfile(ADAPTIVE_MD) else None
    notes = os.path.relpath(notes, c.results).replace(os.sep, "/") if notes else None
    if losing:
        body.append("<h3 id='adaptive-loses'>Where it loses: by how much and why</h3>"
                    "<p>Each losing cell with what its own numbers say; the images (seed 0) where the study has "
                    "them: the adaptive sampler's reconstruction, its signed error (red too bright, blue too dark) "
                    "and its samples per pixel, beside the base sampler's signed error."
                    + (f" Cases measured at larger sizes, with the reasons read from their density images: <a "
                       f"href='{html.escape(notes)}'>results/adaptive.md</a>." if notes else "") + "</p>")
    extra = extra_images(c.study)
    for x in losing:
        body.append(f"<p><b>{html.escape(str(x['scene']))}, {x['spp']} spp</b>: {html.escape(x['adaptive'])} "
                    f"loses to {html.escape(x['base'])} by {x['ratio']:.2f}x &plusmn; {x['ratio_se']:.2f} "
                    f"({-x['z']:.1f} standard errors); {why(x)}.</p>")
        density, error = image_paths(c.images, extra, x)
        figs = []
        if density:
            figs.append(sized(figure(c.results, density, f"{html.escape(x['adaptive'])}, {x['spp']} spp: "
                                     "reconstruction, signed error, samples per pixel", c.embed), density, 1))
        if error:
            figs.append(error_tile(c, error, x))
        if figs:
            body.append("<div class='pair'>" + "".join(figs) + "</div>")
    return "\n".join(body)
