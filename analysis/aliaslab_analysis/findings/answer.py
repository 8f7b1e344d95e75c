"""The answer under each target: per spp level, the methods in the top group of at least half of the
scenes (stats/rankings.answer), each with its count of scenes, its median ratio to each scene's best and
the bootstrap interval of that median; then what holds under every target."""
from ..stats import bootstrap
from .study import Finding, fmt, method_key, method_name, plural

SHOWN = 4  # methods named per spp level (the rest counted)


def target_words(target):
    return {"box:0.5": "the pixel-area image", "gaussian:1.5": "a Gaussian",
            "lanczos:3": "a band-limited (Lanczos) image"}.get(target, "")


def method_phrase(r, majority_scenes):
    lo, hi = r["ci_low"], r["ci_high"]
    extra = []
    if r["flagged"]:
        extra.append(f"flagged in {int(r['flagged'])}")
    if r["undetermined"]:
        extra.append(f"undetermined in {int(r['undetermined'])}")
    return (f"**{method_name(r)}** ({int(r['in_top'])} of {plural(int(r['scenes']), 'scene')}, median {fmt(r['median_ratio'])}x "
            f"[{fmt(lo)}-{fmt(hi)}]" + ("; " + ", ".join(extra) if extra else "") + ")")


def per_target(s, target):
    parts, claims = [], []
    for spp in s.levels:
        pick = s.answer.get((target, spp))
        if pick is None or pick.empty:
            parts.append(f"at {spp} spp no method can be ranked")
            continue
        shown = pick.head(SHOWN)
        names = [method_phrase(r, s.majority) for _, r in shown.iterrows()]
        more = len(pick) - len(shown)
        rule = "majority" if int(pick["in_top"].iloc[0]) >= s.majority else "most scenes"
        parts.append(f"at {spp} spp " + ", ".join(names) + (f" and {more} more" if more else "")
                     + ("" if rule == "majority" else " (no method is in the top group of half the scenes: "
                        "those in it most often)"))
        claims.append(dict(kind="answer_size", target=target, spp=spp, value=len(pick)))
        for _, r in shown.iterrows():
            base = dict(target=target, spp=spp, method=method_key(r))
            for kind in ("in_top", "scenes", "median_ratio", "ci_low", "ci_high", "flagged", "undetermined"):
                claims.append(dict(base, kind=kind, value=float(r[kind])))
    words = target_words(target)
    text = (f"Against `{target}`" + (f" ({words})" if words else "") + ", the methods in the top group "
            f"(not significantly worse than each scene's best) in at least {s.majority} of {len(s.scenes)} scenes: "
            + "; ".join(parts) + ". In brackets: scenes in the top group, the median over scenes of the error "
            f"relative to each scene's best, and its {int(bootstrap.LEVEL * 100)} % bootstrap interval.")
    return Finding(f"answer:{target}", f"The answer against {target}", text, claims)


def all_targets(s):
    if len(s.targets) < 2:
        return Finding("targets", "One target", f"This study has one target, `{s.primary}`: its answer is the "
                       "answer for that target only (the pixel-area target itself aliases, see docs/science.md).")
    parts, claims = [], []
    for spp in s.levels:
        sets = [set(method_key(r) for _, r in s.answer.get((t, spp), s.summary.iloc[0:0]).iterrows())
                for t in s.targets]
        common = set.intersection(*sets) if sets else set()
        samplers = set.intersection(*[set(k[0] for k in x) for x in sets]) if sets else set()
        names = sorted(method_name(dict(zip(["sampler", "filter_name", "radius", "filter_params",
                                             "reconstruction", "prefilter"], k))) for k in common)
        claims.append(dict(kind="common_methods", spp=spp, value=sorted(common)))
        claims.append(dict(kind="common_samplers", spp=spp, value=sorted(samplers)))
        if names:
            parts.append(f"at {spp} spp " + ", ".join(f"**{n}**" for n in names))
        elif samplers:
            parts.append(f"at {spp} spp no one method, but the sampler(s) {', '.join(sorted(samplers))}")
        else:
            parts.append(f"at {spp} spp nothing: the answer depends on the target")
    text = ("What holds under every target (" + ", ".join(f"`{t}`" for t in s.targets) + "): in the answer under "
            "all of them " + "; ".join(parts) + ". A conclusion outside this list is a statement about one target.")
    return Finding("targets", "What holds under every target", text, claims)


def findings(s):
    return [per_target(s, t) for t in s.targets] + [all_targets(s)]
