"""The target as a choice the reader sees (issue 29 item 3): a table of the answer per spp level under each
target, the last column what holds under all of them, and why the pixel-area target itself aliases."""
import html

from ..findings.study import method_name, method_key
from ..stats import rankings


def short(pick):
    names = [html.escape(method_name(r)) + f" <small>({int(r['in_top'])}/{int(r['scenes'])})</small>"
             for _, r in pick.head(4).iterrows()]
    return "<br>".join(names) + (f"<br><small>+{len(pick) - 4} more</small>" if len(pick) > 4 else "")


def targets_section(s, science):
    """HTML: the answer per spp under each target (s: findings.Study)."""
    head = "".join(f"<th><code>{html.escape(t)}</code></th>" for t in s.targets)
    rows = []
    for spp in s.levels:
        picks = [s.answer.get((t, spp)) for t in s.targets]
        cells = [short(p) if p is not None and len(p) else "&ndash;" for p in picks]
        keys = [set(method_key(r) for _, r in p.iterrows()) if p is not None else set() for p in picks]
        common = set.intersection(*keys) if keys else set()
        both = "<br>".join(sorted(html.escape(method_name(dict(zip(rankings.METHOD, k)))) for k in common)) or "none"
        rows.append(f"<tr><td>{spp}</td>" + "".join(f"<td>{c}</td>" for c in cells)
                    + (f"<td>{both}</td>" if len(s.targets) > 1 else "") + "</tr>")
    all_head = "<th>under every target</th>" if len(s.targets) > 1 else ""
    table = f"<table><tr><th>spp</th>{head}{all_head}</tr>{''.join(rows)}</table>"
    text = ("<p>The error of a method is measured against a target image, and the target is a choice: the "
            "pixel-area image (<code>box:0.5</code>) favours the box filter at r = 0.5 by construction, and "
            "itself aliases (its box response lets frequencies above Nyquist through: replica rings on the zone "
            "plate, moir&eacute; at the Siemens star centre; "
            f"<a href='{science}'>docs/science.md</a>). A Gaussian and a band-limited target weigh blur and "
            "aliasing differently. The table gives the answer under each target this study carries: the methods in "
            "the top group of at least half of the scenes (when none is, those in it most often); in brackets, in "
            "how many of the scenes where they were measured. The last column: what holds under all.</p>")
    if len(s.targets) < 2:
        text += ("<p class='note'>This study carries one target only: its answer holds for that target. "
                 "Studies run with several targets show each here.</p>")
    return "<h3 id='targets'>The answer under each target</h3>" + text + table
