"""convergence_<scene>: error, noise and aliasing against spp per sampler, for one filter configuration
per scene; slopes only over at least three spp levels (fits.MIN_SLOPE_LEVELS)."""
import numpy as np
import pandas as pd

from . import figures, palette
from ..stats import fits
from .figures import plt
from .axes import best_row, empty_panel, has_target, label_log_axis, method_label, usable, yerr_log


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
            for sampler, g in fd.groupby("sampler", sort=True):
                g = g.sort_values("spp")
                pos = usable(g, metric)
                slope = fits.slope_or_none(g["spp"], g[metric])
                label = sampler + (f" (slope {slope:+.2f})" if slope is not None else "")
                if pos.empty:
                    continue
                drawn += 1
                se = pos[se_col] if se_col in pos.columns else pd.Series(np.nan, index=pos.index)
                ax.errorbar(pos["spp"], pos[metric], yerr=yerr_log(pos[metric], se), marker="o",
                            color=palette.sampler_colour(sampler), label=label, capsize=2, ms=5, lw=1.2)
                fl = pos[pos["flagged"] == 1]
                if metric == "error" and len(fl):  # flagged rows stay, drawn hollow
                    ax.scatter(fl["spp"], fl[metric], s=40, marker="o", facecolors="white",
                               edgecolors=palette.sampler_colour(sampler), zorder=3)
                    title = name + "\n(hollow: flagged, kept)"
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
            ax.set_ylabel(f"{name}\n(per pixel and channel; lower is better)", fontsize=9)
            ax.grid(True, which="major", alpha=0.3)
            label_log_axis(ax)
            ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, frameon=False)
        if "blur" in fd.columns and np.isfinite(fd["blur"]).any() and (fd["blur"] > 0).any():
            axes[0].axhline(float(fd["blur"].max()), color="black", ls=":", lw=1)
            axes[0].text(0.98, float(fd["blur"].max()), "blur (floor)", ha="right", va="bottom", fontsize=7,
                         transform=axes[0].get_yaxis_transform())
        fit = ("slopes: least squares on log-log over the spp levels" if len(levels) >= fits.MIN_SLOPE_LEVELS
               else f"no slopes: {len(levels)} spp level(s), a slope needs >= {fits.MIN_SLOPE_LEVELS}")
        fig.suptitle(f"Convergence: {scene}, {method_label(best, True, sampler=False)} "
                     f"({'--filter ' + filter_name + ', best radius' if filter_name else 'the best method'});"
                     f" {fit}; error bars +-2 se", fontsize=10)
        fig.tight_layout(rect=(0, 0, 1, 0.94))
        figures.save_figure(fig, out_dir, f"convergence_{figures.slug(scene)}")
