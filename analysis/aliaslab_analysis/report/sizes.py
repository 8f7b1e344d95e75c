"""The quick study against the presented one: the same scenes at two image sizes, compared
on what both hold (stats/sizes.py: the shared scenes, spp, targets and methods, ranked as answer.csv ranks
them), in words and a table generated from the two CSVs.

The page shows it when a quick study is found (`report --quick CSV`, else RESULTS/study/study.csv when it exists
and is not the page's own study) whose images are smaller than those of the page's study. Nothing is shown (and the
page says why in one line) when the two share no scene, spp level or target."""
import html
import os

import numpy as np

from ..io import study_csv, text_file
from ..findings.study import facts, plural
from ..stats import factors, sizes


def quick_csv(results, study, given=None):
    """The quick study to reconcile the page's study with (module doc), or None."""
    path = given or text_file.existing(os.path.join(results, "study", "study.csv"))  # or study.csv.gz
    if not os.path.isfile(path) or os.path.realpath(path) == os.path.realpath(study):
        return None
    return path


def names(samplers, present, fixed=()):
    """Samplers with families named (factors.family_names), the fixed grid (the samplers in `fixed`) named so."""
    out = [f"{n} ({len(m)})" if m else n + (" (fixed grid)" if n in fixed else "")
           for n, m in factors.family_names(list(samplers), present)]
    return ", ".join(out) if out else "none"


STATUS = {factors.MOST: "<i>none in half the scenes; most often:</i> ",
          factors.NONE: "<i>none within the margin; closest:</i> "}


def pct(v):
    return "&ndash;" if not np.isfinite(v) else f"{100 * v:.0f} %"


def ratio(v):
    return "not told from zero" if not np.isfinite(v) else "1x (the best)" if v == 1 else f"{v:.3g}x"


def spread(rho):
    rho = rho[np.isfinite(rho)]
    if not len(rho):
        return "&ndash;"
    return f"{np.median(rho):.2f} [{rho.min():.2f}&ndash;{rho.max():.2f}]"


def size_of(df):
    f = facts(df)
    return f"{f['size']} px" + (f", the smallest scene {f['smallest']} px" if f["smallest"] != f["size"] else "")


def missing_text(c, small, large):
    if not c.missing:
        return "Both studies hold the same scenes, spp, targets, samplers, filters and radii."
    parts = []
    for what, a, b in c.missing:
        side = [f"only at {small}: {', '.join(map(str, a))}" if a else "",
                f"only at {large}: {', '.join(map(str, b))}" if b else ""]
        parts.append(f"{what} ({'; '.join(s for s in side if s)})")
    return "Not compared (one study lacks them): " + "; ".join(parts) + "."


def answer_rows(c, small, large):
    rows = []
    fixed = set(c.moves.loc[c.moves["deterministic_small"].astype(bool), "sampler"])
    for _, a in c.answers.iterrows():
        r = c.ranks[(c.ranks["target"] == a["target"]) & (c.ranks["spp"] == a["spp"])]["rho"].to_numpy(dtype=float)
        cells = []
        for side in sizes.SIDES:
            lead = STATUS.get(a["status_" + side], "")
            cells.append(f"{lead}{html.escape(names(a['samplers_' + side], c.samplers, fixed))}<br><small>with "
                         f"{html.escape(', '.join(a['configs_' + side]) or '-')}</small>")
        same = ("same samplers" if a["same_samplers"] else "<b>other samplers</b>") + ", " + \
               ("same filter" if a["same_filters"] else "<b>other filter</b>")
        rows.append(f"<tr><td><code>{html.escape(a['target'])}</code></td><td>{a['spp']}</td><td>{cells[0]}</td>"
                    f"<td>{cells[1]}</td><td>{same}</td><td>{spread(r)}</td></tr>")
    return (f"<table class='sizes'><tr><th>target</th><th>spp</th><th>leading at {small}</th><th>leading at {large}"
            "</th><th>the answer</th><th>rank agreement &rho; median [range over scenes]</th></tr>"
            + "".join(rows) + "</table>")


def scene_rows(c, small, large, top):
    rows = []
    for scene in c.scenes:
        r = c.ranks[c.ranks["scene"] == scene]["rho"].to_numpy(dtype=float)
        sh = c.shares[c.shares["scene"] == scene]
        noise = "<br>".join(f"{s['spp']}: {pct(s['noise_share_small'])} &rarr; {pct(s['noise_share_large'])}"
                                  for _, s in sh.iterrows())
        g = c.grid[(c.grid["scene"] == scene) & (c.grid["spp"] == top)]
        grid = (f"{ratio(g.iloc[0]['ratio_small'])} &rarr; {ratio(g.iloc[0]['ratio_large'])}" if len(g)
                else "&ndash;")
        rows.append(f"<tr><td>{html.escape(scene)}</td><td>{spread(r)}</td><td>{noise}</td><td>{grid}</td></tr>")
    return (f"<table class='sizes'><tr><th>scene</th><th>&rho; median [range over targets and spp]</th><th>noise "
            f"share of the error, {small} &rarr; {large}, per spp</th><th>fixed grid's ratio to the best at {top} "
            f"spp, {small} &rarr; {large}</th></tr>" + "".join(rows) + "</table>")


def movers(m, col):
    """[(value, median factor, n)] per value of column col, largest median factor first."""
    g = m.groupby(col)["factor"]
    out = [(k, float(v), int(g.get_group(k).notna().sum())) for k, v in g.median().items() if np.isfinite(v)]
    return sorted(out, key=lambda t: -t[1])


def mover_text(m, small, large):
    """The per-row factor (ratio to the best at the large size over that at the small one), median per group:
    the groups with the largest and the smallest, by sampler, filter and radius."""
    parts = []
    for col, what in (("sampler", "sampler"), ("filter_name", "filter"), ("radius", "radius")):
        mv = movers(m, col)
        if len(mv) < 2:
            continue
        name = (lambda v: f"r={v:g}") if col == "radius" else str
        (hi, fh, nh), (lo, fl, nl) = mv[0], mv[-1]
        parts.append(f"by {what} from {fh:.3g} ({html.escape(name(hi))}, {nh} rows) to {fl:.3g} "
                     f"({html.escape(name(lo))}, {nl} rows)")
    if not parts:
        return ""
    return (f"<b>What moves.</b> The median over a group's rows of (ratio to the best at {large}) / (ratio at "
            f"{small}) (above 1: further behind the best at {large}) runs {'; '.join(parts)}.")


def prose(c, small, large, top):
    a = c.answers
    n = len(a)
    same_s, same_f = int(a["same_samplers"].sum()), int(a["same_filters"].sum())
    both = int((a["same_samplers"] & a["same_filters"]).sum())
    overlap = int(a["overlap"].sum())
    rho = c.ranks["rho"].to_numpy(dtype=float)
    by_scene = c.ranks.groupby("scene")["rho"].median().sort_values()
    text = [f"<b>The answer.</b> Over the {plural(len(c.scenes), 'shared scene')}, {plural(len(c.levels), 'spp level')}"
            f" and {plural(len(c.targets), 'target')} ({plural(n, 'answer')}): the leading samplers are the same at "
            f"both sizes in {same_s} of {n} (they share at least one in {overlap}), the filter and radius in {same_f}, "
            f"both in {both} (first table).",
            f"<b>The order.</b> The methods' order (Spearman's &rho; of their ratios to the best, per scene, target and spp over "
            f"{int(np.median(c.ranks['n']))} shared methods in the median) agrees with median &rho; = "
            f"{np.nanmedian(rho):.2f} (range {np.nanmin(rho):.2f} to {np.nanmax(rho):.2f}); most in "
            f"{html.escape(by_scene.index[-1])} (median {by_scene.iloc[-1]:.2f}), least in "
            f"{html.escape(by_scene.index[0])} ({by_scene.iloc[0]:.2f})."]
    sh = c.shares.assign(d=lambda d: (d["noise_share_large"] - d["noise_share_small"]).abs())
    if len(sh) and np.isfinite(sh["d"]).any():
        w = sh.loc[sh["d"].idxmax()]
        text.append(f"<b>Where the error comes from.</b> Its make-up moves most in {html.escape(w['scene'])} at {w['spp']} spp: noise is "
                    f"{pct(w['noise_share_small'])} of the error (median over the shared methods) at {small}, "
                    f"{pct(w['noise_share_large'])} at {large} (the rest: blur, aliasing and the cross term). Aliasing against each "
                    f"filter's own reference is told from zero (above 2 se) in {pct(np.nanmean(c.shares['aliased_small']))} "
                    f"of the randomised rows at {small} and {pct(np.nanmean(c.shares['aliased_large']))} at {large} "
                    "(mean over scenes and spp).")
    g = c.grid[c.grid["spp"] == top]
    if len(g):
        worse = int((g["ratio_large"] > g["ratio_small"]).sum())
        text.append(f"<b>The fixed grid</b> (deterministic) at its best filter, {top} spp: further behind the best at "
                    f"{large} in {worse} of {plural(len(g), 'scene')} (per scene in the second table).")
    text.append(mover_text(c.moves, small, large))
    return "<ul class='sizes'>" + "".join(f"<li>{t}</li>" for t in text if t) + "</ul>"


def where(quick_path, results):
    """The quick study's CSV as the page names it, linked to its own page when it has one beside it."""
    rel = os.path.relpath(quick_path)
    shown = f"<code>{html.escape(os.path.abspath(quick_path) if rel.startswith('..') else rel)}</code>"
    page = os.path.join(os.path.dirname(os.path.abspath(quick_path)), "index.html")
    if results and os.path.isfile(page):
        href = os.path.relpath(page, os.path.abspath(results)).replace(os.sep, "/")
        return f"<a href='{html.escape(href)}'>{shown}</a>"
    return shown


def section(page_df, quick_path, margin, results=None):
    """HTML of the section comparing the page's study (page_df) with the quick study at quick_path; results: the
    page's folder (the quick study's page is linked from it)."""
    head = "<h2 id='sizes'>The quick study against the presented one</h2>"
    small_df, _ = study_csv.load_study(quick_path)
    large_df = page_df
    ns, nl = facts(small_df)["size"], facts(large_df)["size"]
    if ns >= nl:
        return ""
    c = sizes.compare(small_df, large_df, margin)
    small, large = f"{ns} px", f"{nl} px"
    if c.answers.empty or not c.scenes:
        return head + ("<p>The two studies share no scene, spp level and target: nothing to compare. "
                       f"{html.escape(missing_text(c, small, large))} A pixel at {small} covers {(nl / ns) ** 2:.3g} times the "
             f"scene area of one at {large}: the same content lies {nl / ns:.3g} times higher in frequency per "
             "pixel.</p>")
    top = max(c.levels)
    intro = (f"<p>The quick study ({where(quick_path, results)}, {size_of(small_df)}) and this one ({size_of(large_df)}) "
             "rank the same methods on the same scenes; here only what both hold: scenes "
             f"{html.escape(', '.join(c.scenes))}; spp {', '.join(map(str, c.levels))}; targets "
             f"{html.escape(', '.join(c.targets))}; samplers {html.escape(', '.join(c.samplers))}. Each study's "
             f"shared rows are ranked as in answer.csv (margin {100 * margin:g} %): a ratio is to the best shared "
             "method of the scene, which may differ from the best of the whole study. "
             f"{html.escape(missing_text(c, small, large))} A pixel at {small} covers {(nl / ns) ** 2:.3g} times the "
             f"scene area of one at {large}: the same content lies {nl / ns:.3g} times higher in frequency per "
             "pixel.</p>")
    note = ("<p class='note'>Leading: the samplers equivalent to the best in at least half of the shared scenes "
            "(else those equivalent in the most scenes), each at its best filter and radius, as in the answer "
            "table; a family is named with its count. &rho;: Spearman's rank correlation of the shared methods' "
            "ratios to the best between the two sizes (1: same order). Noise share: the median over the shared "
            "methods of noise / error against the first target. The fixed grid's ratio: its lowest among rows "
            "told from zero.</p>")
    return (head + intro + prose(c, small, large, top) + answer_rows(c, small, large)
            + scene_rows(c, small, large, top) + note)


def sizes_section(c):
    """The page section (page.py SECTIONS): '' unless a smaller quick study is found (module doc)."""
    path = quick_csv(c.results, c.study, getattr(c, "quick", None))
    if path is None:
        return ""
    return section(c.df, path, c.s.margin, c.results)
