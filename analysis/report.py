#!/usr/bin/python3
"""Builds results/index.html and the tables for results/README.md.

Usage: /usr/bin/python3 analysis/report.py RESULTS_DIR [--embed] [--study study.csv] [--tables]

index.html is one self-contained page (inline CSS, no scripts, no external
resources): every PNG under RESULTS_DIR, grouped by folder, side by side;
the point sets as a sampler x N grid of point plots and periodograms; the
small CSV tables and Markdown tables (e.g. convergence/slopes.md) as HTML
tables. Images are referenced by relative paths inside RESULTS_DIR, or
embedded as base64 data URIs with --embed.

--tables prints Markdown for README.md instead: the Pareto front of every
scene and the stability counts (from --study, default RESULTS_DIR/study/study.csv),
and a summary of the slope verdicts.
"""
import argparse
import base64
import html
import os
import re
import sys

import pandas as pd

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

CSS = """body{font-family:sans-serif;margin:1.5em;background:#fafafa;color:#222}
h1{font-size:1.5em}h2{border-bottom:1px solid #ccc;margin-top:2em}
.gallery{display:flex;flex-wrap:wrap;gap:12px}
figure{margin:0;background:#fff;border:1px solid #ddd;padding:6px;max-width:48%}
figure img{max-width:100%;height:auto}figcaption{font-size:.8em;color:#555}
table{border-collapse:collapse;font-size:.8em;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 6px}
th{background:#eee}.grid img{width:128px;image-rendering:pixelated}"""
MAX_TABLE_ROWS = 200


def image_src(results, path, embed):
    if embed:
        with open(path, "rb") as f:
            return "data:image/png;base64," + base64.b64encode(f.read()).decode("ascii")
    return html.escape(os.path.relpath(path, results).replace(os.sep, "/"))


def markdown_tables(text):
    """HTML of every Markdown table in text (each a run of '|' lines: header, separator, rows), or ''.
    **bold** inside cells is kept as bold."""
    blocks, block = [], []
    for line in text.splitlines() + [""]:
        if line.strip().startswith("|"):
            block.append(line)
        elif block:
            blocks.append(block)
            block = []
    out = []
    for lines in blocks:
        if len(lines) < 2 or not set(lines[1].replace("|", "").strip()) <= set("-: "):
            continue  # not a table: no separator row under the header
        cells = [[re.sub(r"\*\*(.+?)\*\*", r"<b>\1</b>", html.escape(c.strip()))
                  for c in l.strip().strip("|").split("|")] for l in lines]
        head = "".join(f"<th>{c}</th>" for c in cells[0])
        body = "".join("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in cells[2:])
        out.append(f"<table><tr>{head}</tr>{body}</table>")
    return "\n".join(out)


def pointset_grid(results, folder, files, embed):
    """Sampler x N table of point plots and periodograms; returns (html, files used)."""
    pat = re.compile(r"^(points|periodogram)_(.+)_(\d+)\.png$")
    found = {}
    for f in files:
        m = pat.match(f)
        if m:
            found[(m.group(2), int(m.group(3)), m.group(1))] = f
    if not found:
        return "", set()
    samplers = list(dict.fromkeys(k[0] for k in sorted(found)))
    counts = sorted({k[1] for k in found})
    out = ["<table class='grid'><tr><th>sampler</th>"]
    out += [f"<th>N = {n}: points</th><th>N = {n}: periodogram</th>" for n in counts]
    out.append("</tr>")
    for s in samplers:
        out.append(f"<tr><th>{html.escape(s)}</th>")
        for n in counts:
            for kind in ("points", "periodogram"):
                f = found.get((s, n, kind))
                cell = (f"<img src='{image_src(results, os.path.join(folder, f), embed)}' alt='{kind} {s} {n}'>"
                        if f else "")
                out.append(f"<td>{cell}</td>")
        out.append("</tr>")
    out.append("</table>")
    return "".join(out), set(found.values())


def section(results, folder, embed):
    files = sorted(os.listdir(folder))
    title = os.path.relpath(folder, results)
    parts = [f"<h2>{html.escape('results' if title == '.' else title)}</h2>"]
    for f in files:
        if f.endswith(".md") and f != "README.md":
            with open(os.path.join(folder, f), encoding="utf-8") as fh:
                table = markdown_tables(fh.read())
            if table:
                parts.append(f"<h3>{html.escape(f)}</h3>{table}")
    grid, used = pointset_grid(results, folder, files, embed)
    gallery = [f for f in files if f.endswith(".png") and f not in used]
    if gallery:
        parts.append("<div class='gallery'>")
        for f in gallery:
            src = image_src(results, os.path.join(folder, f), embed)
            parts.append(f"<figure><img src='{src}' alt='{html.escape(f)}'><figcaption>{html.escape(f)}"
                         "</figcaption></figure>")
        parts.append("</div>")
    if grid:
        parts.append("<h3>Point sets and mean periodograms</h3>" + grid)
    for f in files:
        if f.endswith(".csv"):
            try:
                df = pd.read_csv(os.path.join(folder, f))
            except (pd.errors.ParserError, pd.errors.EmptyDataError):
                continue
            if 0 < len(df) <= MAX_TABLE_ROWS:
                parts.append(f"<h3>{html.escape(f)}</h3>" + df.to_html(index=False, border=0,
                                                                       float_format=lambda v: f"{v:.4g}"))
            else:
                parts.append(f"<p>{html.escape(f)}: {len(df)} rows (not shown)</p>")
    return "\n".join(parts) if len(parts) > 1 else ""


def build_index(results, embed=False):
    sections = []
    for folder, dirs, _ in os.walk(results):
        dirs.sort()
        s = section(results, folder, embed)
        if s:
            sections.append(s)
    page = ("<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>aliaslab results</title>"
            f"<style>{CSS}</style></head><body><h1>aliaslab results</h1>"
            "<p>Charts and tables of the reference study; definitions in SCIENCE.md, findings in "
            "README.md.</p>" + "\n".join(sections) + "</body></html>\n")
    path = os.path.join(results, "index.html")
    tmp = path + ".partial"
    try:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(page)
        os.replace(tmp, path)
    except OSError as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        common.fail(f"{results}: cannot write index.html: {e.strerror or e}")
    return path


def markdown(df, float_format="{:.4g}"):
    cols = list(df.columns)
    rows = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    for _, r in df.iterrows():
        rows.append("| " + " | ".join(float_format.format(v) if isinstance(v, float) else str(v)
                                      for v in r) + " |")
    return "\n".join(rows)


def tables(results, study):
    import charts  # the same aggregation and front as the charts
    out = []
    if study:
        df = charts.aggregate(common.read_study_csv(study))
        for scene, sd in df.groupby("scene", sort=True):
            ok = sd[(sd["flagged"] == 0) & (sd["mse"] > 0)].reset_index(drop=True)
            front = ok.iloc[common.pareto_front(ok["time_ms"], ok["mse"])]
            out.append(f"### Pareto front: {scene}\n")
            out.append(markdown(front[["sampler", "spp", "filter", "radius", "reconstruction", "time_ms", "mse"]]))
            out.append("")
        bad = df.groupby(["filter", "radius", "reconstruction"])[
            ["undefined_pixels", "negative_pixels", "nan_pixels", "flagged"]].sum().reset_index()
        bad = bad[(bad[["undefined_pixels", "negative_pixels", "nan_pixels", "flagged"]] > 0).any(axis=1)]
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


def main(argv=None):
    ap = argparse.ArgumentParser(description="results/index.html and README tables")
    ap.add_argument("results", help="results folder")
    ap.add_argument("--embed", action="store_true", help="embed images as base64 data URIs")
    ap.add_argument("--study", help="study CSV for --tables (default RESULTS/study/study.csv, if present)")
    ap.add_argument("--tables", action="store_true", help="print Markdown tables for README.md")
    args = ap.parse_args(argv)
    if not os.path.isdir(args.results):
        common.fail(f"{args.results}: not a folder")
    if args.tables:
        try:
            study = args.study
            if study is None:  # the default study, when there is one
                default = os.path.join(args.results, "study", "study.csv")
                study = default if os.path.isfile(default) else None
                if study is None:
                    print(f"note: no {default}: only the convergence table", file=sys.stderr)
            tables(args.results, study)
        except common.InputError as e:
            common.fail(str(e))
        return 0
    print(f"wrote {build_index(args.results, args.embed)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
