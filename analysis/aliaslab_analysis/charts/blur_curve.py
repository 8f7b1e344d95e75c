"""blur_curve: the eye's low-pass as a curve. Per scene, the share of each sampler's error (against the row's
target) left after a Gaussian blur of sigma 0.5, 1, 2 and 4 pixels (CSV columns blur_ratio_S, blur_ratio_S_se,
lib/measure/spectrum.h), at every sampler's highest spp, with +-2 standard errors, beside white noise's expected
curve (docs/science.md, "The blur curve"): for independent pixel errors of equal variance, the blur by the
normalised kernel w leaves the share sum w^2, which for the blur the study applies (the transfer function
exp(-2 pi^2 sigma^2 rho^2) on the W x H DFT grid) is the mean over that grid of exp(-4 pi^2 sigma^2 rho^2).
Below the white curve a sampler's error sits at high screen frequencies (blue), above it at low ones.

Flagged rows (error not told from zero) are drawn dotted and hollow, marked "(flagged)" in the legend.

blur_curve(df, out_dir) draws blur_curve_<scene> (.png; .svg too after figures.write_svg) and returns the paths; a CSV without the columns
(older sweeps) draws nothing and returns [].
"""
import numpy as np
import pandas as pd

from . import figures, palette
from .figures import plt

SIGMAS = (0.5, 1.0, 2.0, 4.0)


def column(sigma):
    return f"blur_ratio_{sigma:g}"


def white_share(sigma, width, height):
    """sum w^2 of the study's Gaussian blur of `sigma` px on a width x height image: the mean over the DFT
    frequencies (u/W, v/H), wrapped to [-1/2, 1/2), of exp(-4 pi^2 sigma^2 rho^2) (Parseval)."""
    fu = np.fft.fftfreq(int(width))
    fv = np.fft.fftfreq(int(height))
    rho2 = fu[None, :] ** 2 + fv[:, None] ** 2
    return float(np.mean(np.exp(-4 * np.pi ** 2 * sigma ** 2 * rho2)))


def blur_curve(df, out_dir):
    cols = [column(s) for s in SIGMAS] + [column(s) + "_se" for s in SIGMAS]
    if any(c not in df.columns for c in cols):
        return []
    df = df.copy()
    for c in cols:
        df[c] = pd.to_numeric(df[c], errors="coerce")
    paths = []
    for scene, rows in df.groupby("scene"):
        # one curve per sampler: its highest spp; among its rows (filters) the one of lowest error
        err = "error" if "error" in rows.columns else "mse_target"
        picks = []
        for sampler, r in rows.groupby("sampler"):
            r = r[r["spp"] == r["spp"].max()]
            picks.append(r.sort_values(err).iloc[0])
        fig, ax = plt.subplots(figsize=(6.4, 4.2), layout="constrained")
        w, h = int(rows["width"].iloc[0]), int(rows["height"].iloc[0])
        ax.plot(SIGMAS, [white_share(s, w, h) for s in SIGMAS], color="black", lw=2.2, ls="--",
                label=f"white noise: sum w^2 ({w} x {h})", zorder=3)
        for k, row in enumerate(picks):
            y = np.array([row[column(s)] for s in SIGMAS], dtype=float)
            e = np.array([row[column(s) + "_se"] for s in SIGMAS], dtype=float)
            flagged = int(row.get("flagged", 0) or 0) == 1  # error not told from zero: drawn, marked, hollow
            ax.errorbar(SIGMAS, y, yerr=2 * e, marker="o", ms=4, color=palette.sampler_colour(row["sampler"]), capsize=2, lw=1.2, ls=":" if flagged else "-",
                        mfc="none" if flagged else None,
                        label=f"{row['sampler']} ({int(row['spp'])} spp, {row.get('filter_name', row.get('filter'))} "
                              f"r={row['radius']:g}){' (flagged)' if flagged else ''}")
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xticks(SIGMAS, [f"{s:g}" for s in SIGMAS])
        ax.set_xlabel("Gaussian blur sigma (pixels)")
        ax.set_ylabel("error left after the blur / error before (lower: bluer error)")
        ax.set_title(f"{scene}: the blur curve (below white: blue error)", fontsize=10)
        ax.legend(fontsize=7, loc="lower left")
        ax.grid(True, which="both", alpha=0.3)
        paths += figures.save_figure(fig, out_dir, f"blur_curve_{scene}")
    return paths
