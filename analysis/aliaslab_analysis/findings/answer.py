"""The answer by factor, in words generated from the study (docs/science.md "Answers a practitioner can act
on"): under each target and at each spp, the samplers equivalent to each scene's best (each at its best filter
and radius: stats/factors.sampler_picks; a family named when all of it is there), the filter and radius they
use, and jittered and random against the best; then what changes from the lowest to the highest spp.
What holds under every target is in factors.py (beside the filter finding)."""
from .study import Finding, fmt, plural
from ..stats import factors

CONTROLS = ("jittered", "random")  # the samplers every effect size is also stated against


def target_words(target):
    return {"box:0.5": "the pixel-area image", "gaussian:1.5": "a Gaussian (sigma 0.5)",
            "lanczos:3": "a band-limited (Lanczos) image"}.get(target, "")


def config(r):
    return f"{r['filter_name']} r={r['radius']:g}"


def record(r, n):
    """'equivalent in k of n, median R x [lo-hi]' of an across-scene record."""
    return (f"equivalent in {int(r['equivalent'])} of {n}, median {fmt(r['median_ratio'])}x "
            f"[{fmt(r['ci_low'])}-{fmt(r['ci_high'])}]" + (", heavy-tailed" if r["heavy"] else ""))


def sampler_list(s, rows):
    """The leading samplers in words, grouped by their configuration, families named
    (factors.family_names)."""
    present = sorted(s.df["sampler"].unique())
    parts = []
    for cfg, g in rows.groupby(rows.apply(config, axis=1), sort=False):
        by = {r["sampler"]: r for _, r in g.iterrows()}
        names = []
        for name, members in factors.family_names(list(by), present):
            if members:
                meds = [by[m]["median_ratio"] for m in members]
                eqs = [int(by[m]["equivalent"]) for m in members]
                k = f"{min(eqs)}" if min(eqs) == max(eqs) else f"{min(eqs)}-{max(eqs)}"
                names.append(f"the **{name}** family ({', '.join(members)}; {k}, "
                             f"{fmt(min(meds))}-{fmt(max(meds))}x)")
            else:
                r = by[name]
                grid = "the fixed grid; " if r["deterministic"] else ""
                names.append(f"**{name}** ({grid}{int(r['equivalent'])}, {fmt(r['median_ratio'])}x)")
        parts.append(", ".join(names) + f" at {cfg}")
    return parts


HEAD = {factors.EQUIVALENT: "within the margin of each scene's best in at least half of the {n} scenes",
        factors.HALF: "within the margin of each scene's best in at least half of the {n} scenes",
        factors.MOST: "no sampler is within the margin in half of the {n} scenes; in the most ({k})",
        factors.NONE: "no sampler is within the margin in any scene; the closest"}


def spp_phrase(s, target, spp):
    status, rows = s.leaders[(target, spp)]
    k = int(rows["equivalent"].max())
    text = f"At {spp} spp, {HEAD[status].format(n=len(s.scenes), k=k)}: " + "; ".join(sampler_list(s, rows)) + "."
    across = rows[rows["verdict"] == factors.EQUIVALENT]
    if len(across):
        text += " Equivalent across scenes: " + ", ".join(
            f"{r['sampler']} (median {fmt(r['median_ratio'])}x [{fmt(r['ci_low'])}-{fmt(r['ci_high'])}])"
            for _, r in across.iterrows()) + "."
    claims = [dict(kind="leaders", target=target, spp=spp, value=sorted(rows["sampler"]))]
    for _, r in rows.iterrows():
        base = dict(target=target, spp=spp, sampler=r["sampler"])
        claims.append(dict(base, kind="pick", value=config(r)))
        for c in ("median_ratio", "ci_low", "ci_high", "equivalent"):
            claims.append(dict(base, kind=f"pick_{c}", value=float(r[c])))
    controls = []
    for c in CONTROLS:
        p = s.pick(target, spp, c)
        if p is not None and c not in set(rows["sampler"]):
            controls.append(f"{c} {fmt(p['median_ratio'])}x (at {config(p)})")
            claims.append(dict(kind="pick_median_ratio", target=target, spp=spp, sampler=c, value=float(p["median_ratio"])))
    if controls:
        text += " At their own best: " + ", ".join(controls) + "."
    return text, claims


def per_target(s, target):
    parts, claims = [], []
    for spp in s.levels:
        if (target, spp) not in s.leaders:
            parts.append(f"At {spp} spp no sampler can be ranked.")
            continue
        t, c = spp_phrase(s, target, spp)
        parts.append(t)
        claims += c
    words = target_words(target)
    text = (f"Against `{target}`" + (f" ({words})" if words else "") + f", margin {100 * s.margin:g} %, each "
            "sampler at its best filter and radius (its lowest median ratio to each scene's best); in brackets the "
            "scenes where it is equivalent to the best and its median ratio. " + " ".join(parts))
    return Finding(f"answer:{target}", f"The answer against {target}", text, claims)


def changes(s, target):
    """What changes from the lowest to the highest spp under `target`."""
    lo, hi = s.levels[0], s.levels[-1]
    if lo == hi or (target, lo) not in s.leaders or (target, hi) not in s.leaders:
        return None
    a, b = s.leaders[(target, lo)][1], s.leaders[(target, hi)][1]
    sa, sb = set(a["sampler"]), set(b["sampler"])
    fa, fb = sorted({config(r) for _, r in a.iterrows()}), sorted({config(r) for _, r in b.iterrows()})
    parts = [f"the leading samplers go from {', '.join(sorted(sa))} to {', '.join(sorted(sb))}"
             if sa != sb else f"the leading samplers stay {', '.join(sorted(sa))}",
             f"their filter from {', '.join(fa)} to {', '.join(fb)}" if fa != fb else f"their filter stays {', '.join(fa)}"]
    claims = [dict(kind="leaders", target=target, spp=lo, value=sorted(sa)),
              dict(kind="leaders", target=target, spp=hi, value=sorted(sb))]
    for c in CONTROLS:
        p, q = s.pick(target, lo, c), s.pick(target, hi, c)
        if p is not None and q is not None:
            parts.append(f"{c} goes from {fmt(p['median_ratio'])}x to {fmt(q['median_ratio'])}x the best")
            claims += [dict(kind="pick_median_ratio", target=target, spp=x, sampler=c, value=float(r["median_ratio"]))
                       for x, r in ((lo, p), (hi, q))]
    text = f"From {lo} to {hi} spp against `{target}`: " + "; ".join(parts) + "."
    return Finding(f"changes:{target}", f"From {lo} to {hi} spp ({target})", text, claims)


def findings(s):
    out = []
    for t in s.targets:
        out.append(per_target(s, t))
        out.append(changes(s, t))
    return [f for f in out if f is not None]


__all__ = ["findings", "plural"]
