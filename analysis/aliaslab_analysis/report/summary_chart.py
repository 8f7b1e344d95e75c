"""The one chart of the findings: every method at every spp level against the primary target, its median
(over scenes) error relative to each scene's best with the bootstrap interval, against its time; the front
(stats/fronts.summary_points: no point beaten in both) numbered and listed below, each front point with its
time spread (+-2 standard errors, horizontal), and each panel's time range shaded with the spread of its
extremes written in (stats/fronts.cost_by_spp). No method is dropped: a method heavy-tailed in some scene is
drawn hollow, the fixed grid (deterministic, ranked like any method) as a cross; a median at or below 0 is
drawn at the bottom edge as a down triangle."""
import os

import matplotlib.ticker
import numpy as np

from ..charts import figures, palette
from ..stats import fronts
from ..charts import axes
from ..charts.figures import plt
from .findings import method_name

CAP_FACTOR = 4.0


def summary_points(s):
    """The chart's points (findings.Study s): stats/fronts.summary_points against the primary target."""
    return s.points().copy()


def layout(n):
    """(figure, axes): the first of n panels across the top row, the others side by side below it, all sharing
    the y axis."""
    if n == 1:
        fig, ax = plt.subplots(figsize=(12.0, 6.0))
        return fig, [ax]
    fig = plt.figure(figsize=(12.0, 11.0))
    grid = fig.add_gridspec(2, n - 1, height_ratios=[1.25, 1.0])
    top = fig.add_subplot(grid[0, :])
    below = [fig.add_subplot(grid[1, k], sharey=top) for k in range(n - 1)]
    for ax in below[1:]:
        ax.tick_params(labelleft=False)
    return fig, [top] + below


def summary_chart(s, out_dir):
    """Draws summary_error_time; returns (png path, the front's lines, the points drawn). One panel per spp
    level on one shared y axis, each with its own time range, so that the front's numbers of one cluster of
    times do not pile up; the lowest level, where the methods differ most and the front is longest, has the
    whole width of the top row (readable at a 1366-px page), the others share the row below (layout)."""
    g = summary_points(s)
    name = "summary_error_time"
    g = g[np.isfinite(g["median_ratio"].to_numpy(dtype=float)) & np.isfinite(g["cost"].to_numpy(dtype=float))
          & (g["cost"] > 0)].copy()
    if g.empty:
        fig, ax = plt.subplots(figsize=(10, 5.6))
        axes.empty_panel(ax, "no method has a finite error ratio and time")
        figures.save_figure(fig, out_dir, name)
        return os.path.join(out_dir, name + ".png"), [], g
    levels = sorted(g["spp"].unique())
    samplers = sorted(g["sampler"].unique())
    colours = {x: palette.sampler_colour(x) for x in samplers}
    pos = g["median_ratio"] > 0
    floor = float(g.loc[pos, "ci_low"].clip(lower=g.loc[pos, "median_ratio"].min() / 2).min()) / 1.5 if pos.any() else 1e-3
    # the y axis ends at CAP_FACTOR x the front's largest median (at least 10x): the question is which methods
    # are near the best; the points above are drawn at the top edge as grey triangles and counted in the title
    front_top = float(g.loc[g["front"], "median_ratio"].max()) if g["front"].any() else float(g["median_ratio"].max())
    cap = max(10.0, CAP_FACTOR * front_top)
    above = g["median_ratio"] > cap
    g["y"] = np.where(pos, np.minimum(g["median_ratio"], cap), floor)
    g["hollow"] = g["heavy"] > 0
    spans = {x["spp"]: x for x in fronts.cost_by_spp(g)}
    front = g[g["front"]].sort_values(["spp", "cost", "median_ratio"])
    fig, panels = layout(len(levels))
    lines = [f"{k}. {method_name(r)}, {int(r['spp'])} spp: x{r['median_ratio']:.3g} "
             f"[{r['ci_low']:.3g}-{r['ci_high']:.3g}], {r['cost']:.3g} ms" for k, (_, r) in enumerate(front.iterrows(), 1)]
    timing = "thread CPU time" if "cpu_ms" in s.df.columns else "wall time"
    number = 1
    for ax, spp in zip(panels, levels):
        h_all = g[g["spp"] == spp]
        f = front[front["spp"] == spp]
        lo = np.clip(f["y"] - f["ci_low"].clip(lower=floor), 0, None)
        hi = np.clip(np.minimum(f["ci_high"], cap * 1.2) - f["y"], 0, None)
        ax.errorbar(f["cost"], f["y"], yerr=np.vstack([lo, hi]), xerr=2 * f["cost_se"].fillna(0).to_numpy(),
                    fmt="none", ecolor="#999", lw=0.8, capsize=2, zorder=1)
        span = spans.get(int(spp))
        if span:
            ax.axvspan(span["low"], span["high"], color="#eef3fb", zorder=0)
            ax.text(0.01, 0.01, f"time {span['low']:.3g}-{span['high']:.3g} ms, spread of the two +-{span['spread']:.2g}"
                    + (": cost set by spp" if span["set_by_spp"] else ""), transform=ax.transAxes, fontsize=7,
                    va="bottom", color="#345")
        up = above[h_all.index]
        if up.any():
            ax.scatter(h_all.loc[up, "cost"], np.full(int(up.sum()), cap * 1.15), marker="^", color="grey", s=18,
                       zorder=2, clip_on=False)
        for (sampler, hollow, det, pre), h in h_all[~up].groupby(["sampler", "hollow", "deterministic", "prefilter"]):
            colour = colours[sampler]
            marker = np.where(h["median_ratio"] > 0, "o", "v")
            for m in set(marker):
                k = h[marker == m]
                if det:
                    ax.scatter(k["cost"], k["y"], s=40, marker="x", color=colour, linewidths=1.2, alpha=0.9, zorder=2)
                    continue
                ax.scatter(k["cost"], k["y"], s=36, marker=m, facecolors="none" if hollow else colour,
                           edgecolors="black" if pre != "none" else colour,
                           linewidths=1.5 if pre != "none" or hollow else 0.8, alpha=0.85, zorder=2)
        ax.plot(f["cost"], f["y"], "k--", lw=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        axes.plain_log_x(ax)
        if h_all["cost"].max() < 10 * h_all["cost"].min():  # less than a decade: label every minor tick
            ax.xaxis.set_minor_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
            ax.tick_params(axis="x", which="both", labelsize=8)
        ax.set_ylim(bottom=float(g["y"].min()) / 1.3, top=cap * 1.3)
        ax.set_title(f"{int(spp)} spp", fontsize=11)
        ax.set_xlabel(f"{timing} per image (ms, mean over scenes)", fontsize=9)
        ax.grid(True, which="both", alpha=0.25)
        axes.number_points(ax, list(f["cost"]), list(f["y"]), start=number)
        number += len(f)
    for ax in panels[:2]:
        ax.set_ylabel("error / each scene's best at that spp,\nlower is better (median over scenes;\n"
                      "front: 95 % bootstrap interval)", fontsize=9)
    clipped = (f"{int(above.sum())} point(s) above {cap:.3g}x (up to {g['median_ratio'].max():.3g}x) drawn as grey "
               "triangles at the top" if above.any() else "")
    handles = [plt.Line2D([], [], ls="", marker="o", color=colours[x], label=x) for x in samplers]
    handles.append(plt.Line2D([], [], ls="--", color="k", label="front (numbered): no point\nbeats it in both"))
    handles.append(plt.Line2D([], [], color="#999", label="front: 95 % interval (y),\n+-2 se of time (x)"))
    handles.append(plt.Line2D([], [], ls="", marker="s", ms=9, color="#eef3fb", label="the panel's time range"))
    handles.append(plt.Line2D([], [], ls="", marker="o", mfc="none", mec="0.3", label="hollow: heavy-tailed\n"
                              "in >= 1 scene (kept)"))
    if g["deterministic"].any():
        handles.append(plt.Line2D([], [], ls="", marker="x", color="0.3", label="cross: fixed grid\n(deterministic, ranked)"))
    if (g["median_ratio"] <= 0).any():
        handles.append(plt.Line2D([], [], ls="", marker="v", color="0.3", label="median <= 0 (drawn at the edge)"))
    if (g["prefilter"] != "none").any():
        handles.append(plt.Line2D([], [], ls="", marker="o", mfc="white", mec="black", mew=1.5, label="pre-filtered"))
    leg = panels[0].legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0),
                           title="colour: sampler", title_fontsize=8)
    leg.set_in_layout(True)
    shown = lines[:36] + ([f"... {len(lines) - 36} more"] if len(lines) > 36 else [])
    per = max(12, -(-len(shown) // 2))  # two columns
    for c in range(0, len(shown), per):
        fig.text(0.02 + 0.5 * (c // per), -0.01, ("Front:\n" if c == 0 else "\n") + "\n".join(shown[c:c + per]),
                 fontsize=8, va="top", family="monospace")
    fig.suptitle(f"Error against `{s.primary}` vs time: every method at every spp level, all "
                 f"{len(s.scenes)} scenes" + (f"\n{clipped}" if clipped else ""), fontsize=11)
    fig.tight_layout()
    figures.save_figure(fig, out_dir, name)
    return os.path.join(out_dir, name + ".png"), lines, g
