"""radius_<scene>: the radius trade-off. Error, noise and blur against radius, one panel per filter, one
colour per spp level, for the sampler of the scene's best method. The panels share one y range (filters are
compared), set by the non-degenerate values (degenerate.py); degenerate points are drawn at the top edge as
red up-triangles with their value."""
import numpy as np

from ..stats import degenerate
from . import figures
from .figures import plt
from .axes import ERROR_LABEL, best_row, has_target, label_log_axis, usable, yerr_log


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
        sd = sd.assign(degenerate=degenerate.mask(sd))
        sub = sd[(sd["sampler"] == sampler) & (sd["reconstruction"] == recon) & (sd["prefilter"] == "none")]
        sane = sub[~sub["degenerate"]]
        values = np.concatenate([usable(sane, c)[c].to_numpy(dtype=float) for c in ("error", "noise", blur_col)
                                 if c in sane.columns])
        lo, hi = (values.min() / 1.6, values.max() * 2.2) if len(values) else (None, None)
        n_deg = 0
        filters = sorted(sub["filter_name"].unique())
        cols = min(3, max(1, len(filters)))
        nrows = (max(1, len(filters)) + cols - 1) // cols
        fig, axes = plt.subplots(nrows, cols, figsize=(3.9 * cols + 1.6, 3.4 * nrows + 0.6), squeeze=False,
                                 sharey=True)
        for ax in axes.flat[len(filters):]:
            ax.axis("off")
        for ax, filt in zip(axes.flat, filters):
            fd = sub[sub["filter_name"] == filt]
            drawn = False
            for spp in levels:
                g = usable(fd[fd["spp"] == spp].sort_values("radius"))
                bad = g[g["degenerate"]]
                g = g[~g["degenerate"]]
                if len(bad) and hi is not None:
                    n_deg += len(bad)
                    ax.scatter(bad["radius"], np.full(len(bad), hi / 1.25), marker="^", color="#c0392b", s=28,
                               zorder=4)
                    for rad, v in zip(bad["radius"], bad["error"]):
                        ax.annotate(f"{v:.0e}", (rad, hi / 1.25), textcoords="offset points", xytext=(0, -9),
                                    fontsize=6, color="#c0392b", ha="center")
                if g.empty:
                    continue
                drawn = True
                c = spp_colours[spp]
                ax.errorbar(g["radius"], g["error"], yerr=yerr_log(g["error"], g["error_se"]), color=c,
                            marker="o", ms=4, lw=1.2, capsize=2, label=f"error, {int(spp)} spp")
                fl = g[g["flagged"] == 1]
                if len(fl):  # flagged rows stay, drawn hollow
                    ax.scatter(fl["radius"], fl["error"], s=30, facecolors="white", edgecolors=c, zorder=3)
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
                if lo is not None:
                    ax.set_ylim(lo, hi)
                ax.grid(True, which="major", alpha=0.3)
                label_log_axis(ax)
            else:
                ax.text(0.5, 0.5, "no finite value > 0", ha="center", va="center", transform=ax.transAxes,
                        fontsize=9, color="#555")  # not empty_panel: its ticks would clear the shared y axis
        for row in axes:
            row[0].yaxis.set_tick_params(labelleft=True)
            row[0].set_ylabel(ERROR_LABEL[has_target(df)].replace(" (", "\n("), fontsize=8)
        handles = [plt.Line2D([], [], color=spp_colours[s], marker="o", label=f"error, {int(s)} spp")
                   for s in levels]
        handles += [plt.Line2D([], [], ls="", marker="o", mfc="white", mec="grey", label="flagged (kept, hollow)"),
                plt.Line2D([], [], color="grey", ls="--", label="noise (same colour: spp)"),
                    plt.Line2D([], [], color="black", ls=":", marker="x",
                               label="blur" if blur_col == "blur" else "blur + cross (mse_area - mse)")]
        if n_deg:
            handles.append(plt.Line2D([], [], ls="", marker="^", color="#c0392b",
                                      label=f"degenerate, off the scale\n({degenerate.RULE})"))
        fig.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.0), fontsize=8, frameon=False,
                   ncol=min(4, len(handles)))
        fig.suptitle(f"Radius trade-off: {scene}, sampler {sampler} (that of the best method), {recon}; r is the "
                     "kernel's width: below its natural radius a kernel is squeezed", fontsize=10)
        fig.tight_layout(rect=(0, 0.04 + 0.02 * ((len(handles) + 3) // 4), 1, 1))
        figures.save_figure(fig, out_dir, f"radius_{figures.slug(scene)}")
