"""heatmap_<scene>: log10 error over sampler x (filter, radius), one panel per spp level, every cell's value
written in it at a size that can be read on the page. Degenerate cells (degenerate.py: weight sums near zero)
are hatched, labelled and kept out of the colour scale, so that the useful cells spread over the colours."""
import matplotlib.colors
import numpy as np

from ..stats import degenerate
from . import figures
from .figures import plt
from .axes import ERROR_LABEL, has_target, usable

CELL_W, CELL_H = 0.52, 0.27  # inches per cell: at the page's width the numbers are about 10 px tall


def cell_text(v, flagged):
    if not np.isfinite(v):
        return "n/a"
    text = f"{v:.1e}".replace("e-0", "e-").replace("e+0", "e")
    return text + ("*" if flagged else "")


def heatmaps(df, out_dir):
    """log10 error over sampler (rows) x filter and radius (columns), one panel per spp level."""
    show_recon = df["reconstruction"].nunique() > 1
    for scene, sd in df.groupby("scene", sort=True):
        sd = sd.assign(method=[f"{r['filter_name']}" + (f" {r['reconstruction']}" if show_recon else "")
                               + (f" [{r['prefilter']}]" if r["prefilter"] != "none" else "")
                               for _, r in sd.iterrows()], degenerate=degenerate.mask(sd))
        levels = sorted(sd["spp"].unique())
        samplers = sorted(sd["sampler"].unique())
        methods = sorted(sd["method"].unique())
        radii = sorted(sd["radius"].unique())
        columns = [(m, r) for m in methods for r in radii]
        pos = np.log10(usable(sd[~sd["degenerate"]])["error"].to_numpy(dtype=float))
        # the scale spans the non-degenerate cells up to their 95th percentile (above: the top colour, the
        # colour bar's arrow), so that a few poor cells do not turn every useful one the same colour
        vmin, vmax = (pos.min(), min(pos.max(), np.quantile(pos, 0.95))) if len(pos) else (-6.0, 0.0)
        if vmax - vmin < 1e-9:
            vmin, vmax = vmin - 0.5, vmax + 0.5
        norm = matplotlib.colors.Normalize(vmin, vmax)
        width = CELL_W * len(columns) + 1.4
        height = (CELL_H * len(samplers) + 0.9) * len(levels) + 1.4
        fig, axes = plt.subplots(len(levels), 1, figsize=(width, height), squeeze=False, layout="constrained")
        im = None
        n_deg = 0
        for ax, spp in zip(axes[:, 0], levels):
            cell = sd[sd["spp"] == spp]
            grid = {(r["sampler"], r["method"], r["radius"]): r for _, r in cell.iterrows()}
            data = np.full((len(samplers), len(columns)), np.nan)
            deg = np.zeros_like(data, dtype=bool)
            flag = np.zeros_like(deg)
            for i, s in enumerate(samplers):
                for j, (m, rad) in enumerate(columns):
                    r = grid.get((s, m, rad))
                    if r is not None:
                        data[i, j] = r["error"]
                        deg[i, j] = bool(r["degenerate"]) and np.isfinite(r["error"])
                        flag[i, j] = r["flagged"] == 1
            n_deg += int(deg.sum())
            with np.errstate(divide="ignore", invalid="ignore"):
                logd = np.where(np.isfinite(data) & (data > 0) & ~deg, np.log10(np.where(data > 0, data, 1)), np.nan)
            im = ax.imshow(logd, cmap="viridis", norm=norm, aspect="auto")
            ax.set_facecolor("#f4f4f4")
            for (i, j) in zip(*np.nonzero(deg)):
                ax.add_patch(plt.Rectangle((j - 0.5, i - 0.5), 1, 1, facecolor="white", edgecolor="#c0392b",
                                           hatch="////", lw=0, alpha=0.6))
            for (i, j), v in np.ndenumerate(data):
                shade = logd[i, j]
                light = np.isfinite(shade) and norm(shade) > 0.6
                colour = "#8b1a10" if deg[i, j] else ("black" if light or not np.isfinite(shade) else "white")
                ax.text(j, i, cell_text(v, flag[i, j]), ha="center", va="center", fontsize=7.5, color=colour,
                        weight="bold" if deg[i, j] else "normal")
            ax.set_xticks(range(len(columns)), [f"{r:g}" for _, r in columns], fontsize=7)
            ax.set_yticks(range(len(samplers)), samplers, fontsize=7.5)
            for k in range(1, len(methods)):
                ax.axvline(k * len(radii) - 0.5, color="white", lw=2.5)
            for k, m in enumerate(methods):
                ax.text((k + 0.5) * len(radii) - 0.5, -0.7, m, ha="center", va="bottom", fontsize=8, weight="bold")
            ax.set_xlabel("radius (px), grouped by filter", fontsize=7)
            ax.set_title(f"{int(spp)} spp", fontsize=9, loc="left", pad=14)
        fig.colorbar(im, ax=axes, label="log10 " + ERROR_LABEL[has_target(df)], location="bottom", shrink=0.6,
                     aspect=40, extend="max" if len(pos) and pos.max() > vmax else "neither")
        fig.suptitle(f"Error over sampler x filter x radius: {scene}. Hatched red: degenerate ({degenerate.RULE}; "
                     f"{n_deg} cell(s), kept out of the colour scale); * flagged (kept); n/a: no value", fontsize=9)
        figures.save_figure(fig, out_dir, f"heatmap_{figures.slug(scene)}")
