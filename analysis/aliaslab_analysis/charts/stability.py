"""stability: undefined / negative / NaN pixel counts and flagged rows per method and sampler (empty
panels say so); writes flagged.csv."""
import os

import numpy as np

from . import figures
from ..io import study_csv
from .figures import plt


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
    figures.save_figure(fig, out_dir, "stability")
    flagged = df[df["flagged"] == 1][study_csv.config_key(df) + ["mse", "noise", "error"]]
    flagged.rename(columns={v: k for k, v in study_csv.RENAMED.items()}).to_csv(
        os.path.join(out_dir, "flagged.csv"), index=False)
