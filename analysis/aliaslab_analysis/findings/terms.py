"""Where the error comes from, what an own-mse ranking would pick, aliasing within error, and the rows that
cannot be ranked (flagged: unstable or reference-limited, stats/flags.py; heavy-tailed, stats/tails.py). Where the error
comes from is stated under every target; the rest against the primary target, counts over its rows (the target-independent
columns repeat once per target)."""
import numpy as np

from ..io.study_rows import components
from ..stats import flags, tails
from .study import Finding, fmt, method_name

WORDS = {"noise": "noise", "aliasing": "aliasing", "blur": "blur", "cross": "the cross term",
         "blur_cross": "blur with the cross term"}
PIXEL_AREA = "box:0.5"
KERNEL_SHARE = 0.5  # blur's share of the best's error above which the page says the target ranks kernels


def shares(s, target):
    """Where the error of each scene's best at the highest spp comes from, against `target`."""
    top_spp = s.levels[-1]
    r = s.ranked[(s.ranked["target"].astype(str) == target) & (s.ranked["spp"] == top_spp) & s.ranked["best"]]
    if r.empty:
        return None
    terms = [c for c, _ in components(s.df)]
    claims, parts = [], []
    blur = None
    for c in terms:
        with np.errstate(divide="ignore", invalid="ignore"):
            v = float(np.nanmedian(r[c].to_numpy(dtype=float) / r["error"].to_numpy(dtype=float)))
        claims.append(dict(kind="share", target=target, spp=top_spp, term=c, value=v))
        parts.append(f"{WORDS[c]} {100 * v:.0f} %")
        blur = v if c in ("blur", "blur_cross") else blur
    text = (f"Where the error of each scene's best method against `{target}` at {top_spp} spp comes from (median "
            f"share over {len(r)} scenes): " + ", ".join(parts) + ".")
    if target != PIXEL_AREA and blur is not None and blur >= KERNEL_SHARE:
        text += (" Most of it is blur, the distance between the filter's own reference and the target: against this "
                 "target a ranking at high spp mostly measures how close a kernel is to the target's kernel (see the "
                 "trade-off charts: noise plus aliasing against blur).")
    return Finding(f"shares:{target}", f"Where the error comes from ({target})", text, claims)


def own_mse(s):
    top_spp = s.levels[-1]
    r = s.ranked[(s.ranked["target"].astype(str) == s.primary) & (s.ranked["spp"] == top_spp)
                 & ~s.ranked["deterministic"].astype(bool)]
    picks = []
    for _, g in r.groupby("scene", sort=True):
        own = g[np.isfinite(g["mse"].to_numpy(dtype=float))]
        if len(own):
            picks.append(own.loc[own["mse"].idxmin()])
    if not picks:
        return None
    names = [method_name(p) for p in picks]
    name = max(sorted(set(names)), key=names.count)
    ratio = float(np.nanmedian([p["ratio"] for p in picks]))
    claims = [dict(kind="own_mse_ratio", target=s.primary, spp=top_spp, value=ratio),
              dict(kind="own_mse_scenes", target=s.primary, spp=top_spp, value=len(picks))]
    if ratio > 1 + 1e-12:
        text = (f"Ranked by each filter's own mse (against its own reference, blind to blur), {name} would win "
                f"most scenes at {top_spp} spp; against the target the own-mse pick's error is {fmt(ratio)}x each "
                f"scene's best (median over {len(picks)} scenes). Every ranking here uses the error against the target.")
    else:
        text = f"Here the own-mse ranking agrees with the error against the target at {top_spp} spp ({name})."
    return Finding("own_mse", "Own mse against the target", text, claims)


def aliasing_zero(s):
    if "aliasing_se" not in s.df.columns:
        return None
    rows = s.rows()
    zero, neg = int(rows["aliasing_zero"].sum()), int((rows["aliasing"] < 0).sum())
    text = (f"Aliasing is zero within error (|aliasing| <= 2 standard errors) in {zero} of {len(rows)} "
            f"configurations; {neg} have a negative aliasing estimate.")
    claims = [dict(kind="aliasing_zero", value=zero), dict(kind="configurations", value=len(rows)),
              dict(kind="aliasing_negative", value=neg)]
    return Finding("aliasing", "Aliasing within error", text, claims)


def unrankable(s):
    df = s.df
    kind = flags.kinds(df)
    n_flag = int((kind != "").sum())
    unstable = df[kind == flags.UNSTABLE]
    n_ref = int((kind == flags.REFERENCE_LIMITED).sum())
    claims = [dict(kind="flagged_rows", value=n_flag), dict(kind="rows", value=len(df)),
              dict(kind="unstable_rows", value=len(unstable)), dict(kind="reference_limited_rows", value=n_ref)]
    by = unstable.groupby(["filter_name", "radius"]).size().sort_values(ascending=False, kind="stable")
    for (name, radius), n in by.items():
        claims.append(dict(kind="unstable_filter", filter=name, radius=float(radius), value=int(n)))
    heavy = int(s.ranked["heavy_tailed"].sum())
    claims.append(dict(kind="heavy_tailed_rows", value=heavy))
    text = (f"{n_flag} of {len(df)} rows are flagged by the sweep: their error against the target is within two "
            f"standard errors of zero (docs/science.md). {len(unstable)} of them are unstable: their error is more "
            f"than {flags.REF_LIMIT:g}x what the target reference's own error explains, so certainly not small, "
            "but its spread over the seeds is as large as its mean (a few seeds carry most of it)"
            + (": " + ", ".join(f"{name} r={radius:g} {int(n)}" for (name, radius), n in by.items()) if len(by) else "")
            + f". {n_ref} are reference-limited (error within {flags.REF_LIMIT:g}x the reference's own). "
            "Flagged rows are drawn hollow on every chart. "
            f"Apart from the flag, {heavy} of {len(df)} rows are heavy-tailed (their largest seed carries more than "
            f"{tails.SHARE_FACTOR:g}x an equal share of their summed error): their interval is a bootstrap over seeds "
            "and they are never equivalent to the best.")
    return Finding("flagged", "Flagged rows: unstable or reference-limited", text, claims)


def findings(s):
    return [shares(s, t) for t in s.targets] + [own_mse(s), aliasing_zero(s), unrankable(s)]
