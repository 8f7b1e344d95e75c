"""The answer at a glance, at the top of the page (docs/science.md "Answers a practitioner can act on"): a table
with a row per spp level and a column per target; each cell names the leading samplers (stats/factors.leaders,
families named), the filter and radius they use, and jittered's and random's error against each scene's best.
Rendered from answer.csv as written (report/answer_csv.py), not from the objects that made it."""
import html

from ..stats import factors
from . import answer_csv

CONTROLS = ("jittered", "random")


def config(r):
    return f"{r['filter_name']} r={r['radius']:g}"


def sampler_cell(rows, present, n_scenes):
    """The leading samplers: a family as its name (members in the tooltip), each with its scenes."""
    by = {r["sampler"]: r for _, r in rows.iterrows()}
    out = []
    for name, members in factors.family_names(list(by), present):
        if members:
            eqs = [int(by[m]["equivalent"]) for m in members]
            k = f"{min(eqs)}" if min(eqs) == max(eqs) else f"{min(eqs)}-{max(eqs)}"
            across = all(by[m]["verdict"] == factors.EQUIVALENT for m in members)
            label = f"<span title='{html.escape(', '.join(members))}'>{html.escape(name)} ({len(members)})</span>"
            out.append((f"<b>{label}</b>" if across else label) + f" <small>{k}/{n_scenes}</small>")
        else:
            r = by[name]
            label = html.escape(name) + (" <small>(fixed grid)</small>" if r["deterministic"] else "")
            out.append((f"<b>{label}</b>" if r["verdict"] == factors.EQUIVALENT else label)
                       + f" <small>{int(r['equivalent'])}/{n_scenes}</small>")
    return ", ".join(out)


def cell(picks, lead, target, spp, present, n_scenes):
    if (target, spp) not in lead:
        return "&ndash;"
    status, rows = lead[(target, spp)]
    head = {factors.NONE: "<i>no sampler within the margin in any scene; closest:</i> ",
            factors.MOST: "<i>no sampler within the margin in half of the scenes; most often:</i> "}.get(status, "")
    cfgs = ", ".join(sorted({config(r) for _, r in rows.iterrows()}))
    ctl = []
    for c in CONTROLS:
        p = picks[(picks["target"] == target) & (picks["spp"] == spp) & (picks["sampler"] == c)]
        if len(p) and c not in set(rows["sampler"]):
            ctl.append(f"{c} {p.iloc[0]['median_ratio']:.3g}x")
    if ctl:
        ctl[0] = "vs best: " + ctl[0]
    return (f"<div class='samplers'>{head}{sampler_cell(rows, present, n_scenes)}</div>"
            f"<div class='cfg'>with {html.escape(cfgs)}</div>"
            + (f"<div class='ctl'><small>{' &middot; '.join(ctl)}</small></div>" if ctl else ""))


def answer_table(path, targets, levels, present, n_scenes, margin, science):
    """HTML: the answer table read from answer.csv at `path` (module doc)."""
    summary = answer_csv.summary(answer_csv.read(path))
    picks = factors.sampler_picks(summary)
    lead = factors.leaders(picks, n_scenes)
    head = "".join(f"<th><code>{html.escape(t)}</code></th>" for t in targets)
    rows = "".join(f"<tr><th>{spp} spp</th>" + "".join(f"<td>{cell(picks, lead, t, spp, present, n_scenes)}</td>"
                                                      for t in targets) + "</tr>" for spp in levels)
    return (f"<table class='answer-table'><tr><th></th>{head}</tr>{rows}</table>"
            f"<p class='note'>Each cell: the samplers within <b>{100 * margin:g} %</b> of each scene's best error (the "
            f"margin of equivalence, <code>report --margin</code>) in at least half of the {n_scenes} scenes, each at "
            "its best filter and radius (below them); <b>bold</b>: equivalent across scenes (the 95 % bootstrap "
            "interval of its median ratio lies below the margin, and it is equivalent in at least half of them); k/n: the scenes where it is equivalent; a family is "
            "named when all of its samplers lead (hover for them). Last line: jittered and random at their own best, "
            "their median error over each scene's best. The rows compared in a scene share its references: their "
            f"part of the error is counted for both rows of a ratio (conservative). Rules: <a href='{science}"
            "#answers-a-practitioner-can-act-on'>docs/science.md</a>; the numbers: "
            f"<a href='{html.escape(answer_csv.NAME)}'>{html.escape(answer_csv.NAME)}</a>.</p>")
