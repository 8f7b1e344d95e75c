"""The one chart of the findings: every method at every spp level, its error relative to each scene's
best (geometric mean over scenes) against its time, the Pareto front numbered and listed below."""
import os

import numpy as np

from .. import figures, fits
from ..charts import axes
from ..figures import plt
from .findings import method_name, summary_table


def summary_chart(df, out_dir):
    """The one chart of the findings: error relative to each scene's best against time per image."""
    g = summary_table(df)
    fig, ax = plt.subplots(figsize=(10, 5.6))
    name = "summary_error_time"
    if g.empty:
        axes.empty_panel(ax, "no method has a finite error in every scene")
        figures.save_figure(fig, out_dir, name)
        return os.path.join(out_dir, name + ".png"), []
    levels = sorted(g["spp"].unique())
    samplers = sorted(g["sampler"].unique())
    colours = {s: figures.colour(i) for i, s in enumerate(samplers)}
    sizes = {s: 18 + 60 * i / max(1, len(levels) - 1) for i, s in enumerate(levels)}
    for (sampler, pre), h in g.groupby(["sampler", "prefilter"]):
        ax.scatter(h["time_ms"], h["ratio"], s=h["spp"].map(sizes), color=colours[sampler], alpha=0.75,
                   edgecolors="black" if pre != "none" else "none", linewidths=1.5)
    front = g.iloc[fits.pareto_front(g["time_ms"], g["ratio"])]
    ax.plot(front["time_ms"], front["ratio"], "k--", lw=1)
    lines = []
    for k, (_, r) in enumerate(front.iterrows(), 1):
        lines.append(f"{k}. {method_name(r)}, {int(r['spp'])} spp: x{r['ratio']:.3g}, {r['time_ms']:.3g} ms")
    ax.set_xscale("log")
    ax.set_yscale("log")
    axes.plain_log_x(ax)
    ax.set_ylim(bottom=float(g["ratio"].min()) / 1.5)
    clipped = axes.clip_outliers(ax, g["time_ms"], g["ratio"])
    ax.set_xlabel("time per image (ms, mean over scenes)")
    ax.set_ylabel("error / the scene's lowest error at any spp\n(geometric mean over scenes; 1 = best)")
    ax.grid(True, which="both", alpha=0.25)
    handles = [plt.Line2D([], [], ls="", marker="o", color=colours[s], label=s) for s in samplers]
    handles += [plt.Line2D([], [], ls="", marker="o", color="grey", ms=np.sqrt(sizes[s]), label=f"{int(s)} spp")
                for s in levels]
    handles.append(plt.Line2D([], [], ls="--", color="k", label="Pareto front (numbered)"))
    if (g["prefilter"] != "none").any():
        handles.append(plt.Line2D([], [], ls="", marker="o", mfc="white", mec="black", mew=1.5, label="pre-filtered"))
    leg = ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0),
                    title="colour: sampler, size: spp", title_fontsize=7)
    leg.set_in_layout(True)
    # the numbered front below the plot, in columns of at most 8 lines (beside the legend it collided with
    # it once there were a dozen samplers)
    shown = lines[:24] + ([f"... {len(lines) - 24} more"] if len(lines) > 24 else [])
    per_col = 8
    for c in range(0, len(shown), per_col):
        ax.text(0.55 * (c // per_col), -0.17, ("Pareto front:\n" if c == 0 else "\n") + "\n".join(shown[c:c + per_col]),
                transform=ax.transAxes, fontsize=7, va="top", family="monospace")
    ax.set_title("Error against the target vs time, every method at every spp level, all scenes"
                 + (f"\n{clipped}" if clipped else ""), fontsize=10)
    axes.number_points(ax, list(front["time_ms"]), list(front["ratio"]))
    figures.save_figure(fig, out_dir, name)
    return os.path.join(out_dir, name + ".png"), lines
