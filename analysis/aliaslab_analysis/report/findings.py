"""The answer, computed from the study: the numbers and the sentences of the findings.

Every ranking uses the error against the common target (`error`, see study_csv.load_study) over
unflagged rows with a finite error; `ratio` is a row's error over the best error of its (scene, spp).
"""
import html

import numpy as np
import pandas as pd

from .. import fits
from ..charts import axes
from ..charts.decomposition import components


def method_name(r):
    return axes.method_label(r, show_recon=False)


METHOD_KEY = axes.METHOD  # the columns that name a method (a configuration less scene and spp)


def ranked(df):
    """Unflagged rows with a finite error, with `ratio` = error / the best error of its (scene, spp)."""
    ok = df[(df["flagged"] == 0) & np.isfinite(df["error"].to_numpy(dtype=float))].copy()
    for column, by in (("ratio", ["scene", "spp"]), ("ratio_scene", ["scene"])):
        best = ok.groupby(by)["error"].transform("min")
        with np.errstate(divide="ignore", invalid="ignore"):
            ok[column] = np.where(best > 0, ok["error"] / best, np.where(ok["error"] == 0, 1.0, np.inf))
    return ok


def best_per_spp(df):
    """Per spp level: the method with the lowest median (over scenes) ratio to each scene's best error.
    Returns a list of dicts (spp, method, median ratio, wins, scenes)."""
    ok = ranked(df)
    out = []
    for spp, g in ok.groupby("spp", sort=True):
        med = g.groupby(METHOD_KEY, dropna=False)["ratio"].median()
        if med.empty:
            continue
        key = med.idxmin()
        rows = g[(g[METHOD_KEY] == pd.Series(key, index=METHOD_KEY)).all(axis=1)]
        wins = int((rows["ratio"] <= 1.0).sum())
        out.append({"spp": int(spp), "method": method_name(rows.iloc[0]), "ratio": float(med.min()),
                    "wins": wins, "scenes": int(g["scene"].nunique()), "row": rows.iloc[0]})
    return out


def own_mse_pick(df):
    """At the highest spp level, per scene, the method an own-mse ranking would pick and its error
    relative to the scene's best error against the target. Returns (method, median ratio, scenes) or None."""
    ok = ranked(df)
    if ok.empty:
        return None
    top = ok[ok["spp"] == ok["spp"].max()]
    picks = []
    for _, g in top.groupby("scene"):
        own = g[np.isfinite(g["mse"].to_numpy(dtype=float))]
        if own.empty:
            continue
        picks.append(own.loc[own["mse"].idxmin()])
    if not picks:
        return None
    p = pd.DataFrame(picks)
    names = p.apply(method_name, axis=1)
    return names.value_counts().idxmax(), float(p["ratio"].median()), len(p), int(top["spp"].iloc[0])


def summary_table(df):
    """One point per (method, spp) present in every scene: mean time and the geometric mean over scenes
    of error / the scene's lowest error at any spp level."""
    ok = ranked(df)
    scenes = ok["scene"].nunique()
    with np.errstate(divide="ignore"):
        ok = ok.assign(logratio=np.log(ok["ratio_scene"].astype(float)))
    g = ok.groupby(METHOD_KEY + ["spp"], dropna=False).agg(time_ms=("time_ms", "mean"),
                                                          logratio=("logratio", "mean"),
                                                          scenes=("scene", "nunique")).reset_index()
    g = g[(g["scenes"] == scenes) & np.isfinite(g["logratio"]) & (g["time_ms"] > 0)].copy()
    g["ratio"] = np.exp(g["logratio"])
    return g


def findings(df, notes, target):
    """The answer in sentences (HTML paragraphs), computed from the study."""
    ok = ranked(df)
    scenes = df["scene"].nunique()
    out = []
    if ok.empty:
        return ["<p>No row has a finite error against the target and an unflagged reference: this study "
                "cannot answer the question. See the stability section.</p>"]
    best = best_per_spp(df)
    groups = []  # consecutive spp levels with the same best method
    for b in best:
        if groups and groups[-1][0]["method"] == b["method"]:
            groups[-1].append(b)
        else:
            groups.append([b])
    parts = []
    for g in groups:
        levels = ", ".join(str(b["spp"]) for b in g)
        ratios = ", ".join(f"{b['ratio']:.2f}x" for b in g)
        wins = ", ".join(f"{b['wins']}" for b in g)
        if all(b["ratio"] == 1.0 and b["wins"] == b["scenes"] for b in g):
            detail = f"the best in every scene ({g[0]['scenes']})"
        else:
            detail = (f"error relative to each scene's best: {ratios}, median over {g[0]['scenes']} scene(s); "
                      f"best outright in {wins} scene(s)")
        parts.append(f"at {levels} spp <b>{html.escape(g[0]['method'])}</b> ({detail})")
    out.append("<p>Lowest error against the target: " + "; ".join(parts) + ".</p>")
    table = summary_table(df)
    if len(table):
        front = table.iloc[fits.pareto_front(table["time_ms"], table["ratio"])]
        first, last = front.iloc[0], front.iloc[-1]
        if len(front) == 1:
            out.append(f"<p>For the time spent, one method is both the fastest and the most accurate: "
                       f"<b>{html.escape(method_name(first))} at {int(first['spp'])} spp</b> "
                       f"({first['time_ms']:.3g} ms).</p>")
        else:
            out.append(f"<p>For the time spent, the Pareto front (nothing both faster and more accurate) runs from "
                       f"<b>{html.escape(method_name(first))} at {int(first['spp'])} spp</b> ({first['time_ms']:.3g} "
                       f"ms, {first['ratio']:.3g}x the scene's lowest error) to <b>{html.escape(method_name(last))} at "
                       f"{int(last['spp'])} spp</b> ({last['time_ms']:.3g} ms, {last['ratio']:.3g}x); {len(front)} "
                       "methods on it in all (numbered on the chart below).</p>")
    pick = own_mse_pick(df)
    if pick:
        name, ratio, n, spp = pick
        if ratio > 1.0 + 1e-12:
            out.append(f"<p>Ranked by each filter's own mse (against its own reference, blind to blur), "
                       f"{html.escape(name)} would win at {spp} spp; against the common target its error is "
                       f"{ratio:.3g}x the best (median over {n} scene(s)). That is why every ranking here uses "
                       "the error against the target.</p>")
        else:
            out.append(f"<p>Here the own-mse ranking agrees with the error against the target at {spp} spp "
                       f"({html.escape(name)}).</p>")
    if best:
        top = ok[ok["spp"] == best[-1]["spp"]]
        winners = top.loc[top.groupby("scene")["error"].idxmin()]
        terms = [c for c, _ in components(df)]
        shares = {c: np.nanmedian(winners[c] / winners["error"].where(winners["error"] > 0)) for c in terms}
        words = {"noise": "noise", "aliasing": "aliasing", "blur": "blur", "cross": "the cross term",
                 "blur_cross": "blur with the cross term"}
        out.append(f"<p>Where the error of each scene's best method at {best[-1]['spp']} spp comes from (median "
                   "share): " + ", ".join(f"{words[c]} {100 * shares[c]:.0f}%" for c in terms) + ".</p>")
    if "aliasing_se" in df.columns:
        zero = int(df["aliasing_zero"].sum())
        neg = int((df["aliasing"] < 0).sum())
        out.append(f"<p>Aliasing is zero within error (|aliasing| &le; 2 standard errors) in {zero} of {len(df)} "
                   f"rows; {neg} row(s) have a negative aliasing estimate"
                   + (", every one of them zero within error" if neg and
                      df.loc[df["aliasing"] < 0, "aliasing_zero"].all() else "") + ".</p>")
    if (df["prefilter"] != "none").any():
        out.append(prefilter_finding(ok))
    flagged = int((df["flagged"] == 1).sum())
    out.append(f"<p>{scenes} scene(s), {len(df)} configurations, target <code>{html.escape(target)}</code>; "
               f"{flagged} row(s) flagged (reference not converged enough for the row to count) and left out "
               "of the rankings.</p>")
    return out


def prefilter_finding(ok):
    """Pre-filtered at the lowest spp against plain sampling at each higher spp (medians over scenes)."""
    low = ok["spp"].min()
    pre = ok[(ok["prefilter"] != "none") & (ok["spp"] == low)]
    if pre.empty:
        return "<p>No pre-filtered row with a finite error at the lowest spp.</p>"
    pre_best = pre.loc[pre.groupby("scene")["error"].idxmin()].set_index("scene")
    parts = []
    for spp in sorted(ok["spp"].unique()):
        plain = ok[(ok["prefilter"] == "none") & (ok["spp"] == spp)]
        if plain.empty:
            continue
        pb = plain.loc[plain.groupby("scene")["error"].idxmin()].set_index("scene")
        common_scenes = pre_best.index.intersection(pb.index)
        if not len(common_scenes):
            continue
        er = np.median(pre_best.loc[common_scenes, "error"] / pb.loc[common_scenes, "error"])
        tr = np.median(pre_best.loc[common_scenes, "time_ms"] / pb.loc[common_scenes, "time_ms"])
        parts.append(f"plain {int(spp)} spp: error x{er:.2f}, time x{tr:.2f}")
    return (f"<p>Pre-filtered at {int(low)} spp (best pre-filtered method per scene) against the best plain "
            f"sampling: " + "; ".join(parts) + " (medians over scenes; below 1 = the pre-filtered image is "
            "better or faster). The error-vs-time chart of each scene rings pre-filtered rows in black.</p>")
