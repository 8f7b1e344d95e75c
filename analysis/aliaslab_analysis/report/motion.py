"""The motion section of the report (definitions docs/science.md "Motion"). For a study CSV made
with frames (sweep --frames F > 1: the motion columns of lib/study/records/csv.h), against the primary target:
  - per scene a chart: shimmer (measured in the content's frame) against blur and against noise, one line per
    (sampler, spp, filter) through its radii, the target's own shimmer drawn as a level;
  - per scene and (sampler, spp) the still-image ranking (mse_target, frame 0) beside the in-motion rankings
    (shimmer, and flicker with one seed per sequence), each in order with its top group (tied with the best by
    the two-standard-error rule, stats/ties.py top_group) in bold;
  - the animated loop of frames of one scene with each frame's error (motion_loop.py), when loop.png and its
    loop.csv are beside the CSV;
  - per scene the x-t slices of a row over registered frames (xt_slice.py, report/motion_xt.py), when xt/xt.csv
    is beside the CSV.
Every number in the prose comes from facts(), computed from the CSV; analysis/tests/test_motion_report.py
recomputes them from the CSV's text by another path. '' for a still study (no frames column, or F = 1).
Rows whose measure is not finite are left out of that measure's ranking and counts."""
import csv
import html
import os

import numpy as np

from ..charts import figures, palette
from ..charts.figures import plt
from ..stats import ties
from .elements import figure
from .motion_xt import read_panels, xt_figure

MEASURES = [("still (mse_target)", "mse_target", "mse_target_se", True),
            ("in motion: shimmer", "shimmer", "shimmer_se", False),
            ("in motion: flicker, one seed", "flicker_same", "flicker_same_se", False)]


def motion_rows(df, target):
    """The rows of a study with frames against `target`, or None for a still study."""
    if "frames" not in df.columns or not (df["frames"].astype(float) > 1).any():
        return None
    return df[(df["target"].astype(str) == target) & (df["frames"].astype(float) > 1)].copy()


def method(r):
    recon = "" if str(r["reconstruction"]) == "weighted" else f" ({r['reconstruction']})"
    return f"{r['filter_name']} {float(r['radius']):g}{recon}"


def ranked(cell, column, se_column, paired):
    """The cell's rows in order of `column` with ties.top_group's `top` (paired by seeds only for mse_target)."""
    rows = cell[np.isfinite(cell[column].astype(float))].copy()
    rows["error"], rows["error_se"] = rows[column].astype(float), rows[se_column].astype(float)
    if not paired:
        rows = rows.drop(columns=[c for c in ("seed_values",) if c in rows.columns])
    return ties.top_group(rows).sort_values("error")


def best(cell, column):
    """The method with the lowest finite value of `column`, None when no value is finite."""
    v = cell[column].astype(float)
    v = v[np.isfinite(v)]
    return None if v.empty else method(cell.loc[v.idxmin()])


def steady(r):
    """Shimmer zero within two standard errors (a deterministic row: below 1e-5, the registration's border error)."""
    s, se = float(r["shimmer"]), float(r["shimmer_se"])
    return bool(np.isfinite(s)) and abs(s) <= (2 * se if np.isfinite(se) and se > 0 else 0) + 1e-5


def facts(rows):
    """The section's numbers: cells = (scene, sampler, spp); `tradeoff`: cells whose Gaussians of radius 1 or more
    (two radii or more; at r = 0.5, sigma = r / 3 is narrower than the pixel, and its blur against the pixel
    area a sharpening) have shimmer falling and blur rising with the radius, value by value;
    `differ_shimmer` / `differ_flicker`: cells whose lowest mse_target is another method than their lowest
    shimmer / flicker_same (cells with no finite value left out); `steady`: per scene (sorted), (scene, rows
    whose shimmer is zero within error (steady()), rows)."""
    out = dict(cells=0, gaussian_cells=0, tradeoff=0, differ_shimmer=0, differ_flicker=0, steady=[])
    for _, cell in rows.groupby(["scene", "sampler", "spp"], sort=True):
        out["cells"] += 1
        still = best(cell, "mse_target")
        out["differ_shimmer"] += still is not None and best(cell, "shimmer") not in (None, still)
        out["differ_flicker"] += still is not None and best(cell, "flicker_same") not in (None, still)
        g = cell[(cell["filter_name"] == "gaussian") & (cell["reconstruction"] == "weighted") &
                 (cell["radius"].astype(float) >= 1)].sort_values("radius")
        if len(g) >= 2:
            out["gaussian_cells"] += 1
            sh, blur = g["shimmer"].to_numpy(float), g["blur"].to_numpy(float)
            out["tradeoff"] += bool((np.diff(sh) < 0).all() and (np.diff(blur) > 0).all())
    for scene, sd in rows.groupby("scene", sort=True):
        out["steady"].append((str(scene), int(sum(steady(r) for _, r in sd.iterrows())), len(sd)))
    return out


def chart(rows, scene, out_dir):
    """shimmer vs blur and shimmer vs noise for one scene, the target's own shimmer as a level; returns the PNG."""
    panels = [("blur", "shimmer", "shimmer (content frame) against blur"),
              ("noise", "shimmer", "shimmer (content frame) against noise")]
    fig, axes = plt.subplots(1, 2, figsize=(15, 5.2))
    styles = {spp: ["-", "--", ":", "-."][i % 4] for i, spp in enumerate(sorted(rows["spp"].unique()))}
    sd = rows[rows["scene"] == scene]
    level = sd["target_shimmer"].astype(float)
    level = float(level[np.isfinite(level)].median()) if np.isfinite(level).any() else None
    for ax, (x, y, title) in zip(axes, panels):
        if level is not None:
            ax.axhline(level, color="0.4", linestyle=":", label=f"the target's own shimmer ({level:.2g})")
        for (sampler, spp, name, recon), line in sd.groupby(["sampler", "spp", "filter_name", "reconstruction"]):
            line = line.sort_values("radius")
            ax.plot(line[x].astype(float), line[y].astype(float), marker=palette.filter_marker(name),
                    color=palette.sampler_colour(sampler), linestyle=styles[spp],
                    label=f"{sampler} {int(spp)} spp, {name}" + ("" if recon == "weighted" else f" ({recon})"))
            for _, r in line.iterrows():
                ax.annotate(f"{float(r['radius']):g}", (float(r[x]), float(r[y])), fontsize=7, xytext=(3, 3),
                            textcoords="offset points")
        ax.set_xscale("symlog", linthresh=1e-6)
        ax.set_yscale("symlog", linthresh=1e-6)
        ax.set_xlabel(f"{x} (the still image, frame 0)")
        ax.set_ylabel(y)
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=7, loc="center left", bbox_to_anchor=(0.8, 0.5), ncol=2 if len(labels) > 20 else 1)
    fig.subplots_adjust(left=0.05, right=0.79, wspace=0.25)
    fig.suptitle(f"{scene}: shimmer beside blur and noise (numbers: filter radius; lower is steadier)")
    return figures.save_figure(fig, out_dir, f"motion-{figures.slug(scene)}")[0]


def ranking_table(rows, scene):
    head = "".join(f"<th>{html.escape(label)}</th>" for label, _, _, _ in MEASURES)
    body = []
    for (sampler, spp), cell in rows[rows["scene"] == scene].groupby(["sampler", "spp"], sort=True):
        tds = []
        for _, col, se, paired in MEASURES:
            parts = []
            for _, r in ranked(cell, col, se, paired).iterrows():
                text = f"{html.escape(method(r))} ({float(r[col]):.2g})"
                parts.append(f"<b>{text}</b>" if r["top"] else text)
            tds.append("<td style='text-align:left'>" + ", ".join(parts) + "</td>")
        body.append(f"<tr><td>{html.escape(str(sampler))} {int(spp)} spp</td>{''.join(tds)}</tr>")
    return f"<table><tr><th>sampler</th>{head}</tr>{''.join(body)}</table>"


def loop_part(results, folder, embed):
    """The animated loop and its per-frame errors, when motion_loop.py wrote them beside the CSV."""
    png, table = os.path.join(folder, "loop.png"), os.path.join(folder, "loop.csv")
    if not (os.path.isfile(png) and os.path.isfile(table)):
        return ""
    with open(table, newline="") as f:
        errs = list(csv.DictReader(f))
    by = {}
    for r in errs:
        by.setdefault(r["method"], []).append(float(r["mse"]))
    rows = "".join(f"<tr><td>{html.escape(m)}</td>" + "".join(f"<td>{v:.2e}</td>" for v in vals) +
                   f"<td>{np.mean(vals):.2e}</td></tr>" for m, vals in by.items())
    n = max(len(v) for v in by.values())
    head = "".join(f"<th>frame {t}</th>" for t in range(n))
    return (figure(results, png, "A short loop of frames (the camera moving as in the study): the reference, then "
                   "per method its frame and its signed error against that frame's reference (red above, blue "
                   "below), with the frame's error (mean squared difference) above it. Made by "
                   "<code>motion_loop.py</code> from <code>raytracer -frames</code> renders. Below Nyquist the error moves "
                   "with the stripes (the blur of the filter): an eye following them sees it steady, and shimmer, "
                   "measured in the content's frame, is zero.", embed,
                   anchor="motion-loop", toc="motion: a loop of frames")
            + f"<table><tr><th>method</th>{head}<th>mean</th></tr>{rows}</table>")


def motion_section(c):
    rows = motion_rows(c.df, c.s.primary)
    if rows is None or rows.empty:
        return ""
    f = facts(rows)
    frames = int(rows["frames"].iloc[0])
    dx, dy = float(rows["motion_dx"].iloc[0]), float(rows["motion_dy"].iloc[0])
    steady_text = "; ".join(f"{html.escape(sc)} {n} of {total}" for sc, n, total in f["steady"])
    body = ["<h2 id='motion'>Aliasing in motion</h2>",
            f"<p>Every configuration rendered in {frames} frames of a camera moving ({dx:g}, {dy:g}) pixels per "
            f"frame (definitions: <a href='{c.science}'>docs/science.md</a>, \"Motion\"). <code>shimmer</code>: "
            "the change between consecutive frames once frame t + 1 is moved back by the motion (band-limited "
            "interpolation), the part every seed shares, noise removed: what an eye following the content sees "
            "change. It needs no target; error that moves with the picture (a filter's blur) does not count. "
            "<code>target_shimmer</code>: the target's own (the pixel-area image aliases too). "
            "<code>flicker</code>: the same change one rendered sequence shows with one seed, noise included. "
            "The still columns are frame 0's.</p>",
            f"<div class='answer'><b>Answer for this study</b> (computed from the CSV). Rows whose shimmer is zero "
            f"within two standard errors, per scene: {steady_text}. In {f['tradeoff']} of "
            f"{f['gaussian_cells']} (scene, sampler, spp) cells with two or more Gaussian radii of 1 pixel or more, "
            "shimmer falls and blur rises at every step as the Gaussian widens: the trade-off (value by value, "
            "without the standard errors: a rise within noise counts against it). The still image's best method "
            f"is not the steadiest in {f['differ_shimmer']} of {f['cells']} cells by shimmer and in "
            f"{f['differ_flicker']} by flicker (lowest value; ties in the tables below).</div>"]
    panels = read_panels(os.path.dirname(os.path.abspath(c.study)))
    for scene in sorted(rows["scene"].unique()):
        png = chart(rows, scene, c.charts_dir)
        body.append(f"<h3>{html.escape(str(scene))}</h3>")
        body.append(figure(c.results, png, f"{html.escape(str(scene))}: shimmer against blur (left) and against noise "
                           "(right), per filter and radius; dotted: the target's own shimmer "
                           "(symmetric log axes: zero is drawn).", c.embed, anchor=f"motion-{figures.slug(scene)}",
                           toc=f"motion: {scene}"))
        body.append("<p>Rankings, lowest first, with the value; <b>bold</b>: tied with the best by the "
                    "two-standard-error rule (mse_target paired over seeds, the motion measures unpaired).</p>")
        body.append(ranking_table(rows, scene))
        body.append(xt_figure(c, rows, scene, panels))
    body.append(loop_part(c.results, os.path.dirname(os.path.abspath(c.study)), c.embed))
    return "\n".join(p for p in body if p)
