"""The page's trade-off section: per target, noise plus aliasing against blur for every
filter over its radii (charts/tradeoff.py), at each spp level with the leading sampler there, and where the
error of each scene's best comes from under that target (findings/terms.shares)."""
import html

from ..charts import tradeoff as chart
from ..findings import terms
from .markdown import inline
from .elements import figure


def tradeoff_section(c):
    s = c.s
    natural = chart.natural_radius(s.df)
    known = ", ".join(f"{f} {r:g}" for f, r in sorted(natural.items()))
    body = ["<h2 id='tradeoff'>Targets as a trade-off</h2>",
            "<p>Against a target other than the pixel area most of the error at high spp is blur, the distance between "
            "the filter's own reference and the target, so a ranking there mostly measures how close a kernel is to "
            "the target's kernel. The charts show the trade-off itself: for every filter over its radii, noise plus "
            "aliasing (its error against its own reference, <code>mse</code>) against its blur (its own reference "
            "against the target, <code>blur</code>), each divided by the scene's best error and the median over "
            f"scenes taken; the natural radius of each filter is ringed ({html.escape(known)}"
            + ("" if "natural_radius" in s.df.columns else "; from the filter registry, the CSV has no "
               "<code>natural_radius</code> column") + "). Down and to the left is better; the faint diagonals are "
            "totals of 1, 2, 4, ... times the best.</p>"]
    for t in s.targets:
        panels = [(spp, s.leaders[(t, spp)][1].iloc[0]["sampler"]) for spp in s.levels if (t, spp) in s.leaders]
        png = chart.tradeoff(s.ranked, t, panels, natural, c.charts_dir)
        share = terms.shares(s, t)
        slug = "".join(ch if ch.isalnum() else "-" for ch in t)
        body.append(f"<h3 id='tradeoff-{slug}'>Against <code>{html.escape(t)}</code></h3>")
        if share is not None:
            body.append(f"<p>{inline(share.text)}</p>")
        if png:
            body.append(figure(c.results, png, f"Against <code>{html.escape(t)}</code>: noise + aliasing against "
                               "blur per filter over its radii, one panel per spp (the leading sampler there); "
                               "ringed: the natural radius.", c.embed, anchor=f"tradeoff-chart-{slug}",
                               toc=f"trade-off {t}"))
    return "\n".join(body)
