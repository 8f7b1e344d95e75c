"""heatmap_<scene>: log10 error over filter x radius, one row of panels per spp level, one column per
sampler, every cell's value written in it."""
import numpy as np

from .. import figures
from ..figures import plt
from .axes import ERROR_LABEL, has_target, usable


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
            flags = cell.pivot_table(index="row", columns="radius", values="flagged", aggfunc="max",
                                     dropna=False).reindex(index=rows_, columns=radii).to_numpy(dtype=float)
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
                if flags[i, j] == 1:
                    text += "*"
                shade = logd[i, j]
                dark = np.isfinite(shade) and (shade - vmin) / (vmax - vmin) > 0.6
                ax.text(j, i, text, ha="center", va="center", fontsize=5.5, color="black" if dark else "white")
        fig.colorbar(im, ax=axes, label=("log10 " + ERROR_LABEL[has_target(df)]).replace(" (", "\n("),
                     shrink=min(1.0, 0.9 if len(levels) > 1 else 1.0))
        fig.suptitle(f"Error over filter x radius: {scene} (grey/blank: no value or <= 0; * flagged, kept)",
                     fontsize=10)
        figures.save_figure(fig, out_dir, f"heatmap_{figures.slug(scene)}")
