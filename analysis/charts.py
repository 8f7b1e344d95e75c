#!/usr/bin/python3
"""Charts of a sweep CSV (read with common.load_study; definitions in docs/science.md).

Usage: /usr/bin/python3 analysis/charts.py study.csv --out DIR [--filter NAME]

Every ranking and every "error" axis is the error against the study's common
target (column mse_target; for CSVs of older sweeps without it, mse_area, the
error against the pixel-area reference, and the charts say so). A filter's own
mse is not used for ranking: it ignores blur, so the widest filter would win.

Writes into DIR, each as .png and .svg:
  speed_accuracy_<scene>  error against the target vs time per image, log-log;
                          colour = sampler, marker = filter, pre-filtered rows
                          (when the CSV has a prefilter column) ringed in black;
                          flagged rows hollow and off the Pareto front; the
                          front numbered, its methods listed beside the chart;
                          error bars +-2 standard errors (mse_target_se)
  decomposition_<scene>   per spp level: the error of the best methods split
                          into noise, aliasing and blur as stacked bars, the
                          cross term as its own (signed) bar, the total with
                          +-2 se; negative terms drawn left of 0
  radius_<scene>          the radius trade-off: error, noise and blur against
                          radius, one panel per filter, one colour per spp
  convergence_<scene>     error, noise and aliasing against spp per sampler;
                          slopes only when >= 3 spp levels
  heatmap_<scene>         log10 error over filter x radius, one row of panels
                          per spp level, one column per sampler
  stability               undefined / negative / NaN pixel counts per method,
                          and flagged rows per method (empty panels say so)
and the tables pareto.csv (the front of every scene), flagged.csv and
decomposition.csv. A CSV repeating a configuration is refused (exit 2).
"""
import argparse
import os
import sys

import matplotlib.patches
import matplotlib.patheffects
import matplotlib.ticker
import numpy as np
import pandas as pd

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
from common import plt  # noqa: E402

MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*", "<", ">", "h", "p"]
METHOD = ["sampler", "filter_name", "radius", "filter_params", "reconstruction", "prefilter"]
ERROR_LABEL = {True: "error against the target (mse_target, per pixel and channel)",
               False: "error against the pixel-area reference (mse_area, per pixel and channel)"}
COMPONENT_COLOURS = {"noise": "#4c72b0", "aliasing": "#dd8452", "blur": "#55a868", "cross": "#8c8c8c",
                     "blur_cross": "#55a868"}
BEST_SHOWN = 10


def has_target(df):
    return "mse_target" in df.columns


def method_label(row, show_recon=False, sampler=True):
    label = f"{row['filter_name']} r={row['radius']:g}"
    if sampler:
        label = f"{row['sampler']} " + label
    if show_recon:
        label += f" {row['reconstruction']}"
    if row.get("prefilter", "none") not in ("none", ""):
        label += f" [{row['prefilter']}]"
    return label


def usable(df, column="error"):
    """Rows with a finite, positive value of `column` (what log axes can show)."""
    v = df[column].to_numpy(dtype=float)
    with np.errstate(invalid="ignore"):
        return df[np.isfinite(v) & (v > 0)]


def empty_panel(ax, text):
    """Draws ax as an empty panel that says why it is empty."""
    ax.set_xticks([])
    ax.set_yticks([])
    ax.text(0.5, 0.5, text, ha="center", va="center", transform=ax.transAxes, fontsize=9, color="#555",
            wrap=True)


def label_log_axis(ax):
    """Labels minor ticks of a log y axis that spans less than about two decades (else one label)."""
    lo, hi = ax.get_ylim()
    if lo > 0 and hi / lo < 100:
        ax.yaxis.set_minor_formatter(matplotlib.ticker.LogFormatterSciNotation(labelOnlyBase=False,
                                                                               minor_thresholds=(2, 0.4)))
        ax.tick_params(axis="y", which="minor", labelsize=7)


def number_points(ax, xs, ys, fontsize=8):
    """Numbers the points (xs[k], ys[k]) 1, 2, ... on the axes without two numbers overlapping: each label
    takes the first free spot of a ring of offsets around its point (nearest first), further rings once the
    near ones are taken, with a thin leader line when it sits away from its point. Call it after the axes'
    limits are final (it works in display space)."""
    fig = ax.figure
    fig.canvas.draw()  # settles the layout so that data -> display is final
    to_points = 72.0 / fig.dpi
    placed = []  # centres (in points) of the labels placed so far
    w, h = 0.62 * fontsize, 1.0 * fontsize  # one digit's box, in points
    rings = [(dx * r, dy * r) for r in (1, 2, 3, 4, 5) for dx, dy in
             ((1, 1), (1, -1), (-1, 1), (-1, -1), (0, 1.4), (0, -1.4), (1.4, 0), (-1.4, 0))]
    for k, (x, y) in enumerate(zip(xs, ys), 1):
        px, py = (v * to_points for v in ax.transData.transform((x, y)))
        text = str(k)
        tw = w * len(text)
        choice = None
        for dx, dy in rings:
            ox, oy = dx * (tw / 2 + 4), dy * (h / 2 + 3)
            cx, cy = px + ox, py + oy
            if all(abs(cx - qx) >= (tw + qw) / 2 + 1 or abs(cy - qy) >= h + 1 for qx, qy, qw in placed):
                choice = (ox, oy)
                break
        if choice is None:
            choice = (rings[-1][0] * (tw / 2 + 4), rings[-1][1] * (h / 2 + 3))
        ox, oy = choice
        far = abs(ox) > tw + 6 or abs(oy) > 1.5 * h + 4
        ax.annotate(text, (x, y), textcoords="offset points", xytext=(ox, oy), fontsize=fontsize, weight="bold",
                    ha="center", va="center", zorder=6,
                    path_effects=[matplotlib.patheffects.withStroke(linewidth=2.5, foreground="white")],
                    arrowprops=dict(arrowstyle="-", lw=0.5, color="0.4", shrinkA=0, shrinkB=2) if far else None)
        placed.append((px + ox, py + oy, tw))


def plain_log_x(ax):
    """Tick labels of a log x axis as plain numbers (0.5, 2, 300), major and minor."""
    fmt = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
    ax.xaxis.set_major_formatter(fmt)
    ax.xaxis.set_minor_formatter(matplotlib.ticker.FuncFormatter(
        lambda v, _: f"{v:g}" if f"{v:.0e}"[0] in "25" else ""))
    ax.tick_params(axis="x", which="minor", labelsize=7)


OUTLIER_FACTOR = 30.0


def clip_outliers(ax, x, y, colour="grey"):
    """Caps a log y axis at OUTLIER_FACTOR x the 75th percentile of y when the values span more than
    four decades; the points above are drawn at the cap as grey triangles. Returns a note ('' if none)."""
    y = np.asarray(y, dtype=float)
    x = np.asarray(x, dtype=float)
    if len(y) < 4 or y.max() / y.min() < 1e4:
        return ""
    cap = float(np.quantile(y, 0.75)) * OUTLIER_FACTOR
    above = y > cap
    if not above.any():
        return ""
    ax.set_ylim(top=cap * 1.6)
    ax.scatter(x[above], np.full(above.sum(), cap * 1.3), marker="^", color=colour, s=30, zorder=4,
               clip_on=False)
    return f"{int(above.sum())} point(s) above {cap:.2g} (up to {y.max():.2g}) drawn as grey triangles at the top"


def yerr_log(values, se):
    """Asymmetric +-2 se error bars that stay positive on a log axis (None when se is unknown)."""
    se = np.asarray(se, dtype=float)
    if not np.isfinite(se).any():
        return None
    v = np.asarray(values, dtype=float)
    se = np.where(np.isfinite(se), se, 0.0)
    lower = np.minimum(2 * se, v * 0.999)
    return np.vstack([lower, 2 * se])


def speed_accuracy(df, out_dir):
    """Error against the target vs time per scene; returns the Pareto rows of every scene."""
    samplers = sorted(df["sampler"].unique())
    filters = sorted(df["filter_name"].unique())
    colours = {s: common.colour(i) for i, s in enumerate(samplers)}
    markers = {f: MARKERS[i % len(MARKERS)] for i, f in enumerate(filters)}
    show_recon = df["reconstruction"].nunique() > 1
    prefiltered = (df["prefilter"] != "none").any()
    fronts = []
    for scene, all_rows in df.groupby("scene", sort=True):
        sd = usable(all_rows)
        sd = sd[np.isfinite(sd["time_ms"]) & (sd["time_ms"] > 0)].reset_index(drop=True)
        left_out = len(all_rows) - len(sd)
        fig, ax = plt.subplots(figsize=(11, 6.5))
        title = f"Error against the target vs time: {scene}"
        if left_out:
            title += f"\n({left_out} row(s) with error <= 0 or not finite not drawn)"
        ax.set_title(title, fontsize=10)
        if sd.empty:
            empty_panel(ax, "no row with a finite error > 0 and a time > 0:\nnothing to draw on log axes")
            common.save_figure(fig, out_dir, f"speed_accuracy_{common.slug(scene)}")
            continue
        err = yerr_log(sd["error"], sd["error_se"])
        if err is not None:
            ax.errorbar(sd["time_ms"], sd["error"], yerr=err, fmt="none", ecolor="#bbb", lw=0.7, zorder=1)
        for (sampler, filt, hollow, pre), g in sd.groupby(["sampler", "filter_name", "flagged", "prefilter"]):
            ax.scatter(g["time_ms"], g["error"], marker=markers[filt], s=60 if pre != "none" else 36,
                       facecolors="none" if hollow == 1 else colours[sampler],
                       edgecolors="black" if pre != "none" else colours[sampler],
                       linewidths=1.6 if pre != "none" else 1.0, alpha=0.85, zorder=2)
        ok = sd[sd["flagged"] == 0].reset_index(drop=True)
        lines = []
        if len(ok):
            front = ok.iloc[common.pareto_front(ok["time_ms"], ok["error"])]
            ax.plot(front["time_ms"], front["error"], "k--", lw=1, zorder=3)
            for k, (_, r) in enumerate(front.iterrows(), 1):
                lines.append(f"{k}. {method_label(r, show_recon)}, {int(r['spp'])} spp: "
                             f"{r['error']:.2e}, {r['time_ms']:.3g} ms")
            fronts.append(front.assign(scene=scene))
        ax.set_xscale("log")
        ax.set_yscale("log")
        plain_log_x(ax)
        ymin = float(sd["error"].min())
        ax.set_ylim(bottom=ymin / 1.6)
        clipped = clip_outliers(ax, sd["time_ms"], sd["error"])
        if len(ok):
            number_points(ax, list(front["time_ms"]), list(front["error"]))
        if clipped:
            ax.set_title(title + ("\n" if "\n" not in title else "; ") + clipped, fontsize=10)
        ax.set_xlabel("time per image (ms) = trace + reconstruction")
        ax.set_ylabel(ERROR_LABEL[has_target(df)])
        ax.grid(True, which="major", alpha=0.3)
        handles = [plt.Line2D([], [], ls="", marker="o", color=colours[s], label=s) for s in samplers]
        handles += [plt.Line2D([], [], ls="", marker=markers[f], color="grey", label=f) for f in filters]
        handles += [plt.Line2D([], [], ls="--", color="k", label="Pareto front (numbered)"),
                    plt.Line2D([], [], ls="", marker="o", mfc="none", color="grey", label="flagged (reference)")]
        if prefiltered:
            handles.append(plt.Line2D([], [], ls="", marker="o", mfc="white", mec="black", mew=1.6,
                                      label="pre-filtered"))
        if err is not None:
            handles.append(plt.Line2D([], [], color="#bbb", label="+-2 standard errors"))
        leg = ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0),
                        title="colour: sampler, marker: filter", title_fontsize=7)
        ax.add_artist(leg)
        if lines:
            shown = lines[:25] + ([f"... {len(lines) - 25} more in pareto.csv"] if len(lines) > 25 else [])
            ax.text(1.01, 0.0, "Pareto front (fastest for its error):\n" + "\n".join(shown),
                    transform=ax.transAxes, fontsize=7, va="bottom", ha="left", family="monospace")
        common.save_figure(fig, out_dir, f"speed_accuracy_{common.slug(scene)}")
    cols = ["scene"] + METHOD + ["spp", "time_ms", "error", "error_se"]
    table = pd.concat(fronts)[cols] if fronts else pd.DataFrame(columns=cols)
    table.to_csv(os.path.join(out_dir, "pareto.csv"), index=False)
    return table


def components(df):
    """The decomposition's terms present in df, in drawing order: [(column, label)]."""
    if "blur" in df.columns and "cross" in df.columns:
        return [("noise", "noise"), ("aliasing", "aliasing"), ("blur", "blur"), ("cross", "cross term")]
    return [("noise", "noise"), ("aliasing", "aliasing"), ("blur_cross", "blur + cross (mse_area - mse)")]


def chosen_methods(sd):
    """The methods a decomposition panel shows: the BEST_SHOWN lowest errors (unflagged, finite), plus
    the lowest own mse if that is another method (the one an own-mse ranking would pick)."""
    ok = sd[(sd["flagged"] == 0) & np.isfinite(sd["error"].to_numpy(dtype=float))]
    best = ok.nsmallest(BEST_SHOWN, "error").assign(_top=True)
    own = ok[np.isfinite(ok["mse"].to_numpy(dtype=float))]
    if len(own):
        pick = own.loc[[own["mse"].idxmin()]]
        if pick.index[0] not in best.index:
            best = pd.concat([best, pick.assign(_top=False)])
    return best


def decomposition(df, out_dir):
    """Stacked bars of the error's terms per method, one panel per spp level."""
    terms = components(df)
    show_recon = df["reconstruction"].nunique() > 1
    for scene, sd in df.groupby("scene", sort=True):
        levels = sorted(sd["spp"].unique())
        cols = min(2, len(levels))
        rows = (len(levels) + cols - 1) // cols
        fig, axes = plt.subplots(rows, cols, figsize=(6.2 * cols, 0.32 * (BEST_SHOWN + 1) * rows + 1.6 * rows),
                                 squeeze=False)
        for ax in axes.flat[len(levels):]:
            ax.axis("off")
        any_zero = False
        for ax, spp in zip(axes.flat, levels):
            pick = chosen_methods(sd[sd["spp"] == spp])
            ax.set_title(f"{int(spp)} spp", fontsize=10)
            if pick.empty:
                empty_panel(ax, "no unflagged row with a finite error")
                continue
            pick = pick.iloc[::-1]  # best at the top
            y = np.arange(len(pick))
            pos_left = np.zeros(len(pick))
            neg_left = np.zeros(len(pick))
            for col, label in terms:
                v = np.nan_to_num(pick[col].to_numpy(dtype=float), nan=0.0, posinf=0.0, neginf=0.0)
                p, n = np.maximum(v, 0), np.minimum(v, 0)
                hatch = "//" if col == "cross" else None
                ax.barh(y, p, left=pos_left, color=COMPONENT_COLOURS[col], hatch=hatch, edgecolor="white",
                        lw=0.4, label=label)
                ax.barh(y, n, left=neg_left, color=COMPONENT_COLOURS[col], hatch=hatch, edgecolor="white",
                        lw=0.4)
                pos_left += p
                neg_left += n
            se = pick["error_se"].to_numpy(dtype=float)
            ax.errorbar(pick["error"], y, xerr=2 * np.where(np.isfinite(se), se, 0) if np.isfinite(se).any()
                        else None, fmt="D", color="black", ms=4, capsize=2, lw=0.8, label="total (+-2 se)")
            labels = []
            best_own = pick["mse"].idxmin() if np.isfinite(pick["mse"]).any() else None
            ranked = pick["_top"].to_numpy(dtype=bool)
            for (i, r), top in zip(pick.iterrows(), ranked):
                text = method_label(r, show_recon)
                if bool(r["aliasing_zero"]):
                    text += " *"
                    any_zero = True
                if i == best_own and not top:
                    text = "(lowest own mse) " + text
                labels.append(text)
            ax.set_yticks(y, labels, fontsize=7)
            ax.axvline(0, color="black", lw=0.6)
            # Scale to the best methods; an own-mse pick far beyond them is cut and its value written.
            top_rows = np.asarray(ranked, dtype=bool)
            if top_rows.any() and not top_rows.all():
                err2 = np.nan_to_num(pick["error"].to_numpy(dtype=float) + 2 * np.where(np.isfinite(se), se, 0),
                                     nan=0.0, posinf=0.0)
                right = max(float(pos_left[top_rows].max()), float(err2[top_rows].max()), 1e-300) * 1.15
                left = min(float(neg_left[top_rows].min()) * 1.15, -0.02 * right)
                beyond = ~top_rows & (np.maximum(pos_left, err2) > right)
                if beyond.any():
                    ax.set_xlim(left, right)
                    for yy, v in zip(y[beyond], pick["error"].to_numpy(dtype=float)[beyond]):
                        ax.text(right, yy, f"{v:.2g} \u2192 ", ha="right", va="center", fontsize=7,
                                color="white", weight="bold")
            ax.set_xlabel(ERROR_LABEL[has_target(df)].replace(" (", "\n("), fontsize=8)
            ax.ticklabel_format(axis="x", style="sci", scilimits=(-2, 3))
            ax.grid(True, axis="x", alpha=0.3)
        handles = [matplotlib.patches.Patch(facecolor=COMPONENT_COLOURS[c], hatch="//" if c == "cross" else None,
                                            edgecolor="white", label=l) for c, l in terms]
        handles.append(plt.Line2D([], [], ls="", marker="D", color="black", ms=4, label="total (+-2 se)"))
        labels = [h.get_label() for h in handles]
        if any_zero:
            handles.append(plt.Line2D([], [], ls=""))
            labels.append("* aliasing zero within error (|a| <= 2 se)")
        fig.legend(handles, labels, loc="lower center", ncol=len(labels), fontsize=8, frameon=False,
                   bbox_to_anchor=(0.5, -0.02))
        fig.suptitle(f"Where the error comes from: {scene} (the {BEST_SHOWN} lowest errors per spp level; "
                     "negative terms left of 0)", fontsize=11)
        fig.tight_layout(rect=(0, 0.04, 1, 0.97))
        common.save_figure(fig, out_dir, f"decomposition_{common.slug(scene)}")
    cols = ["scene"] + METHOD + ["spp", "error", "error_se"] + [c for c, _ in terms] + ["aliasing_zero", "flagged"]
    df.sort_values(["scene", "spp", "error"])[cols].to_csv(os.path.join(out_dir, "decomposition.csv"),
                                                           index=False)


def best_row(sd):
    """The scene's lowest-error unflagged row at its highest spp level (None if there is none)."""
    ok = sd[(sd["flagged"] == 0) & np.isfinite(sd["error"].to_numpy(dtype=float))]
    if ok.empty:
        return None
    top = ok[ok["spp"] == ok["spp"].max()]
    return top.loc[top["error"].idxmin()]


def radius_tradeoff(df, out_dir):
    """Error, noise and blur against radius per filter, one colour per spp, for one sampler per scene
    (the sampler of the scene's best method, named in the title)."""
    levels = sorted(df["spp"].unique())
    spp_colours = {s: plt.cm.viridis(i / max(1, len(levels) - 1) * 0.85) for i, s in enumerate(levels)}
    blur_col = "blur" if "blur" in df.columns else "blur_cross"
    for scene, sd in df.groupby("scene", sort=True):
        best = best_row(sd)
        sampler = best["sampler"] if best is not None else sorted(sd["sampler"].unique())[0]
        recon = best["reconstruction"] if best is not None else sd["reconstruction"].iloc[0]
        sub = sd[(sd["sampler"] == sampler) & (sd["reconstruction"] == recon) & (sd["prefilter"] == "none")]
        filters = sorted(sub["filter_name"].unique())
        cols = min(3, max(1, len(filters)))
        nrows = (max(1, len(filters)) + cols - 1) // cols
        fig, axes = plt.subplots(nrows, cols, figsize=(3.9 * cols + 1.6, 3.4 * nrows + 0.6), squeeze=False)
        for ax in axes.flat[len(filters):]:
            ax.axis("off")
        for ax, filt in zip(axes.flat, filters):
            fd = sub[sub["filter_name"] == filt]
            drawn = False
            for spp in levels:
                g = usable(fd[fd["spp"] == spp].sort_values("radius"))
                if g.empty:
                    continue
                drawn = True
                c = spp_colours[spp]
                ax.errorbar(g["radius"], g["error"], yerr=yerr_log(g["error"], g["error_se"]), color=c,
                            marker="o", ms=4, lw=1.2, capsize=2, label=f"error, {int(spp)} spp")
                n = usable(g, "noise")
                ax.plot(n["radius"], n["noise"], color=c, ls="--", lw=0.9)
            b = usable(fd.drop_duplicates("radius").sort_values("radius"), blur_col)
            if len(b):
                drawn = True
                ax.plot(b["radius"], b[blur_col], color="black", ls=":", marker="x", lw=1.2)
            ax.set_title(filt, fontsize=10)
            ax.set_xlabel("radius (pixels)")
            if drawn:
                ax.set_yscale("log")
                ax.grid(True, which="major", alpha=0.3)
                label_log_axis(ax)
            else:
                empty_panel(ax, "no finite value > 0")
        for row in axes:
            row[0].set_ylabel(ERROR_LABEL[has_target(df)].replace(" (", "\n("), fontsize=8)
        handles = [plt.Line2D([], [], color=spp_colours[s], marker="o", label=f"error, {int(s)} spp")
                   for s in levels]
        handles += [plt.Line2D([], [], color="grey", ls="--", label="noise (same colour: spp)"),
                    plt.Line2D([], [], color="black", ls=":", marker="x",
                               label="blur" if blur_col == "blur" else "blur + cross (mse_area - mse)")]
        fig.legend(handles=handles, loc="center left", bbox_to_anchor=(1.0, 0.5), fontsize=8, frameon=False)
        fig.suptitle(f"Radius trade-off: {scene}, sampler {sampler} (that of the best method), {recon}: "
                     "a wider filter lowers noise and adds blur", fontsize=10)
        fig.tight_layout()
        common.save_figure(fig, out_dir, f"radius_{common.slug(scene)}")


def convergence(df, out_dir, filter_name):
    """Error, noise and aliasing against spp per sampler, for one filter configuration per scene: the
    one of the scene's best method, or the best radius of --filter. Slopes need >= 3 spp levels."""
    panels = [("error", "error_se", "error against the target" if has_target(df) else "mse_area"),
              ("noise", "noise_se", "noise"), ("aliasing", "aliasing_se", "aliasing")]
    for scene, sd in df.groupby("scene", sort=True):
        pool = sd if filter_name is None else sd[sd["filter_name"] == filter_name]
        best = best_row(pool)
        if best is None:
            best = pool.iloc[0] if len(pool) else sd.iloc[0]
        fd = sd[(sd["filter_name"] == best["filter_name"]) & (sd["radius"] == best["radius"])
                & (sd["filter_params"] == best["filter_params"]) & (sd["reconstruction"] == best["reconstruction"])
                & (sd["prefilter"] == best["prefilter"])]
        levels = sorted(fd["spp"].unique())
        fig, axes = plt.subplots(1, 3, figsize=(13, 4.4 + 0.16 * ((fd["sampler"].nunique() + 1) // 2)))
        for ax, (metric, se_col, name) in zip(axes, panels):
            title = name
            drawn = 0
            for i, (sampler, g) in enumerate(fd.groupby("sampler", sort=True)):
                g = g.sort_values("spp")
                pos = usable(g, metric)
                slope = common.slope_or_none(g["spp"], g[metric])
                label = sampler + (f" (slope {slope:+.2f})" if slope is not None else "")
                if pos.empty:
                    continue
                drawn += 1
                se = pos[se_col] if se_col in pos.columns else pd.Series(np.nan, index=pos.index)
                ax.errorbar(pos["spp"], pos[metric], yerr=yerr_log(pos[metric], se), marker=MARKERS[i % len(MARKERS)],
                            color=common.colour(i), label=label, capsize=2, ms=5, lw=1.2)
            if metric == "aliasing" and "aliasing_se" in fd.columns:
                zero = fd[fd["aliasing_zero"].astype(bool)]
                if len(zero):
                    title += (f"\n{len(zero)} of {len(fd)} points zero within error (|a| <= 2 se)"
                              + ("; <= 0 not drawn" if (fd["aliasing"] <= 0).any() else ""))
            ax.set_title(title, fontsize=9)
            if not drawn:
                empty_panel(ax, f"no {metric} > 0 to draw on log axes")
                continue
            ax.set_xscale("log", base=2)
            ax.set_yscale("log")
            ax.set_xlabel("samples per pixel")
            ax.set_ylabel(f"{name}\n(per pixel and channel)", fontsize=9)
            ax.grid(True, which="major", alpha=0.3)
            label_log_axis(ax)
            ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, frameon=False)
        if "blur" in fd.columns and np.isfinite(fd["blur"]).any() and (fd["blur"] > 0).any():
            axes[0].axhline(float(fd["blur"].max()), color="black", ls=":", lw=1)
            axes[0].text(0.98, float(fd["blur"].max()), "blur (floor)", ha="right", va="bottom", fontsize=7,
                         transform=axes[0].get_yaxis_transform())
        fit = ("slopes: least squares on log-log over the spp levels" if len(levels) >= common.MIN_SLOPE_LEVELS
               else f"no slopes: {len(levels)} spp level(s), a slope needs >= {common.MIN_SLOPE_LEVELS}")
        fig.suptitle(f"Convergence: {scene}, {method_label(best, True, sampler=False)} "
                     f"({'--filter ' + filter_name + ', best radius' if filter_name else 'the best method'});"
                     f" {fit}; error bars +-2 se", fontsize=10)
        fig.tight_layout(rect=(0, 0, 1, 0.94))
        common.save_figure(fig, out_dir, f"convergence_{common.slug(scene)}")


def heatmaps(df, out_dir):
    """log10 error over filter x radius: one row of panels per spp level, one column per sampler."""
    show_recon = df["reconstruction"].nunique() > 1
    for scene, sd in df.groupby("scene", sort=True):
        sd = sd.assign(row=[f"{r['filter_name']}" + (f" {r['reconstruction']}" if show_recon else "")
                            + (f" [{r['prefilter']}]" if r["prefilter"] != "none" else "")
                            for _, r in sd.iterrows()])
        levels = sorted(sd["spp"].unique())
        samplers = sorted(sd["sampler"].unique())
        rows_ = sorted(sd["row"].unique())
        radii = sorted(sd["radius"].unique())
        pos = usable(sd)["error"]
        vmin, vmax = (np.log10(pos.min()), np.log10(pos.max())) if len(pos) else (-6.0, 0.0)
        if vmax - vmin < 1e-9:
            vmin, vmax = vmin - 0.5, vmax + 0.5
        w = 0.62 * len(radii) + 0.6
        h = 0.3 * len(rows_) + 0.9
        fig, axes = plt.subplots(len(levels), len(samplers), figsize=(w * len(samplers) + 2.8, h * len(levels) + 1.2),
                                 squeeze=False, layout="constrained")
        im = None
        for (a, spp), (b, sampler) in [(x, y) for x in enumerate(levels) for y in enumerate(samplers)]:
            ax = axes[a][b]
            cell = sd[(sd["spp"] == spp) & (sd["sampler"] == sampler)]
            table = cell.pivot_table(index="row", columns="radius", values="error", aggfunc="first",
                                     dropna=False).reindex(index=rows_, columns=radii)
            data = table.to_numpy(dtype=float)
            with np.errstate(divide="ignore", invalid="ignore"):
                logd = np.where(np.isfinite(data) & (data > 0), np.log10(np.where(data > 0, data, 1)), np.nan)
            im = ax.imshow(logd, cmap="viridis", vmin=vmin, vmax=vmax, aspect="auto")
            ax.set_xticks(range(len(radii)), [f"{r:g}" for r in radii], fontsize=7)
            ax.set_yticks(range(len(rows_)), rows_ if b == 0 else [], fontsize=7)
            if a == len(levels) - 1:
                ax.set_xlabel("radius (px)", fontsize=7)
            ax.set_title(f"{sampler}, {int(spp)} spp", fontsize=8)
            for (i, j), v in np.ndenumerate(data):
                text = f"{v:.1e}".replace("e-0", "e-") if np.isfinite(v) else ("n/a" if np.isnan(v) else str(v))
                if np.isfinite(v) and v <= 0:
                    text = f"{v:.0e}"
                shade = logd[i, j]
                dark = np.isfinite(shade) and (shade - vmin) / (vmax - vmin) > 0.6
                ax.text(j, i, text, ha="center", va="center", fontsize=5.5, color="black" if dark else "white")
        fig.colorbar(im, ax=axes, label=("log10 " + ERROR_LABEL[has_target(df)]).replace(" (", "\n("),
                     shrink=min(1.0, 0.9 if len(levels) > 1 else 1.0))
        fig.suptitle(f"Error over filter x radius: {scene} (grey/blank: no value or <= 0)", fontsize=10)
        common.save_figure(fig, out_dir, f"heatmap_{common.slug(scene)}")


def stability(df, out_dir):
    """Pixel failure counts per method (all scenes and spp summed) and flagged rows."""
    df = df.assign(method=df["filter_name"] + " r=" + df["radius"].map("{:g}".format) + " "
                   + df["reconstruction"] + np.where(df["prefilter"] != "none", " [" + df["prefilter"] + "]", ""))
    panels = [("undefined_pixels", "undefined pixels\n(|sum of weights| < tol)"),
              ("negative_pixels", "negative pixels"), ("nan_pixels", "NaN / Inf pixels"),
              ("flagged", "flagged rows\n(reference not converged)")]
    methods = sorted(df["method"].unique())
    samplers = sorted(df["sampler"].unique())
    fig, axes = plt.subplots(1, 4, figsize=(2.6 + 4 * (0.32 * len(samplers) + 1.0), 2.2 + 0.26 * len(methods)),
                             layout="constrained")
    for k, (ax, (col, title)) in enumerate(zip(axes, panels)):
        table = df.pivot_table(index="method", columns="sampler", values=col, aggfunc="sum").reindex(
            index=methods, columns=samplers).fillna(0)
        data = table.to_numpy(dtype=float)
        ax.set_title(title, fontsize=9)
        ax.set_xticks(range(len(samplers)), samplers, rotation=60, ha="right", fontsize=7)
        ax.set_yticks(range(len(methods)), methods if k == 0 else [], fontsize=7)
        if not (data > 0).any():
            ax.imshow(np.zeros_like(data), cmap="Greys", vmin=0, vmax=1, aspect="auto")
            ax.text(0.5, 0.5, "none: every count is 0", ha="center", va="center", transform=ax.transAxes,
                    fontsize=9, color="#333", bbox=dict(facecolor="white", edgecolor="#999"))
            continue
        top = max(np.log10(1 + data.max()), 0.5)
        im = ax.imshow(np.where(data > 0, np.log10(1 + data), np.nan), cmap="magma_r", aspect="auto", vmin=0,
                       vmax=top)
        for (i, j), v in np.ndenumerate(data):
            if v > 0:
                ax.text(j, i, f"{int(v)}", ha="center", va="center", fontsize=6,
                        color="white" if np.log10(1 + v) / top > 0.45 else "black")
        fig.colorbar(im, ax=ax, label="log10(1 + count)", shrink=0.6)
    fig.suptitle("Stability: counts summed over scenes and spp (filter r reconstruction x sampler; "
                 "blank cells: 0)", fontsize=10)
    common.save_figure(fig, out_dir, "stability")
    flagged = df[df["flagged"] == 1][common.config_key(df) + ["mse", "noise", "error"]]
    flagged.rename(columns={v: k for k, v in common.RENAMED.items()}).to_csv(
        os.path.join(out_dir, "flagged.csv"), index=False)


def draw_all(df, out_dir, filter_name=None):
    """Every chart and table of a study loaded with common.load_study."""
    common.prepare_out(out_dir)
    speed_accuracy(df, out_dir)
    decomposition(df, out_dir)
    radius_tradeoff(df, out_dir)
    convergence(df, out_dir, filter_name)
    heatmaps(df, out_dir)
    stability(df, out_dir)


def main(argv=None):
    ap = argparse.ArgumentParser(description="Charts of an aliaslab sweep CSV (definitions: docs/science.md)")
    ap.add_argument("csv", help="study CSV")
    ap.add_argument("--out", required=True, help="output folder")
    ap.add_argument("--filter", default=None,
                    help="filter of the convergence chart (default: that of each scene's best method)")
    args = ap.parse_args(argv)
    try:
        df, notes = common.load_study(args.csv)
    except common.InputError as e:
        common.fail(str(e))
    if args.filter is not None and not (df["filter_name"] == args.filter).any():
        common.fail(f"--filter: no rows with filter '{args.filter}'")
    for n in notes:
        print(f"note: {n}", file=sys.stderr)
    draw_all(df, args.out, args.filter)
    print(f"charts written to {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
