"""The other studies a page links to: every folder directly under the results folder that
holds a study CSV (study/study.csv or study.csv, or either .csv.gz), linked to its page (index.html) or else to the CSV, described
from its CSV (scenes,
size, spp, seeds, references, targets), and the repository's presented study (results/index.html) when the
page is written elsewhere (the quick study of README command (a) writes runs/default/index.html)."""
import html
import os

import pandas as pd

from ..findings.study import is_quick
from ..io import text_file
from ..io.study_rows import targets

COLUMNS = ["scene", "width", "height", "spp", "seeds", "ref_spp", "sampler"]


def csv_of(folder):
    for p in (os.path.join(folder, "study", "study.csv"), os.path.join(folder, "study.csv")):
        p = text_file.existing(p)  # or study.csv.gz
        if os.path.isfile(p):
            return p
    return None


def summary(csv):
    """A one-line description of the study in csv, read from its rows ('' when unreadable)."""
    try:
        head = pd.read_csv(csv, nrows=0).columns
        use = [c for c in COLUMNS + ["target", "prefilter", "frames"] if c in head]
        df = pd.read_csv(csv, usecols=use, dtype={"target": str, "prefilter": str})
    except (OSError, EOFError, ValueError, pd.errors.ParserError):  # EOFError: a gzip member cut short
        return ""
    if "target" not in df.columns:
        df["target"] = "box:0.5"
    df = df.dropna(subset=[c for c in COLUMNS if c in df.columns])  # a cut last line: described from the rest
    if df.empty or any(c not in df.columns for c in COLUMNS):
        return ""
    side = df[["width", "height"]].max(axis=1)
    f = dict(size=int(side.max()), spp=sorted(int(x) for x in df["spp"].unique()),
             ref_spp=sorted(int(x) for x in df["ref_spp"].unique()))
    n = df["scene"].nunique()
    text = (f"{n} scene{'' if n == 1 else 's'} at {f['size']} px, {df['sampler'].nunique()} samplers, spp "
            f"{', '.join(map(str, f['spp']))}, {', '.join(str(int(k)) for k in sorted(df['seeds'].unique()))} seeds, "
            f"references at {', '.join(map(str, f['ref_spp']))} spp, targets {', '.join(targets(df))}")
    if "prefilter" in df.columns and (df["prefilter"].astype(str) != "none").any():
        text += "; pre-filtering against plain sampling"
    if "frames" in df.columns and (pd.to_numeric(df["frames"], errors="coerce") > 1).any():
        text += f"; {int(pd.to_numeric(df['frames'], errors='coerce').max())} frames of a moving camera (shimmer)"
    return text + ("; a quick study" if is_quick(f) else "")


def other_studies(results, study, repo):
    """[(href, name, description)] of the studies to link from RESULTS/index.html showing `study`."""
    out = []
    here = os.path.realpath(study)
    for name in sorted(os.listdir(results)):
        folder = os.path.join(results, name)
        page = os.path.join(folder, "index.html")
        csv = csv_of(folder)
        if not os.path.isdir(folder) or csv is None or os.path.realpath(csv) == here:
            continue
        if os.path.isfile(page):
            out.append((f"{name}/index.html", name, summary(csv)))
        else:  # a committed study without a page of its own: its CSV
            rel = os.path.relpath(csv, results).replace(os.sep, "/")
            out.append((rel, name, summary(csv) + " (no page of its own: the link opens its CSV)"))
    presented = os.path.join(repo, "results", "index.html")
    if os.path.realpath(results) != os.path.realpath(os.path.join(repo, "results")) and os.path.isfile(presented):
        out.append((os.path.relpath(presented, results).replace(os.sep, "/"), "the presented study",
                    "the study this repository presents (results/index.html)"))
    return out


def links_html(items):
    if not items:
        return ""
    lis = "".join(f"<li><a href='{html.escape(h)}'>{html.escape(n)}</a>: {html.escape(d)}</li>" for h, n, d in items)
    return f"<div class='note'><b>Other studies.</b><ul>{lis}</ul></div>"
