"""The filter and radius under each target (each filter at its best radius with the leading samplers:
stats/factors.filter_picks) and what holds under every target (the samplers leading under all of them, and
the filter each target asks for)."""
from ..stats import factors
from .answer import config
from .study import Finding, fmt

SHOWN = 3  # filters named per spp level


def filter_phrase(s, target, spp):
    status, lead = s.leaders[(target, spp)]
    picks = factors.filter_picks(s.summary, target, spp, set(lead["sampler"]))
    if picks.empty:
        return None, []
    half = factors.half(len(s.scenes))
    good = picks[(picks["verdict"] == factors.EQUIVALENT) | (picks["equivalent"] >= half)]
    shown = good if len(good) else picks.head(1)
    names = [f"**{config(r)}** ({r['sampler']}, equivalent in {int(r['equivalent'])} of {len(s.scenes)}, median "
             f"{fmt(r['median_ratio'])}x)" for _, r in shown.iterrows()]
    rest = picks[~picks.index.isin(shown.index)].head(SHOWN)
    text = f"at {spp} spp " + ", ".join(names)
    if len(rest):
        text += "; next " + ", ".join(f"{config(r)} {fmt(r['median_ratio'])}x" for _, r in rest.iterrows())
    claims = [dict(kind="filters", target=target, spp=spp, value=sorted(config(r) for _, r in shown.iterrows()))]
    claims += [dict(kind="filter_median_ratio", target=target, spp=spp, filter=r["filter_name"],
                    samplers=sorted(lead["sampler"]), value=float(r["median_ratio"]))
               for _, r in list(shown.iterrows()) + list(rest.iterrows())]
    return text, claims


def filters(s, target):
    parts, claims = [], []
    for spp in s.levels:
        if (target, spp) not in s.leaders:
            continue
        t, c = filter_phrase(s, target, spp)
        if t:
            parts.append(t)
            claims += c
    if not parts:
        return None
    text = (f"Filter and radius against `{target}` with the leading samplers (each filter at its best radius; "
            "those equivalent to each scene's best in at least half of the scenes, else the closest): "
            + "; ".join(parts) + ".")
    return Finding(f"filters:{target}", f"Filter and radius against {target}", text, claims)


def all_targets(s):
    if len(s.targets) < 2:
        return Finding("targets", "One target", f"This study has one target, `{s.primary}`: its answer is the "
                       "answer for that target only (the pixel-area target itself aliases, see docs/science.md).")
    present = sorted(s.df["sampler"].unique())
    parts, claims = [], []
    for spp in s.levels:
        sets = [set(s.leaders[(t, spp)][1]["sampler"]) if (t, spp) in s.leaders else set() for t in s.targets]
        common = sorted(set.intersection(*sets))
        claims.append(dict(kind="common_samplers", spp=spp, value=common))
        cfg = {t: sorted({config(r) for _, r in s.leaders[(t, spp)][1].iterrows()}) for t in s.targets
               if (t, spp) in s.leaders}
        for t, v in cfg.items():
            claims.append(dict(kind="leader_configs", target=t, spp=spp, value=v))
        where = ", ".join(f"{'/'.join(v)} for `{t}`" for t, v in cfg.items())
        if common:
            names = [(f"the {n} family ({', '.join(m)})" if m else n) for n, m in factors.family_names(common, present)]
            parts.append(f"at {spp} spp {', '.join(names)} lead under all of them (at {where})")
        else:
            parts.append(f"at {spp} spp no sampler leads under all of them (the filters: {where})")
    text = ("What holds under every target (" + ", ".join(f"`{t}`" for t in s.targets) + "): "
            + "; ".join(parts) + ". The filter follows the target; a conclusion outside this list is a statement "
            "about one target.")
    return Finding("targets", "What holds under every target", text, claims)


def findings(s):
    return [f for f in [filters(s, t) for t in s.targets] + [all_targets(s)] if f is not None]
