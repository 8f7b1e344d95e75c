#!/usr/bin/python3
"""The report of a study: an HTML page that answers the study's question first.

Usage:
  /usr/bin/python3 analysis/report.py RESULTS_DIR [--study CSV] [--charts DIR] [--images DIR]
                                      [--label TEXT] [--link] [--reuse-charts]
  /usr/bin/python3 analysis/report.py RESULTS_DIR --tables [--study CSV]

Writes RESULTS_DIR/index.html, and RESULTS_DIR/engineering.html when
RESULTS_DIR holds benchmark or fuzzing records (*_speed.md, fuzzing.md).
Defaults: --study RESULTS_DIR/study/study.csv (else RESULTS_DIR/study.csv),
--charts RESULTS_DIR/charts, --images = the study CSV's folder + /images.
Only the one study CSV is read: shard CSVs lying beside it are ignored, and a
CSV that repeats a configuration is refused (exit 2).

The page, in order:
  1. the question and this study's answer, computed from the CSV (lowest
     error against the common target per spp level, the error-vs-time front,
     what an own-mse ranking would have picked, where the error comes from),
     with one chart: error relative to each scene's best against time;
  2. per scene: the decomposition (stacked bars), the radius trade-off, the
     convergence with spp, the error-vs-time chart, the heatmap, the contact
     sheet and the images of the best and the worst method;
  3. stability (undefined / negative / NaN pixels, flagged rows);
  4. samplers and filters in isolation (analytic convergence, point sets,
     filter profiles) when RESULTS_DIR has them;
  5. a link to engineering.html (benchmarks, fuzzing).
The charts are (re)drawn from the study into --charts first (charts.py's
functions), unless --reuse-charts. The page is self-contained (images
embedded as data URIs) unless --link, which refers to the files by relative
path. It names the study it reports: "the reference study" only for the
repository's results/study/study.csv, otherwise the CSV's path (or --label).
Definitions: docs/science.md, linked from the page.

--tables prints Markdown for results/README.md instead (the Pareto front of
every scene by the error against the target, and the stability counts).
"""
import argparse
import base64
import io
import html
import os
import re
import sys

import numpy as np
import pandas as pd

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import charts  # noqa: E402
import common  # noqa: E402
import spectra  # noqa: E402
from common import plt  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REFERENCE_STUDY = os.path.join(REPO, "results", "study", "study.csv")
SCIENCE = os.path.join(REPO, "docs", "science.md")

CSS = """body{font-family:sans-serif;margin:0 auto;max-width:1250px;padding:1em 1.5em;background:#fafafa;
color:#222;line-height:1.45}h1{font-size:1.55em;margin-bottom:.2em}h2{border-bottom:1px solid #ccc;margin-top:2em}
h3{margin-top:1.6em}.facts{color:#555;font-size:.9em}.answer{background:#fff;border-left:4px solid #2a6;
padding:.6em 1em;margin:1em 0}.note{background:#fff8e0;border-left:4px solid #e0a800;padding:.4em 1em;
font-size:.9em}figure{margin:.8em 0;background:#fff;border:1px solid #ddd;padding:6px;display:inline-block;
max-width:100%;box-sizing:border-box;vertical-align:top}figure img{max-width:100%;height:auto}
figcaption{font-size:.85em;color:#444;max-width:60em}table{border-collapse:collapse;font-size:.82em;margin:.5em 0}
td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}th{background:#eee}td:first-child{text-align:left}
.pix img{width:192px;image-rendering:pixelated}.sheet img{max-height:860px;width:auto}.pix figure{margin-right:8px}
.pair{display:flex;flex-wrap:wrap;gap:8px;align-items:flex-start}.pair figure{margin:0}
.pair img{width:256px;image-rendering:pixelated}.pair figure.spec img{width:600px;image-rendering:auto}.pair figcaption{max-width:256px}.pair figure.spec figcaption{max-width:600px}nav a{margin-right:.8em}
details{margin:.6em 0}summary{cursor:pointer;color:#236}code{background:#eee;padding:0 3px}"""


def chart_png_bytes(path):
    """A chart's PNG with a 256-colour palette (no dithering): about a third of the bytes, and a chart has
    far fewer colours than that. Renders are never passed here (their pixels are data). Falls back to the
    file's bytes where Pillow (a dependency of Debian's matplotlib) is missing."""
    try:
        from PIL import Image
    except ImportError:
        with open(path, "rb") as f:
            return f.read()
    out = io.BytesIO()
    with Image.open(path) as im:
        im.convert("RGB").quantize(colors=256, dither=Image.Dither.NONE).save(out, "PNG", optimize=True)
    return out.getvalue()


def image_src(page_dir, path, embed):
    if embed:
        if os.path.basename(os.path.dirname(path)) == "charts":
            data = chart_png_bytes(path)
        else:
            with open(path, "rb") as f:
                data = f.read()
        return "data:image/png;base64," + base64.b64encode(data).decode("ascii")
    return html.escape(os.path.relpath(path, page_dir).replace(os.sep, "/"))


def figure(page_dir, path, caption, embed, cls=""):
    """<figure> of an existing PNG (or '' when the file is missing)."""
    if not os.path.isfile(path):
        return ""
    return (f"<figure class='{cls}'><img src='{image_src(page_dir, path, embed)}' alt='{html.escape(caption)}'>"
            f"<figcaption>{caption}</figcaption></figure>")


def markdown_tables(text):
    """HTML of every Markdown table in text (each a run of '|' lines: header, separator, rows), or ''.
    **bold** inside cells is kept as bold."""
    return "\n".join(b for kind, b in markdown_blocks(text) if kind == "table")


def inline(text):
    text = html.escape(text)
    text = re.sub(r"\*\*(.+?)\*\*", r"<b>\1</b>", text)
    return re.sub(r"`([^`]+)`", r"<code>\1</code>", text)


def markdown_blocks(text):
    """A small Markdown reader for the results/*.md records: [(kind, html)] with kind in heading,
    table, paragraph. Tables need a separator row under the header."""
    out, para, block = [], [], []

    def flush_para():
        if para:
            out.append(("paragraph", "<p>" + inline(" ".join(para)) + "</p>"))
            para.clear()

    def flush_table():
        if not block:
            return
        lines = list(block)
        block.clear()
        if len(lines) < 2 or not set(lines[1].replace("|", "").strip()) <= set("-: "):
            para.extend(lines)  # not a table: no separator row under the header
            return
        cells = [[inline(c.strip()) for c in l.strip().strip("|").split("|")] for l in lines]
        head = "".join(f"<th>{c}</th>" for c in cells[0])
        body = "".join("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in cells[2:])
        out.append(("table", f"<table><tr>{head}</tr>{body}</table>"))

    for line in text.splitlines() + [""]:
        s = line.strip()
        if s.startswith("|"):
            flush_para()
            block.append(line)
            continue
        flush_table()
        flush_para() if not s or s.startswith("#") else None
        if s.startswith("#"):
            level = min(len(s) - len(s.lstrip("#")) + 2, 5)
            out.append(("heading", f"<h{level}>{inline(s.lstrip('#').strip())}</h{level}>"))
        elif s:
            para.append(s)
    flush_table()
    flush_para()
    return out


# ----------------------------------------------------------------------------------------------
# The answer, computed from the study.

def method_name(r):
    return charts.method_label(r, show_recon=False)


METHOD_KEY = ["sampler", "filter_name", "radius", "filter_params", "reconstruction", "prefilter"]


def ranked(df):
    """Unflagged rows with a finite error, with `ratio` = error / the best error of its (scene, spp)."""
    ok = df[(df["flagged"] == 0) & np.isfinite(df["error"].to_numpy(dtype=float))].copy()
    for column, by in (("ratio", ["scene", "spp"]), ("ratio_scene", ["scene"])):
        best = ok.groupby(by)["error"].transform("min")
        with np.errstate(divide="ignore", invalid="ignore"):
            ok[column] = np.where(best > 0, ok["error"] / best, np.where(ok["error"] == 0, 1.0, np.inf))
    return ok


def best_per_spp(df):
    """Per spp level: the method with the lowest median (over scenes) ratio to each scene's best error.
    Returns a list of dicts (spp, method, median ratio, wins, scenes)."""
    ok = ranked(df)
    out = []
    for spp, g in ok.groupby("spp", sort=True):
        med = g.groupby(METHOD_KEY, dropna=False)["ratio"].median()
        if med.empty:
            continue
        key = med.idxmin()
        rows = g[(g[METHOD_KEY] == pd.Series(key, index=METHOD_KEY)).all(axis=1)]
        wins = int((rows["ratio"] <= 1.0).sum())
        out.append({"spp": int(spp), "method": method_name(rows.iloc[0]), "ratio": float(med.min()),
                    "wins": wins, "scenes": int(g["scene"].nunique()), "row": rows.iloc[0]})
    return out


def own_mse_pick(df):
    """At the highest spp level, per scene, the method an own-mse ranking would pick and its error
    relative to the scene's best error against the target. Returns (method, median ratio, scenes) or None."""
    ok = ranked(df)
    if ok.empty:
        return None
    top = ok[ok["spp"] == ok["spp"].max()]
    picks = []
    for _, g in top.groupby("scene"):
        own = g[np.isfinite(g["mse"].to_numpy(dtype=float))]
        if own.empty:
            continue
        picks.append(own.loc[own["mse"].idxmin()])
    if not picks:
        return None
    p = pd.DataFrame(picks)
    names = p.apply(method_name, axis=1)
    return names.value_counts().idxmax(), float(p["ratio"].median()), len(p), int(top["spp"].iloc[0])


def summary_table(df):
    """One point per (method, spp) present in every scene: mean time and the geometric mean over scenes
    of error / the scene's lowest error at any spp level."""
    ok = ranked(df)
    scenes = ok["scene"].nunique()
    with np.errstate(divide="ignore"):
        ok = ok.assign(logratio=np.log(ok["ratio_scene"].astype(float)))
    g = ok.groupby(METHOD_KEY + ["spp"], dropna=False).agg(time_ms=("time_ms", "mean"),
                                                          logratio=("logratio", "mean"),
                                                          scenes=("scene", "nunique")).reset_index()
    g = g[(g["scenes"] == scenes) & np.isfinite(g["logratio"]) & (g["time_ms"] > 0)].copy()
    g["ratio"] = np.exp(g["logratio"])
    return g


def summary_chart(df, out_dir):
    """The one chart of the findings: error relative to each scene's best against time per image."""
    g = summary_table(df)
    fig, ax = plt.subplots(figsize=(10, 5.6))
    name = "summary_error_time"
    if g.empty:
        charts.empty_panel(ax, "no method has a finite error in every scene")
        common.save_figure(fig, out_dir, name)
        return os.path.join(out_dir, name + ".png"), []
    levels = sorted(g["spp"].unique())
    samplers = sorted(g["sampler"].unique())
    colours = {s: common.colour(i) for i, s in enumerate(samplers)}
    sizes = {s: 18 + 60 * i / max(1, len(levels) - 1) for i, s in enumerate(levels)}
    for (sampler, pre), h in g.groupby(["sampler", "prefilter"]):
        ax.scatter(h["time_ms"], h["ratio"], s=h["spp"].map(sizes), color=colours[sampler], alpha=0.75,
                   edgecolors="black" if pre != "none" else "none", linewidths=1.5)
    front = g.iloc[common.pareto_front(g["time_ms"], g["ratio"])]
    ax.plot(front["time_ms"], front["ratio"], "k--", lw=1)
    lines = []
    for k, (_, r) in enumerate(front.iterrows(), 1):
        lines.append(f"{k}. {method_name(r)}, {int(r['spp'])} spp: x{r['ratio']:.3g}, {r['time_ms']:.3g} ms")
    ax.set_xscale("log")
    ax.set_yscale("log")
    charts.plain_log_x(ax)
    ax.set_ylim(bottom=float(g["ratio"].min()) / 1.5)
    clipped = charts.clip_outliers(ax, g["time_ms"], g["ratio"])
    ax.set_xlabel("time per image (ms, mean over scenes)")
    ax.set_ylabel("error / the scene's lowest error at any spp\n(geometric mean over scenes; 1 = best)")
    ax.grid(True, which="both", alpha=0.25)
    handles = [plt.Line2D([], [], ls="", marker="o", color=colours[s], label=s) for s in samplers]
    handles += [plt.Line2D([], [], ls="", marker="o", color="grey", ms=np.sqrt(sizes[s]), label=f"{int(s)} spp")
                for s in levels]
    handles.append(plt.Line2D([], [], ls="--", color="k", label="Pareto front (numbered)"))
    if (g["prefilter"] != "none").any():
        handles.append(plt.Line2D([], [], ls="", marker="o", mfc="white", mec="black", mew=1.5, label="pre-filtered"))
    leg = ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0),
                    title="colour: sampler, size: spp", title_fontsize=7)
    leg.set_in_layout(True)
    # the numbered front below the plot, in columns of at most 8 lines (beside the legend it collided with
    # it once there were a dozen samplers)
    shown = lines[:24] + ([f"... {len(lines) - 24} more"] if len(lines) > 24 else [])
    per_col = 8
    for c in range(0, len(shown), per_col):
        ax.text(0.55 * (c // per_col), -0.17, ("Pareto front:\n" if c == 0 else "\n") + "\n".join(shown[c:c + per_col]),
                transform=ax.transAxes, fontsize=7, va="top", family="monospace")
    ax.set_title("Error against the target vs time, every method at every spp level, all scenes"
                 + (f"\n{clipped}" if clipped else ""), fontsize=10)
    charts.number_points(ax, list(front["time_ms"]), list(front["ratio"]))
    common.save_figure(fig, out_dir, name)
    return os.path.join(out_dir, name + ".png"), lines


def fmt(v):
    return f"{v:.2g}" if np.isfinite(v) else "n/a"


def findings(df, notes, target):
    """The answer in sentences (HTML paragraphs), computed from the study."""
    ok = ranked(df)
    scenes = df["scene"].nunique()
    out = []
    if ok.empty:
        return ["<p>No row has a finite error against the target and an unflagged reference: this study "
                "cannot answer the question. See the stability section.</p>"]
    best = best_per_spp(df)
    groups = []  # consecutive spp levels with the same best method
    for b in best:
        if groups and groups[-1][0]["method"] == b["method"]:
            groups[-1].append(b)
        else:
            groups.append([b])
    parts = []
    for g in groups:
        levels = ", ".join(str(b["spp"]) for b in g)
        ratios = ", ".join(f"{b['ratio']:.2f}x" for b in g)
        wins = ", ".join(f"{b['wins']}" for b in g)
        if all(b["ratio"] == 1.0 and b["wins"] == b["scenes"] for b in g):
            detail = f"the best in every scene ({g[0]['scenes']})"
        else:
            detail = (f"error relative to each scene's best: {ratios}, median over {g[0]['scenes']} scene(s); "
                      f"best outright in {wins} scene(s)")
        parts.append(f"at {levels} spp <b>{html.escape(g[0]['method'])}</b> ({detail})")
    out.append("<p>Lowest error against the target: " + "; ".join(parts) + ".</p>")
    table = summary_table(df)
    if len(table):
        front = table.iloc[common.pareto_front(table["time_ms"], table["ratio"])]
        first, last = front.iloc[0], front.iloc[-1]
        if len(front) == 1:
            out.append(f"<p>For the time spent, one method is both the fastest and the most accurate: "
                       f"<b>{html.escape(method_name(first))} at {int(first['spp'])} spp</b> "
                       f"({first['time_ms']:.3g} ms).</p>")
        else:
            out.append(f"<p>For the time spent, the Pareto front (nothing both faster and more accurate) runs from "
                       f"<b>{html.escape(method_name(first))} at {int(first['spp'])} spp</b> ({first['time_ms']:.3g} "
                       f"ms, {first['ratio']:.3g}x the scene's lowest error) to <b>{html.escape(method_name(last))} at "
                       f"{int(last['spp'])} spp</b> ({last['time_ms']:.3g} ms, {last['ratio']:.3g}x); {len(front)} "
                       "methods on it in all (numbered on the chart below).</p>")
    pick = own_mse_pick(df)
    if pick:
        name, ratio, n, spp = pick
        if ratio > 1.0 + 1e-12:
            out.append(f"<p>Ranked by each filter's own mse (against its own reference, blind to blur), "
                       f"{html.escape(name)} would win at {spp} spp; against the common target its error is "
                       f"{ratio:.3g}x the best (median over {n} scene(s)). That is why every ranking here uses "
                       "the error against the target.</p>")
        else:
            out.append(f"<p>Here the own-mse ranking agrees with the error against the target at {spp} spp "
                       f"({html.escape(name)}).</p>")
    if best:
        top = ok[ok["spp"] == best[-1]["spp"]]
        winners = top.loc[top.groupby("scene")["error"].idxmin()]
        terms = [c for c, _ in charts.components(df)]
        shares = {c: np.nanmedian(winners[c] / winners["error"].where(winners["error"] > 0)) for c in terms}
        words = {"noise": "noise", "aliasing": "aliasing", "blur": "blur", "cross": "the cross term",
                 "blur_cross": "blur with the cross term"}
        out.append(f"<p>Where the error of each scene's best method at {best[-1]['spp']} spp comes from (median "
                   "share): " + ", ".join(f"{words[c]} {100 * shares[c]:.0f}%" for c in terms) + ".</p>")
    if "aliasing_se" in df.columns:
        zero = int(df["aliasing_zero"].sum())
        neg = int((df["aliasing"] < 0).sum())
        out.append(f"<p>Aliasing is zero within error (|aliasing| &le; 2 standard errors) in {zero} of {len(df)} "
                   f"rows; {neg} row(s) have a negative aliasing estimate"
                   + (", every one of them zero within error" if neg and
                      df.loc[df["aliasing"] < 0, "aliasing_zero"].all() else "") + ".</p>")
    if (df["prefilter"] != "none").any():
        out.append(prefilter_finding(ok))
    flagged = int((df["flagged"] == 1).sum())
    out.append(f"<p>{scenes} scene(s), {len(df)} configurations, target <code>{html.escape(target)}</code>; "
               f"{flagged} row(s) flagged (reference not converged enough for the row to count) and left out "
               "of the rankings.</p>")
    return out


def prefilter_finding(ok):
    """Pre-filtered at the lowest spp against plain sampling at each higher spp (medians over scenes)."""
    low = ok["spp"].min()
    pre = ok[(ok["prefilter"] != "none") & (ok["spp"] == low)]
    if pre.empty:
        return "<p>No pre-filtered row with a finite error at the lowest spp.</p>"
    pre_best = pre.loc[pre.groupby("scene")["error"].idxmin()].set_index("scene")
    parts = []
    for spp in sorted(ok["spp"].unique()):
        plain = ok[(ok["prefilter"] == "none") & (ok["spp"] == spp)]
        if plain.empty:
            continue
        pb = plain.loc[plain.groupby("scene")["error"].idxmin()].set_index("scene")
        common_scenes = pre_best.index.intersection(pb.index)
        if not len(common_scenes):
            continue
        er = np.median(pre_best.loc[common_scenes, "error"] / pb.loc[common_scenes, "error"])
        tr = np.median(pre_best.loc[common_scenes, "time_ms"] / pb.loc[common_scenes, "time_ms"])
        parts.append(f"plain {int(spp)} spp: error x{er:.2f}, time x{tr:.2f}")
    return (f"<p>Pre-filtered at {int(low)} spp (best pre-filtered method per scene) against the best plain "
            f"sampling: " + "; ".join(parts) + " (medians over scenes; below 1 = the pre-filtered image is "
            "better or faster). The error-vs-time chart of each scene rings pre-filtered rows in black.</p>")


# ----------------------------------------------------------------------------------------------
# Per scene.

def method_image(images, scene, r):
    """Paths (image, error image) of a row's seed-0 reconstruction, or None when the sweep wrote none."""
    folder = os.path.join(images, common.slug(scene))
    stem = f"{r['sampler']}-spp{int(r['spp'])}-{r['filter_name']}-r{r['radius']:g}-{r['reconstruction']}"
    candidates = [stem]
    if r["prefilter"] not in ("none", ""):
        candidates = [f"{stem}-{r['prefilter']}", f"{stem}-prefilter-{r['prefilter']}"]
    for c in candidates:
        p = os.path.join(folder, c + ".png")
        if os.path.isfile(p):
            return p, os.path.join(folder, c + "-error.png")
    return None


def scene_table(sd):
    """HTML table of the scene's three lowest errors at each spp level, with their terms."""
    terms = charts.components(sd)
    extra = [(c, l) for c, l in (("blurred_mse", "blurred mse"), ("flip", "FLIP"),
                                 ("lowfreq_error", "low-frequency share &plusmn; se"),
                                 ("mean_spp", "mean spp spent")) if c in sd.columns]
    ok = sd[(sd["flagged"] == 0) & np.isfinite(sd["error"].to_numpy(dtype=float))]
    rows = []
    for spp, g in ok.groupby("spp", sort=True):
        for _, r in g.nsmallest(3, "error").iterrows():
            se = r["error_se"]
            err = f"{r['error']:.3g}" + (f" &plusmn; {se:.1g}" if np.isfinite(se) else "")
            cells = [html.escape(method_name(r)), str(int(spp)), err]
            for c, _ in terms:
                v = f"{r[c]:.2g}"
                if c == "aliasing" and r["aliasing_zero"]:
                    v += " (0 within error)"
                cells.append(v)
            for c, _ in extra:
                v = f"{r[c]:.3g}"
                se = r.get(c + "_se", np.nan)
                if c == "lowfreq_error" and np.isfinite(se):
                    v += f" &plusmn; {se:.1g}"
                cells.append(v)
            cells.append(f"{r['time_ms']:.3g}")
            rows.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    head = (["method", "spp", "error &plusmn; se"] + [html.escape(l) for _, l in terms]
            + [l for _, l in extra] + ["time (ms)"])
    return ("<table><tr>" + "".join(f"<th>{h}</th>" for h in head) + "</tr>" + "".join(rows) + "</table>")


def spectrum_section(page_dir, scene, sd, spec, charts_dir, images, embed):
    """Issue 22: where the error sits on screen. An overview chart of every sampler's error spectrum at one
    spp, then, at 4 and 16 spp, an independent and a correlated sampler side by side (error images, their
    spectra, mse, blurred mse, FLIP). Says so instead of failing when spectra or images are absent."""
    head = "<h4>Where the error sits on screen</h4>"
    if spec is None or not (spec["scene"] == str(scene)).any():
        return (head + "<p class='note'>No error spectra for this scene (the study CSV has no "
                "<code>spectra/</code> files beside it: written by sweeps since issue 22).</p>")
    spec = spec[spec["scene"] == str(scene)]
    levels = sorted(int(x) for x in spec["spp"].unique())
    parts = [head, f"<p>Radially averaged power spectra of the per-seed error images (I<sub>k</sub> &minus; G), "
             f"frequency in cycles per pixel; the dotted line is a quarter of Nyquist "
             f"({spectra.CUTOFF:g} cycles/pixel), below which <code>lowfreq_error</code> counts the error's "
             "energy. White error is flat; error moved to high frequencies (what the correlated samplers aim "
             "for) rises to the right. "
             "Definitions: docs/spectrum.md.</p>"]
    spp0 = spectra.pick_spp(levels, 16)
    overview = spectra.chart(spec, scene, spp0, spectra.chart_path(charts_dir, scene, spp0))
    if overview:
        parts.append(figure(page_dir, overview, f"Error spectra of every sampler at {spp0} spp.", embed))
    ind, corr = spectra.pick_samplers(spec["sampler"].unique())
    if ind is None or not corr:
        parts.append("<p class='note'>Side-by-side comparison omitted: the study needs an independent and a "
                     "correlated sampler (<code>zsobol</code> or <code>bluenoise-dither:BASE</code>).</p>")
        return "\n".join(p for p in parts if p)
    pair = [ind, corr[0]]
    has_flip = "flip" in sd.columns and np.isfinite(sd["flip"].to_numpy(dtype=float)).any()
    has_blur = "blurred_mse" in sd.columns
    if not has_flip:
        parts.append("<p class='note'>FLIP is not shown: this study CSV has no <code>flip</code> column.</p>")
    shown = [s for s in (4, 16) if s in levels] or levels[:2]
    filt, radius, recon = spectra.common_method(spec)
    for spp in shown:
        rows = sd[(sd["spp"] == spp) & (sd["filter_name"] == filt) & (sd["radius"] == float(radius))
                  & (sd["reconstruction"] == recon) & (sd["prefilter"].astype(str) == "none")]
        cells, pics = [], []
        for sampler in pair:
            r = rows[rows["sampler"] == sampler]
            if not len(r):
                continue
            r = r.iloc[0]
            vals = [f"mse {r['mse']:.3g}" + (f" &plusmn; {r['mse_se']:.1g}" if "mse_se" in r and
                                             np.isfinite(r["mse_se"]) else "")]
            if has_blur:
                vals.append(f"blurred mse {r['blurred_mse']:.3g}")
            if "lowfreq_error" in r:
                se = r.get("lowfreq_error_se", np.nan)
                vals.append(f"low-frequency share {r['lowfreq_error']:.3g}"
                            + (f" &plusmn; {se:.1g}" if np.isfinite(se) else ""))
            if has_flip:
                vals.append(f"FLIP {r['flip']:.3g}")
            cells.append(f"<tr><td>{html.escape(sampler)}</td>" + "".join(f"<td>{v}</td>" for v in vals) + "</tr>")
            found = method_image(images, scene, r)
            if found:
                pics.append(figure(page_dir, found[1], f"{html.escape(sampler)}, {spp} spp: signed error of "
                                   "seed 0 (red too bright, blue too dark)", embed))
        png = spectra.chart(spec, scene, spp, spectra.chart_path(charts_dir, scene, spp, "spectrum_pair"),
                            samplers=pair, title=f"{scene}: {pair[0]} vs {pair[1]} at {spp} spp")
        if png:
            pics.append(figure(page_dir, png, f"Their error spectra at {spp} spp.", embed, cls="spec"))
        pics = [p for p in pics if p]
        parts.append(f"<h5>{spp} spp: {html.escape(pair[0])} (independent) vs {html.escape(pair[1])} "
                     f"(correlated), {html.escape(filt)} r={float(radius):g}</h5>")
        if cells:
            parts.append("<table>" + "".join(cells) + "</table>")
        if pics:
            parts.append("<div class='pair'>" + "".join(pics) + "</div>")
        else:
            parts.append("<p class='note'>No images for these rows (run the sweep with <code>--images</code>).</p>")
    return "\n".join(p for p in parts if p)


def scene_section(page_dir, scene, sd, charts_dir, images, embed, spec=None):
    s = common.slug(scene)
    parts = [f"<h3 id='scene-{html.escape(s)}'>{html.escape(scene)}</h3>", scene_table(sd)]
    chart = lambda kind, caption: figure(page_dir, os.path.join(charts_dir, f"{kind}_{s}.png"), caption, embed)
    parts.append(chart("decomposition", "Where the error comes from: noise, aliasing and blur stacked, the cross "
                       "term hatched (negative terms left of 0), the total with &plusmn;2 standard errors."))
    parts.append(chart("radius", "The radius trade-off per filter: a wider filter lowers noise (dashed) and "
                       "adds blur (dotted)."))
    parts.append(chart("convergence", "Convergence with spp (slopes only over at least three spp levels)."))
    parts.append(chart("speed_accuracy", "Error against the target vs time per image; the Pareto front is "
                       "numbered and listed."))
    heat = chart("heatmap", "Error over filter x radius, one row per spp level.")
    if heat:
        parts.append(f"<details><summary>Error over filter x radius (heatmap)</summary>{heat}</details>")
    sheet = os.path.join(images, f"contact-{s}.png")
    if os.path.isfile(sheet):
        caption = "Contact sheet: zoomed crops of the hardest region."
        txt = os.path.join(images, f"contact-{s}.txt")
        if os.path.isfile(txt):
            with open(txt, encoding="utf-8", errors="replace") as f:
                caption = "Contact sheet: " + html.escape(f.readline().strip())
        parts.append(figure(page_dir, sheet, caption, embed, cls="sheet"))
    ok = sd[(sd["flagged"] == 0) & np.isfinite(sd["error"].to_numpy(dtype=float))]
    if len(ok):
        top = ok[ok["spp"] == ok["spp"].max()]
        pics = []
        target = os.path.join(images, s, "reference-area.png")
        pics.append(figure(page_dir, target, "pixel-area reference" + (" (the target)" if set(
            sd["target"].astype(str)) <= {"box:0.5", "area"} else ""), embed))
        for what, r in (("best", top.loc[top["error"].idxmin()]), ("worst", top.loc[top["error"].idxmax()])):
            found = method_image(images, scene, r)
            if found:
                label = f"{what}: {html.escape(method_name(r))}, {int(r['spp'])} spp, error {r['error']:.2g}"
                pics.append(figure(page_dir, found[0], label, embed))
                pics.append(figure(page_dir, found[1], f"{what}: signed error (red too bright, blue too dark)",
                                   embed))
        pics = [p for p in pics if p]
        if len(pics) > 1:
            parts.append("<div class='pix'>" + "".join(pics) + "</div>")
    parts.append(spectrum_section(page_dir, scene, sd, spec, charts_dir, images, embed))
    return "\n".join(p for p in parts if p)


# ----------------------------------------------------------------------------------------------

def study_label(study, label):
    if label:
        return label
    if os.path.realpath(study) == os.path.realpath(REFERENCE_STUDY):
        return "the reference study (results/study/study.csv)"
    return f"the study {shown_path(study)}"


def shown_path(path):
    """path relative to the repository when inside it, else absolute."""
    full = os.path.realpath(path)
    rel = os.path.relpath(full, os.path.realpath(REPO))
    return full if rel.startswith("..") else rel


def write_page(path, title, body):
    page = ("<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>"
            f"<meta name='viewport' content='width=device-width'><title>{html.escape(title)}</title>"
            f"<style>{CSS}</style></head><body>{body}</body></html>\n")
    tmp = path + ".partial"
    try:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(page)
        os.replace(tmp, path)
    except OSError as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        common.fail(f"{os.path.dirname(path) or '.'}: cannot write {os.path.basename(path)}: {e.strerror or e}")
    return path


ENGINEERING = re.compile(r"(_speed|^fuzzing)\.md$")


def engineering_page(results, science_href):
    files = sorted(f for f in os.listdir(results) if ENGINEERING.search(f))
    if not files:
        return None
    body = ["<h1>aliaslab: engineering records</h1>",
            "<p><a href='index.html'>Back to the report</a>. Measured benchmarks and fuzzing counts, as recorded "
            f"in the results folder (definitions: <a href='{science_href}'>docs/science.md</a>).</p>"]
    for f in files:
        with open(os.path.join(results, f), encoding="utf-8", errors="replace") as fh:
            body.append(f"<h2>{html.escape(f)}</h2>" + "\n".join(b for _, b in markdown_blocks(fh.read())))
    return write_page(os.path.join(results, "engineering.html"), "aliaslab engineering records", "\n".join(body))


def isolation_section(results, embed):
    """Samplers and filters on their own (convergence on integrands, point sets, filter profiles)."""
    parts = []
    for rel, caption in (("convergence/convergence.png", "RMSE against N on analytic integrands, fitted slopes."),
                         ("pointsets/discrepancy.png", "Point sets: discrepancy and minimum distance."),
                         ("pointsets/spectra.png", "Point sets: radial power spectra."),
                         ("filters/filter_profiles.png", "Filter profiles and frequency responses.")):
        parts.append(figure(results, os.path.join(results, rel), caption, embed))
    slopes = os.path.join(results, "convergence", "slopes.md")
    if os.path.isfile(slopes):
        with open(slopes, encoding="utf-8") as f:
            table = markdown_tables(f.read())
        if table:
            parts.append(f"<details><summary>Convergence slopes against theory</summary>{table}</details>")
    parts = [p for p in parts if p]
    return ("<h2 id='isolation'>Samplers and filters in isolation</h2>" + "\n".join(parts)) if parts else ""


def build_report(results, study, charts_dir=None, images=None, label=None, embed=True, draw=True):
    """Writes RESULTS/index.html (and engineering.html); returns the index path. Raises common.InputError."""
    df, notes = common.load_study(study)
    spec = spectra.load(study)
    charts_dir = charts_dir or os.path.join(results, "charts")
    images = images or os.path.join(os.path.dirname(os.path.abspath(study)), "images")
    if draw:
        charts.draw_all(df, charts_dir)
    common.prepare_out(charts_dir, "--charts")
    summary_png, _ = summary_chart(df, charts_dir)
    name = study_label(study, label)
    targets = sorted(df["target"].astype(str).unique())
    target = ", ".join(common.describe_target(t) for t in targets)
    science = html.escape(os.path.relpath(SCIENCE, results).replace(os.sep, "/"))
    scenes = sorted(df["scene"].unique())
    levels = sorted(int(s) for s in df["spp"].unique())
    facts = (f"{len(scenes)} scene(s); samplers {', '.join(sorted(df['sampler'].unique()))}; filters "
             f"{', '.join(sorted(df['filter_name'].unique()))}; radii "
             f"{', '.join(f'{r:g}' for r in sorted(df['radius'].unique()))}; spp {', '.join(map(str, levels))}; "
             f"seeds {', '.join(str(int(k)) for k in sorted(df['seeds'].unique()))}; target {target}. "
             f"Read from <code>{html.escape(shown_path(study))}</code>.")
    body = [f"<h1>aliaslab report: {html.escape(name)}</h1>", f"<p class='facts'>{facts}</p>",
            "<nav><a href='#findings'>Findings</a><a href='#scenes'>Scenes</a><a href='#stability'>Stability</a>"
            + ("<a href='#isolation'>Samplers and filters</a>" if os.path.isdir(os.path.join(results, "pointsets"))
               else "") + f"<a href='{science}'>Definitions (docs/science.md)</a></nav>",
            "<h2 id='findings'>Findings</h2>",
            "<p><b>Question.</b> Which sampler, filter and radius give the lowest error against the common target "
            f"(<code>{html.escape(target)}</code>) for the time they take? The error of a configuration is its mean "
            "squared difference from the target over seeds, pixels and channels; it splits into noise (changes "
            "with the seed), aliasing (structured error that stays), blur (the filter's own reference against "
            f"the target) and a cross term. Definitions: <a href='{science}'>docs/science.md</a>.</p>",
            "<div class='answer'><b>Answer for this study.</b>" + "".join(findings(df, notes, target)) + "</div>"]
    if notes:
        body.append("<div class='note'><b>About this CSV.</b> " + " ".join(html.escape(n) for n in notes) + "</div>")
    body.append(figure(results, summary_png, "Every method at every spp level: its error relative to each scene's "
                       "lowest error at any spp level (geometric mean over scenes) against its time; the Pareto "
                       "front is numbered and listed.", embed))
    body.append("<h2 id='scenes'>Per scene</h2><p>" + " ".join(
        f"<a href='#scene-{html.escape(common.slug(s))}'>{html.escape(s)}</a>" for s in scenes) + "</p>")
    for scene in scenes:
        body.append(scene_section(results, scene, df[df["scene"] == scene], charts_dir, images, embed,
                                  spec))
    body.append("<h2 id='stability'>Stability</h2>")
    counts = {c: int(np.nansum(df[c].to_numpy(dtype=float))) for c in
              ("undefined_pixels", "negative_pixels", "nan_pixels")}
    body.append(f"<p>Over all rows: {counts['undefined_pixels']} undefined, {counts['negative_pixels']} negative "
                f"and {counts['nan_pixels']} NaN/Inf pixels; {int((df['flagged'] == 1).sum())} flagged row(s) "
                "(listed in charts/flagged.csv).</p>")
    body.append(figure(results, os.path.join(charts_dir, "stability.png"), "Pixel failure counts per method and "
                       "sampler, summed over scenes and spp; empty panels: no such pixel.", embed))
    body.append(isolation_section(results, embed))
    eng = engineering_page(results, science)
    if eng:
        body.append("<h2>Engineering</h2><p>Benchmarks and fuzzing records are on their own page: "
                    "<a href='engineering.html'>engineering.html</a>.</p>")
    return write_page(os.path.join(results, "index.html"), f"aliaslab report: {name}", "\n".join(body))


# ----------------------------------------------------------------------------------------------

def markdown(df, float_format="{:.4g}"):
    cols = list(df.columns)
    rows = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    for _, r in df.iterrows():
        rows.append("| " + " | ".join(float_format.format(v) if isinstance(v, float) else str(v)
                                      for v in r) + " |")
    return "\n".join(rows)


def tables(results, study):
    out = []
    if study:
        df, notes = common.load_study(study)
        out += [f"_{n}_\n" for n in notes]
        for scene, sd in df.groupby("scene", sort=True):
            ok = sd[(sd["flagged"] == 0) & (sd["error"] > 0) & np.isfinite(sd["error"])].reset_index(drop=True)
            front = ok.iloc[common.pareto_front(ok["time_ms"], ok["error"])]
            out.append(f"### Pareto front (error against the target): {scene}\n")
            out.append(markdown(front[["sampler", "spp", "filter_name", "radius", "reconstruction", "time_ms",
                                       "error"]].rename(columns={"filter_name": "filter"})))
            out.append("")
        cols = ["undefined_pixels", "negative_pixels", "nan_pixels", "flagged"]
        bad = df.groupby(["filter_name", "radius", "reconstruction"])[cols].sum().reset_index()
        bad = bad[(bad[cols] > 0).any(axis=1)].rename(columns={"filter_name": "filter"})
        out.append("### Stability (counts summed over scenes, samplers and spp)\n")
        out.append(markdown(bad) if len(bad) else "No undefined, negative or NaN pixels and no flagged rows.")
        out.append("")
    slopes = os.path.join(results, "convergence", "slopes.md")
    if os.path.isfile(slopes):
        with open(slopes, encoding="utf-8") as f:
            rows = [l for l in f if l.startswith("| ") and not l.startswith("| sampler")]
        verdicts = pd.Series([l.strip().strip("|").split("|")[-1].strip() for l in rows]).value_counts()
        out.append("### Convergence slopes against theory\n")
        out.append(", ".join(f"{k}: {v}" for k, v in verdicts.items()) + " (details: convergence/slopes.md)")
    print("\n".join(out))


def default_study(results):
    for p in (os.path.join(results, "study", "study.csv"), os.path.join(results, "study.csv")):
        if os.path.isfile(p):
            return p
    return None


def main(argv=None):
    ap = argparse.ArgumentParser(description="The HTML report of an aliaslab study (findings first); "
                                 "definitions in docs/science.md")
    ap.add_argument("results", help="folder the report is written into (index.html, engineering.html)")
    ap.add_argument("--study", help="study CSV (default RESULTS/study/study.csv, else RESULTS/study.csv)")
    ap.add_argument("--charts", help="folder of the charts, drawn there from the study (default RESULTS/charts)")
    ap.add_argument("--images", help="folder of the sweep's images (default: the study CSV's folder/images)")
    ap.add_argument("--label", help="how the page names the study (default: the reference study for "
                    "results/study/study.csv, else the CSV's path)")
    ap.add_argument("--link", action="store_true", help="refer to images by relative path instead of embedding")
    ap.add_argument("--embed", action="store_true", help="embed images (the default; kept for old scripts)")
    ap.add_argument("--reuse-charts", action="store_true", help="do not redraw the charts already in --charts")
    ap.add_argument("--tables", action="store_true", help="print Markdown tables for results/README.md")
    args = ap.parse_args(argv)
    if not os.path.isdir(args.results):
        common.fail(f"{args.results}: not a folder")
    if args.link and args.embed:
        common.fail("--link and --embed: choose one")
    study = args.study or default_study(args.results)
    if args.study is not None and not os.path.isfile(args.study):
        common.fail(f"--study: {args.study}: no such file")
    try:
        if args.tables:
            if study is None:
                print(f"note: no study CSV in {args.results}: only the convergence table", file=sys.stderr)
            tables(args.results, study)
            return 0
        if study is None:
            common.fail(f"{args.results}: no study/study.csv or study.csv in it: give --study")
        path = build_report(args.results, study, args.charts, args.images, args.label, embed=not args.link,
                            draw=not args.reuse_charts)
    except common.InputError as e:
        common.fail(str(e))
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
