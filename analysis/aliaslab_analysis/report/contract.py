"""The samplers' bounds at the top of the page (findings/contract.py): a violation is the first thing a reader
sees, in a box of its own; when every bound holds, one line, with the table of ratios folded away."""
import html

from ..findings import contract
from .findings_text import html_paragraphs

STYLE = "background:#fde8e8;border-left:4px solid #c22;padding:.4em 1em;margin:1em 0"


def ratio_table(df):
    rows = []
    for t in contract.table(df):
        bound = "no bound" if t["bound"] is None else f"{t['bound']:.4g}"
        state = ("<b>violated</b> in " + str(t["violated"]) + " scene(s)") if t["violated"] else (
            "no theorem" if t["bound"] is None else "holds")
        rows.append(f"<tr><td>{html.escape(t['sampler'])}</td><td>{t['spp']}</td><td>{t['scenes']}</td>"
                    f"<td>{t['low']:.3g} to {t['high']:.3g} &plusmn; {t['high_se']:.2g} "
                    f"({html.escape(t['high_scene'])})</td><td>{bound}</td><td>{state}</td></tr>")
    return ("<table><tr><th>sampler</th><th>spp</th><th>scenes</th><th>noise / random's noise (highest &plusmn; se, "
            "where)</th><th>bound</th><th></th></tr>" + "".join(rows) + "</table>")


def contract_section(c):
    f = contract.finding(c.df)
    if f is None:
        return ""
    body = "".join(html_paragraphs([f]))
    details = (f"<details><summary>Every sampler's noise against random's (box r = 0.5), and its bound</summary>"
               f"{ratio_table(c.df)}<p class='note'>A bound is a theorem about the sampler's construction: with "
               "the box of radius 0.5 each pixel is the plain mean of its own samples, and jittered, Latin "
               "hypercube (nrooks) and an Owen-scrambled (0,m,2)-net (sobol at N = 2^m) have at most 1, N/(N-1) "
               "and 2 times the variance of N independent points, for every integrand. A ratio above its bound "
               f"by more than {contract.Z:g} standard errors means the implementation misbehaves in this render "
               f"(<a href='{c.science}'>docs/science.md</a>, \"What the samplers guarantee\").</p></details>")
    style = STYLE if any(x["violated"] for x in contract.checks(c.df)) else ""
    return f"<div id='contract' class='{'' if style else 'facts'}' style='{style}'>{body}{details}</div>"
