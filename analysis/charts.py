#!/usr/bin/python3
"""Charts of a sweep CSV (the study engineer's format, see common.STUDY_COLUMNS).

Usage: /usr/bin/python3 analysis/charts.py study.csv --out DIR [--filter NAME]

Writes into DIR, each as .png and .svg:
  speed_accuracy_<scene>  time per image (trace_ms + reconstruct_ms) against
                          mse, log-log; colour = sampler, marker = filter;
                          the Pareto front (fastest for its error) drawn and
                          labelled; flagged rows hollow and off the front
  convergence_<scene>     mse, aliasing, noise against spp per sampler for one
                          filter (default: the most common), fitted slopes in
                          the legend
  heatmap_<scene>         mse over filter x radius, one panel per sampler
  stability               undefined / negative / NaN pixel counts per method,
                          and flagged rows per method
and the tables pareto.csv (the front of every scene) and flagged.csv.
Rows repeated with the same configuration are averaged.
"""
import argparse
import os
import sys

import numpy as np
import pandas as pd

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
from common import plt  # noqa: E402

MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*", "<", ">", "h", "p"]
METHOD = ["sampler", "filter", "radius", "filter_params", "reconstruction"]


def method_label(row, show_recon):
    label = f"{row['sampler']}/{row['filter']} r={row['radius']:g}"
    if show_recon:
        label += f" ({row['reconstruction']})"
    return label


def aggregate(df):
    """One row per configuration: metrics averaged, counts summed, flagged if any."""
    metrics = ["mse", "aliasing", "noise", "mse_area", "psnr", "trace_ms", "reconstruct_ms", "time_ms"]
    counts = ["nan_pixels", "negative_pixels", "undefined_pixels", "flagged"]
    g = df.groupby(common.CONFIG_KEY, sort=True, dropna=False)
    out = g[metrics].mean().join(g[counts].sum())
    out["flagged"] = (out["flagged"] > 0).astype(int)
    return out.reset_index()


def speed_accuracy(df, out_dir):
    """(a) One figure per scene; returns the Pareto rows of every scene."""
    samplers = sorted(df["sampler"].unique())
    filters = sorted(df["filter"].unique())
    colours = {s: common.colour(i) for i, s in enumerate(samplers)}
    markers = {f: MARKERS[i % len(MARKERS)] for i, f in enumerate(filters)}
    show_recon = df["reconstruction"].nunique() > 1
    fronts = []
    for scene, sd in df.groupby("scene", sort=True):
        sd = sd[(sd["mse"] > 0) & (sd["time_ms"] > 0)].reset_index(drop=True)
        fig, ax = plt.subplots(figsize=(10, 7))
        for (sampler, filt, hollow), g in sd.groupby(["sampler", "filter", "flagged"]):
            ax.scatter(g["time_ms"], g["mse"], marker=markers[filt], s=36,
                       facecolors="none" if hollow == 1 else colours[sampler],
                       edgecolors=colours[sampler], linewidths=1.0, alpha=0.85)
        ok = sd[sd["flagged"] == 0].reset_index(drop=True)
        if len(ok):
            idx = common.pareto_front(ok["time_ms"], ok["mse"])
            front = ok.iloc[idx]
            ax.plot(front["time_ms"], front["mse"], "k--", lw=1, label="Pareto front")
            for _, r in front.iterrows():
                ax.annotate(f"{method_label(r, show_recon)} spp={int(r['spp'])}", (r["time_ms"], r["mse"]),
                            textcoords="offset points", xytext=(5, 4), fontsize=7)
            fronts.append(front.assign(scene=scene))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("time per image (ms) = trace + reconstruction")
        ax.set_ylabel("mse (per pixel and channel)")
        ax.set_title(f"Speed against accuracy: {scene}")
        handles = [plt.Line2D([], [], ls="", marker="o", color=colours[s], label=s) for s in samplers]
        handles += [plt.Line2D([], [], ls="", marker=markers[f], color="grey", label=f) for f in filters]
        handles += [plt.Line2D([], [], ls="--", color="k", label="Pareto front"),
                    plt.Line2D([], [], ls="", marker="o", mfc="none", color="grey", label="flagged (reference)")]
        ax.legend(handles=handles, fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5),
                  title="colour: sampler, marker: filter", title_fontsize=7)
        ax.grid(True, which="major", alpha=0.3)
        common.save_figure(fig, out_dir, f"speed_accuracy_{common.slug(scene)}")
    cols = ["scene"] + METHOD + ["spp", "time_ms", "mse"]
    table = pd.concat(fronts)[cols] if fronts else pd.DataFrame(columns=cols)
    table.to_csv(os.path.join(out_dir, "pareto.csv"), index=False)
    return table


def convergence(df, out_dir, filter_name):
    """(b) mse, aliasing, noise against spp per sampler for one filter configuration."""
    if filter_name is None:
        filter_name = common.most_common(df["filter"])
    fd = df[df["filter"] == filter_name]
    if fd.empty:
        common.fail(f"--filter: no rows with filter '{filter_name}'")
    radius = common.most_common(fd["radius"])
    recon = common.most_common(fd["reconstruction"])
    params = common.most_common(fd["filter_params"])
    fd = fd[(fd["radius"] == radius) & (fd["reconstruction"] == recon) & (fd["filter_params"] == params)]
    for scene, sd in fd.groupby("scene", sort=True):
        fig, axes = plt.subplots(1, 3, figsize=(16, 5))
        for ax, metric in zip(axes, ["mse", "aliasing", "noise"]):
            for i, (sampler, g) in enumerate(sd.groupby("sampler", sort=True)):
                g = g.sort_values("spp")
                pos = g[g[metric] > 0]
                label = sampler
                try:
                    slope = common.fit_loglog_slope(g["spp"], g[metric])[0]
                    label += f" (slope {slope:+.2f})"
                except ValueError:
                    label += " (no fit)"
                ax.plot(pos["spp"], pos[metric], marker=MARKERS[i % len(MARKERS)], color=common.colour(i),
                        label=label)
            ax.set_xscale("log", base=2)
            ax.set_yscale("log")
            ax.set_xlabel("samples per pixel")
            ax.set_ylabel(f"{metric} (per pixel and channel)")
            ax.set_title(metric)
            ax.grid(True, which="major", alpha=0.3)
            ax.legend(fontsize=7)
        fig.suptitle(f"Convergence: {scene}, filter {filter_name} r={radius:g} {params}, {recon} "
                     "(slopes: least squares on log-log over all spp; values <= 0 not drawn)")
        common.save_figure(fig, out_dir, f"convergence_{common.slug(scene)}")


def heatmaps(df, out_dir):
    """(c) mse over filter x radius per sampler, at the most common spp and reconstruction."""
    for scene, sd in df.groupby("scene", sort=True):
        spp = common.most_common(sd["spp"])
        recon = common.most_common(sd["reconstruction"])
        sd = sd[(sd["spp"] == spp) & (sd["reconstruction"] == recon)]
        samplers = sorted(sd["sampler"].unique())
        cols = min(4, len(samplers))
        rows = (len(samplers) + cols - 1) // cols
        pos = sd["mse"][sd["mse"] > 0]
        vmin, vmax = (np.log10(pos.min()), np.log10(pos.max())) if len(pos) else (-6, 0)
        fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows), squeeze=False)
        for ax in axes.flat[len(samplers):]:
            ax.axis("off")
        for ax, sampler in zip(axes.flat, samplers):
            table = sd[sd["sampler"] == sampler].pivot_table(index="filter", columns="radius", values="mse",
                                                              aggfunc="mean")
            data = np.log10(table.where(table > 0).to_numpy(dtype=float))
            im = ax.imshow(data, cmap="viridis", vmin=vmin, vmax=vmax, aspect="auto")
            ax.set_xticks(range(len(table.columns)), [f"{r:g}" for r in table.columns], fontsize=7)
            ax.set_yticks(range(len(table.index)), table.index, fontsize=7)
            ax.set_xlabel("radius (pixels)")
            ax.set_title(sampler, fontsize=9)
            for (i, j), v in np.ndenumerate(table.to_numpy(dtype=float)):
                if np.isfinite(v):
                    ax.text(j, i, f"{v:.1e}", ha="center", va="center", fontsize=5, color="w")
        fig.colorbar(im, ax=axes, label="log10 mse (per pixel and channel)", shrink=0.8)
        fig.suptitle(f"mse over filter x radius: {scene}, spp={int(spp)}, {recon}")
        common.save_figure(fig, out_dir, f"heatmap_{common.slug(scene)}")


def stability(df, out_dir):
    """(d) pixel failure counts per method (all scenes and spp summed) and flagged rows."""
    df = df.assign(method=df["filter"] + " r=" + df["radius"].map("{:g}".format) + " " + df["reconstruction"])
    panels = [("undefined_pixels", "undefined pixels (|sum of weights| < tol)"),
              ("negative_pixels", "negative pixels"), ("nan_pixels", "NaN / inf pixels"),
              ("flagged", "flagged rows (reference not converged)")]
    methods = sorted(df["method"].unique())
    samplers = sorted(df["sampler"].unique())
    fig, axes = plt.subplots(1, 4, figsize=(4 + 1.1 * 4 * max(3, len(samplers)) / 2, 2 + 0.28 * len(methods)),
                             sharey=True)
    for ax, (col, title) in zip(axes, panels):
        table = df.pivot_table(index="method", columns="sampler", values=col, aggfunc="sum").reindex(
            index=methods, columns=samplers).fillna(0)
        data = table.to_numpy(dtype=float)
        im = ax.imshow(np.log10(1 + data), cmap="magma_r", aspect="auto", vmin=0)
        ax.set_xticks(range(len(samplers)), samplers, rotation=60, ha="right", fontsize=7)
        ax.set_yticks(range(len(methods)), methods, fontsize=7)
        ax.set_title(title, fontsize=9)
        for (i, j), v in np.ndenumerate(data):
            if v > 0:
                ax.text(j, i, f"{int(v)}", ha="center", va="center", fontsize=5, color="tab:blue")
        fig.colorbar(im, ax=ax, label="log10(1 + count)", shrink=0.6)
    fig.suptitle("Stability: counts summed over scenes and spp (filter r reconstruction x sampler)")
    common.save_figure(fig, out_dir, "stability")
    flagged = df[df["flagged"] == 1][common.CONFIG_KEY + ["mse", "noise"]]
    flagged.to_csv(os.path.join(out_dir, "flagged.csv"), index=False)


def main(argv=None):
    ap = argparse.ArgumentParser(description="Charts of an aliaslab sweep CSV")
    ap.add_argument("csv", help="study CSV")
    ap.add_argument("--out", required=True, help="output folder")
    ap.add_argument("--filter", default=None, help="filter of the convergence chart (default: most common)")
    args = ap.parse_args(argv)
    try:
        raw = common.read_study_csv(args.csv)
    except common.InputError as e:
        common.fail(str(e))
    if args.filter is not None and not (raw["filter"] == args.filter).any():
        common.fail(f"--filter: no rows with filter '{args.filter}'")
    df = aggregate(raw)
    common.prepare_out(args.out)
    speed_accuracy(df, args.out)
    convergence(df, args.out, args.filter)
    heatmaps(df, args.out)
    stability(df, args.out)
    print(f"charts written to {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
