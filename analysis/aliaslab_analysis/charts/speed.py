"""speed_accuracy_<scene>: error against the target vs time per image (cost: cpu_ms, else wall time), log-log,
with the numbered front (stats/fronts.front_mask: the points no other point beats in both error and time;
colour = sampler, marker = filter, pre-filtered rows
ringed, flagged rows hollow and kept (on the front when nothing beats them), the fixed grid (deterministic,
ranked like any method) as crosses; writes pareto.csv, the front of every scene."""
import os

import numpy as np
import pandas as pd

from . import figures, palette
from .figures import plt
from ..stats import fronts as tie_fronts
from .axes import (ERROR_LABEL, METHOD, clip_outliers, empty_panel, has_target, method_label, number_points,
                   plain_log_x, usable, yerr_log)


def speed_accuracy(df, out_dir):
    """Error against the target vs time per scene; returns the Pareto rows of every scene."""
    samplers = sorted(df["sampler"].unique())
    filters = sorted(df["filter_name"].unique())
    colours = {s: palette.sampler_colour(s) for s in samplers}
    markers = {f: palette.filter_marker(f) for f in filters}
    show_recon = df["reconstruction"].nunique() > 1
    prefiltered = (df["prefilter"] != "none").any()
    fronts = []
    for scene, all_rows in df.groupby("scene", sort=True):
        timed = all_rows[np.isfinite(all_rows["cost"]) & (all_rows["cost"] > 0)
                         & np.isfinite(all_rows["error"].to_numpy(dtype=float))].reset_index(drop=True)
        sd = usable(timed).reset_index(drop=True)
        low = timed[timed["error"] <= 0]  # corrected errors at or below 0 (nearly exact): drawn at the bottom edge
        left_out = len(all_rows) - len(timed)
        fig, ax = plt.subplots(figsize=(11, 6.5))
        title = f"Error against the target vs time: {scene}"
        if left_out:
            title += f"\n({left_out} row(s) with a non-finite error or time not drawn)"
        ax.set_title(title, fontsize=10)
        if sd.empty:
            empty_panel(ax, "no row with a finite error > 0 and a time > 0:\nnothing to draw on log axes")
            figures.save_figure(fig, out_dir, f"speed_accuracy_{figures.slug(scene)}")
            continue
        err = yerr_log(sd["error"], sd["error_se"])
        if err is not None:
            ax.errorbar(sd["cost"], sd["error"], yerr=err, fmt="none", ecolor="#bbb", lw=0.7, zorder=1)
        det = sd["deterministic"].to_numpy(dtype=bool)
        for (sampler, filt, hollow, pre), g in sd[~det].groupby(["sampler", "filter_name", "flagged", "prefilter"]):
            ax.scatter(g["cost"], g["error"], marker=markers[filt], s=60 if pre != "none" else 36,
                       facecolors="none" if hollow == 1 else colours[sampler],
                       edgecolors="black" if pre != "none" else colours[sampler],
                       linewidths=1.6 if pre != "none" else 1.0, alpha=0.85, zorder=2)
        if det.any():
            g = sd[det]
            ax.scatter(g["cost"], g["error"], marker="x", s=30, color=[colours[x] for x in g["sampler"]], zorder=2)
        ok = timed.reset_index(drop=True)
        lines = []
        bottom = float(sd["error"].min()) / 1.6
        if len(low):
            ax.scatter(low["cost"], np.full(len(low), bottom * 1.1), marker="v", s=36, facecolors="none",
                       edgecolors=[colours[x] for x in low["sampler"]], zorder=2)
        if len(ok):
            front = ok[tie_fronts.front_mask(ok)].sort_values(["cost", "error"])
            ax.plot(front["cost"], np.maximum(front["error"], bottom * 1.1), "k--", lw=1, zorder=3)
            for k, (_, r) in enumerate(front.iterrows(), 1):
                lines.append(f"{k}. {method_label(r, show_recon)}, {int(r['spp'])} spp: "
                             f"{r['error']:.2e}, {r['cost']:.3g} ms" + (" (flagged)" if r["flagged"] == 1 else ""))
            fronts.append(front.assign(scene=scene))
        ax.set_xscale("log")
        ax.set_yscale("log")
        plain_log_x(ax)
        ax.set_ylim(bottom=bottom)
        clipped = clip_outliers(ax, sd["cost"], sd["error"])
        if len(ok):
            number_points(ax, list(front["cost"]), list(np.maximum(front["error"], bottom * 1.1)))
        if clipped:
            ax.set_title(title + ("\n" if "\n" not in title else "; ") + clipped, fontsize=10)
        ax.set_xlabel("thread CPU time per image (ms, cpu_ms)" if "cpu_ms" in df.columns else
                      "time per image (ms) = trace + reconstruction (wall)")
        ax.set_ylabel(ERROR_LABEL[has_target(df)])
        ax.grid(True, which="major", alpha=0.3)
        handles = [plt.Line2D([], [], ls="", marker="o", color=colours[s], label=s) for s in samplers]
        handles += [plt.Line2D([], [], ls="", marker=markers[f], color="grey", label=f) for f in filters]
        handles += [plt.Line2D([], [], ls="--", color="k", label="front (numbered)"),
                    plt.Line2D([], [], ls="", marker="o", mfc="none", color="grey", label="flagged (kept)")]
        if det.any():
            handles.append(plt.Line2D([], [], ls="", marker="x", color="grey", label="fixed grid (deterministic)"))
        if len(low):
            handles.append(plt.Line2D([], [], ls="", marker="v", mfc="none", color="grey", label="error <= 0 (at the edge)"))
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
            per = 9  # below the chart, in columns: beside it the legend would cover them
            for c in range(0, len(shown), per):
                ax.text(0.5 * (c // per), -0.11, ("Front:\n" if c == 0 else "\n") + "\n".join(shown[c:c + per]),
                        transform=ax.transAxes, fontsize=7, va="top", ha="left", family="monospace")
        figures.save_figure(fig, out_dir, f"speed_accuracy_{figures.slug(scene)}")
    cols = ["scene"] + METHOD + ["spp", "time_ms", "cost", "cost_se", "error", "error_se", "flagged"]
    table = pd.concat(fronts)[cols] if fronts else pd.DataFrame(columns=cols)
    table.to_csv(os.path.join(out_dir, "pareto.csv"), index=False)
    return table
