"""decomposition_<scene>: where the error comes from. Per spp level, the error of the best methods split
into noise, aliasing and blur as stacked bars, the cross term hatched (negative terms left of 0), the
total with +-2 se; writes decomposition.csv.gz (gzipped, the same bytes for the same table)."""
import os

import matplotlib.patches
import numpy as np
import pandas as pd

from . import figures
from .figures import plt
from ..io.study_rows import components
from .axes import BEST_SHOWN, COMPONENT_COLOURS, ERROR_LABEL, METHOD, empty_panel, has_target, method_label


def chosen_methods(sd):
    """The methods a decomposition panel shows: the BEST_SHOWN lowest errors (finite; flagged rows kept and
    marked), plus the lowest own mse if that is another method (the one an own-mse ranking would pick)."""
    ok = sd[np.isfinite(sd["error"].to_numpy(dtype=float))]
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
                empty_panel(ax, "no row with a finite error")
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
                if r["flagged"] == 1:
                    text += " (flagged)"
                if bool(r.get("deterministic", False)):
                    text += " (deterministic)"
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
        figures.save_figure(fig, out_dir, f"decomposition_{figures.slug(scene)}")
    cols = ["scene"] + METHOD + ["spp", "error", "error_se"] + [c for c, _ in terms] + ["aliasing_zero", "flagged"]
    df.sort_values(["scene", "spp", "error"])[cols].to_csv(
        os.path.join(out_dir, "decomposition.csv.gz"), index=False,
        compression={"method": "gzip", "compresslevel": 9, "mtime": 0})
