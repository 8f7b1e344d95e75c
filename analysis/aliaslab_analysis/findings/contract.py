"""The theory contract every study checks (docs/science.md, "What the samplers guarantee"; the sweep computes the
same at its end, lib/study/records/contract.h, and prints violations as warnings).

With the box filter of radius 0.5 a pixel's estimate is the plain mean of its own N samples, so a sampler whose
construction guarantees Var <= c sigma^2 / N for every square-integrable integrand has at most c times random's
`noise` in the same study: jittered c = 1, nrooks (Latin hypercube) c = N / (N - 1), Owen-scrambled sobol at
N = 2^m (a scrambled (0,m,2)-net) c = 2. Per scene and spp where the study has random and the sampler (box
r = 0.5, weighted reconstruction, no pre-filtering):

    ratio = noise(sampler) / noise(random)
    se    = ratio * sqrt((noise_se(sampler) / noise(sampler))^2 + (noise_se(random) / noise(random))^2)

(the delta method; the two noises come from independent sample sets), and a ratio above its bound by more than
3 se is a violation: a finding printed at the top of the page. Samplers with no theorem are listed with their
measured ratio and "no bound".

checks(df)   every check of a study (a list of dicts: scene, sampler, spp, ratio, se, bound, z, violated)
finding(df)  the Finding (key "contract"): its text and claims (every number it states); None without random
Run as `python3 -m analysis.aliaslab_analysis.findings.contract STUDY.csv` it prints the checks and exits 1 when a
bound is violated (2 on bad input).
"""
import math
import sys

import numpy as np

from .study import Finding, fmt

Z = 3.0  # a violation: ratio above the bound by more than Z standard errors


def bound(sampler, spp):
    """The constant c of Var <= c sigma^2 / N the sampler's construction guarantees at spp, or None (no theorem).
    The same table as Sampler::varianceBound (lib/sampling)."""
    n = int(spp)
    if sampler in ("random", "jittered"):
        return 1.0
    if sampler == "nrooks":
        return n / (n - 1) if n > 1 else 1.0
    if sampler == "sobol":
        return 2.0 if n > 0 and n & (n - 1) == 0 else None
    return None


def contract_rows(df):
    """One row per (scene, sampler, spp) at box r = 0.5, weighted, no pre-filtering (noise is the same on every
    target row of a configuration)."""
    f = df["filter_name"] if "filter_name" in df.columns else df["filter"]
    keep = ((f.astype(str) == "box") & np.isclose(df["radius"].to_numpy(dtype=float), 0.5)
            & (df["reconstruction"].astype(str) == "weighted") & (df["prefilter"].astype(str) == "none"))
    rows = df[keep]
    return rows.drop_duplicates(subset=["scene", "sampler", "spp"], keep="first")


def checks(df):
    if not {"noise", "noise_se"} <= set(df.columns):  # an older CSV without the noise's se: nothing to judge
        return []
    rows = contract_rows(df)
    out = []
    for (scene, spp), cell in rows.groupby(["scene", "spp"], sort=True):
        rnd = cell[cell["sampler"] == "random"]
        if rnd.empty or not float(rnd["noise"].iloc[0]) > 0:
            continue
        b, sb = float(rnd["noise"].iloc[0]), float(rnd["noise_se"].iloc[0])
        for r in cell[cell["sampler"] != "random"].sort_values("sampler").itertuples():
            a, sa = float(r.noise), float(r.noise_se)
            ratio = a / b
            ra = sa / a if a > 0 else 0.0
            se = ratio * math.sqrt(ra * ra + (sb / b) ** 2)
            c = bound(r.sampler, spp)
            z = (ratio - c) / se if c is not None and se > 0 and math.isfinite(se) else float("nan")
            out.append(dict(scene=str(scene), sampler=str(r.sampler), spp=int(spp), ratio=ratio, se=se, bound=c,
                            z=z, violated=bool(math.isfinite(z) and z > Z)))
    return out


def bound_text(sampler, spp):
    c = bound(sampler, spp)
    return "no bound" if c is None else f"bound {fmt(c, 4)}"


def finding(df):
    cs = checks(df)
    if not cs:
        return None
    bad = [c for c in cs if c["violated"]]
    bounded = [c for c in cs if c["bound"] is not None]
    claims = [dict(kind="contract_checks", value=len(bounded)), dict(kind="contract_violations", value=len(bad))]
    if bad:
        text = (f"**The samplers' bounds are violated in {len(bad)} of {len(bounded)} checks**: a sampler that "
                "misbehaves in this render (a weak scramble, seeds shared across pixels, a broken stratification), "
                "whatever its unit tests say. ")
        parts = []
        for c in bad:
            parts.append(f"`{c['sampler']}` on {c['scene']} at {c['spp']} spp: noise {fmt(c['ratio'])} "
                         f"± {fmt(c['se'], 2)} times random's, {bound_text(c['sampler'], c['spp'])} "
                         f"(z = {c['z']:.1f})")
            claims.append(dict(kind="violation", scene=c["scene"], sampler=c["sampler"], spp=c["spp"],
                               value=c["ratio"], se=c["se"], bound=c["bound"]))
        text += "; ".join(parts) + "."
    else:
        worst = max(bounded, key=lambda c: c["ratio"] / c["bound"]) if bounded else None
        text = (f"The samplers' variance bounds hold in all {len(bounded)} checks (noise against random's at box "
                f"r = 0.5: jittered at most 1, nrooks N/(N-1), sobol 2 at powers of two; none above its bound by "
                f"more than {Z:g} standard errors).")
        if worst:
            text += (f" Closest to its bound: `{worst['sampler']}` on {worst['scene']} at {worst['spp']} spp, "
                     f"{fmt(worst['ratio'])} ± {fmt(worst['se'], 2)} ({bound_text(worst['sampler'], worst['spp'])}).")
            claims.append(dict(kind="closest", scene=worst["scene"], sampler=worst["sampler"], spp=worst["spp"],
                               value=worst["ratio"], bound=worst["bound"]))
    return Finding("contract", "The samplers' bounds", text, claims)


def table(df):
    """Per sampler and spp: the range of its ratio over scenes, and its bound (for the page and the printout)."""
    out = []
    cs = checks(df)
    for sampler in sorted({c["sampler"] for c in cs}):
        for spp in sorted({c["spp"] for c in cs if c["sampler"] == sampler}):
            sel = [c for c in cs if c["sampler"] == sampler and c["spp"] == spp]
            hi = max(sel, key=lambda c: c["ratio"])
            out.append(dict(sampler=sampler, spp=spp, scenes=len(sel), low=min(c["ratio"] for c in sel),
                            high=hi["ratio"], high_se=hi["se"], high_scene=hi["scene"], bound=bound(sampler, spp),
                            violated=sum(c["violated"] for c in sel)))
    return out


def main(argv=None):
    from ..io.errors import InputError
    from ..io.study_csv import load_study
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        print("usage: python3 -m analysis.aliaslab_analysis.findings.contract STUDY.csv", file=sys.stderr)
        return 2
    try:
        df, _ = load_study(argv[0])
    except InputError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    cs = checks(df)
    for c in cs:
        state = "VIOLATED" if c["violated"] else ("no bound" if c["bound"] is None else "holds")
        b = "" if c["bound"] is None else f"{c['bound']:.6g}"
        print(f"{c['scene']},{c['sampler']},{c['spp']},{c['ratio']:.6g},{c['se']:.3g},{b},{state}")
    f = finding(df)
    print(f.text if f else "no checks: the study has no random rows at box r = 0.5")
    return 1 if any(c["violated"] for c in cs) else 0


if __name__ == "__main__":
    sys.exit(main())
