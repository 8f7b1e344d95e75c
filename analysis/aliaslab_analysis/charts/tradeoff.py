"""tradeoff_<target>: the target as a trade-off, not a contest (docs/science.md "Answers a practitioner can act
on"). One panel per spp level; x = blur (the filter's own reference against the target: the `blur` column),
y = noise + aliasing (the error against the filter's own reference: the `mse` column), both divided by each
scene's best error against the target and then the median over scenes taken, for every filter over its radii
(a line per filter, radius ascending), the sampler being the panel's leading sampler (stats/factors.leaders).
The filter's natural radius is ringed: the CSV's `natural_radius` column, else the registry's values
(NATURAL). Faint diagonals mark a total of 1, 2, 4, ... times the best (x + y; the cross term left out).
Values at or below 0 are drawn at the axis' floor, values beyond CLIP x the 90th percentile (filters whose weight
sums come near zero) at its top edge, counted in the title."""
import os
import re

import numpy as np

from . import figures, palette
from .figures import plt

CLIP = 100.0  # the axes end at CLIP x the 90th percentile of the values (degenerate filters reach 1e6 and more)
# The filters' natural radii as lib/filter/factory.cpp registers them (used when the CSV has no natural_radius).
NATURAL = {"box": 0.5, "tent": 1.0, "gaussian": 1.5, "mitchell": 2.0, "catmullrom": 2.0, "lanczos": 3.0,
           "hann": 3.0, "blackmanharris": 2.0, "gaussian-cut": 1.5, "course-gaussian": 1.5}


def natural_radius(rows):
    """{filter: natural radius}: the CSV's column where present, else NATURAL (NaN when unknown)."""
    out = {}
    for f, g in rows.groupby("filter_name"):
        v = g["natural_radius"].to_numpy(dtype=float) if "natural_radius" in g.columns else np.array([np.nan])
        v = v[np.isfinite(v)]
        out[f] = float(v[0]) if len(v) else NATURAL.get(str(f), np.nan)
    return out


def points(per, target, spp, sampler):
    """Per (filter, radius): the medians over scenes of blur / best and mse / best (per: the per-scene rows
    with `ratio`, stats/equivalence.per_scene), plain sampling only."""
    r = per[(per["target"].astype(str) == target) & (per["spp"] == spp) & (per["sampler"] == sampler)
            & (per["prefilter"].astype(str) == "none")]
    best = r["error"].to_numpy(dtype=float) / r["ratio"].to_numpy(dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        blur = r["blur"] if "blur" in r.columns else r["blur_cross"]  # older CSVs: blur with the cross term
        r = r.assign(x=blur.to_numpy(dtype=float) / best, y=r["mse"].to_numpy(dtype=float) / best)
    r = r[np.isfinite(r["x"]) & np.isfinite(r["y"])]
    return r.groupby(["filter_name", "radius"], sort=True).agg(x=("x", "median"), y=("y", "median")).reset_index()


def tradeoff(per, target, panels, natural, out_dir):
    """Draws tradeoff_<target>.png; panels: [(spp, sampler)]. Returns the path (None when nothing to draw)."""
    drawn = [(spp, sampler, points(per, target, spp, sampler)) for spp, sampler in panels]
    drawn = [d for d in drawn if len(d[2])]
    if not drawn:
        return None
    vals = np.concatenate([np.concatenate([p["x"], p["y"]]) for _, _, p in drawn])
    pos = vals[vals > 0]
    floor = float(pos.min()) / 2 if len(pos) else 1e-3
    top = min(float(pos.max()) * 2, CLIP * float(np.quantile(pos, 0.9))) if len(pos) else 1.0
    clipped = int((vals > top).sum())
    fig, axes = plt.subplots(1, len(drawn), figsize=(4.6 * len(drawn) + 1.8, 4.6), squeeze=False)
    filters = sorted({f for _, _, p in drawn for f in p["filter_name"]})
    for ax, (spp, sampler, p) in zip(axes[0], drawn):
        for k in range(-3, 12):
            t = 2.0 ** k
            xs = np.geomspace(floor, t, 50)
            ax.plot(xs, np.maximum(t - xs, floor), color="#ddd", lw=0.7, zorder=0)
        for f, g in p.groupby("filter_name"):
            g = g.sort_values("radius")
            x, y = np.clip(g["x"], floor, top), np.clip(g["y"], floor, top)
            c = palette.filter_colour(f)
            ax.plot(x, y, "-", color=c, marker=palette.filter_marker(f), ms=5, lw=1.2)
            nat = g[np.isclose(g["radius"], natural.get(f, np.nan))]
            ax.scatter(np.clip(nat["x"], floor, top), np.clip(nat["y"], floor, top), s=170, facecolors="none",
                       edgecolors=c, linewidths=1.8, zorder=4)
            last = g.iloc[-1]
            for end in (g.iloc[0], g.iloc[-1]):
                ax.annotate(f"r={end['radius']:g}", (min(max(end["x"], floor), top), min(max(end["y"], floor), top)),
                            fontsize=6, color=c, xytext=(3, 2), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlim(floor, top)
        ax.set_ylim(floor, top)
        ax.set_title(f"{spp} spp, sampler {sampler}", fontsize=10)
        ax.set_xlabel("blur (own reference vs target) / best", fontsize=9)
        ax.grid(True, which="major", alpha=0.25)
    axes[0][0].set_ylabel("noise + aliasing (vs own reference) / best", fontsize=9)
    handles = [plt.Line2D([], [], color=palette.filter_colour(f), marker=palette.filter_marker(f), label=f)
               for f in filters]
    handles.append(plt.Line2D([], [], ls="", marker="o", ms=11, mfc="none", mec="0.3", label="natural radius"))
    handles.append(plt.Line2D([], [], color="#ccc", label="total 1, 2, 4, ... x best"))
    axes[0][-1].legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    fig.suptitle(f"Against `{target}`: noise + aliasing against blur, every filter over its radii (medians over "
                 "scenes, each divided by the scene's best error)"
                 + (f"\n{clipped} value(s) above {top:.3g} (weight sums near zero) drawn at the edge" if clipped else ""),
                 fontsize=10)
    fig.tight_layout()
    name = "tradeoff_" + re.sub(r"[^A-Za-z0-9]+", "_", str(target))
    figures.save_figure(fig, out_dir, name)
    return os.path.join(out_dir, name + ".png")
