"""Error spectra of the study: reading <csv folder>/spectra/*.csv and drawing them.

The sweep writes, per scene, the radially averaged power spectrum of every configuration's error
(I_k - G) and noise (I_k - m), averaged over seeds (lib/measure/spectrum.h, docs/spectrum.md). Frequencies
are in cycles per pixel (Nyquist = 0.5); `lowfreq_error` is the share of the error energy below
CUTOFF = a quarter of Nyquist. Everything here returns None / an empty frame when the files are absent
(older studies), so the report can say so instead of failing.
"""
import glob
import os

import numpy as np
import pandas as pd
from matplotlib import ticker

from . import figures, palette
from .figures import plt

CUTOFF = 0.125  # cycles per pixel: lib/measure/spectrum.h kLowFrequencyCutoff
NYQUIST = 0.5
# The spectrum key: the columns that name a configuration's spectra, as lib/study/records/spectrum_key.h spells them
# (the first columns of a spectrum line; tests/programs/sweep_test.cpp checks the two agree on a real sweep).
KEY = ["scene", "sampler", "spp", "filter", "radius", "reconstruction", "prefilter"]
# The columns a spectrum file must have (prefilter is absent from files older than the pre-filtering study).
COLUMNS = [c for c in KEY if c != "prefilter"] + ["kind", "bin", "frequency", "power", "energy"]
INDEPENDENT = ["random", "jittered", "stratified", "sobol", "halton"]  # preferred independent samplers


def is_correlated(sampler):
    """Samplers that correlate neighbouring pixels on purpose (docs/spectrum.md)."""
    s = str(sampler)
    return s == "zsobol" or s.startswith("bluenoise-dither")


def load(study_csv):
    """All spectrum rows beside the study CSV (spectra/<scene>[.<stem>].csv), or None when there are none.
    Shards' files are concatenated; repeated rows are dropped."""
    folder = os.path.join(os.path.dirname(os.path.abspath(study_csv)), "spectra")
    frames = []
    for path in sorted(glob.glob(os.path.join(folder, "*.csv"))):
        try:
            f = pd.read_csv(path, dtype={"sampler": str, "filter": str, "reconstruction": str, "kind": str})
        except (pd.errors.EmptyDataError, pd.errors.ParserError, UnicodeDecodeError):
            continue
        if set(COLUMNS) <= set(f.columns) and len(f):
            frames.append(f)
    if not frames:
        return None
    df = pd.concat(frames, ignore_index=True)
    if "prefilter" not in df.columns:
        df["prefilter"] = "none"
    df["prefilter"] = df["prefilter"].fillna("none").astype(str)
    df["scene"] = df["scene"].astype(str)
    return df.drop_duplicates(subset=KEY + ["kind", "bin"]).reset_index(drop=True)


def common_method(spec):
    """(filter, radius, reconstruction) shared by the most samplers (box 0.5 weighted preferred on a tie):
    spectra are compared across samplers with everything else equal."""
    g = spec[spec["prefilter"] == "none"]
    if not len(g):
        g = spec
    counts = g.groupby(["filter", "radius", "reconstruction"])["sampler"].nunique()
    best = counts.max()
    keys = [k for k, n in counts.items() if n == best]
    keys.sort(key=lambda k: (k[0] != "box", abs(float(k[1]) - 0.5), k[2] != "weighted", k))
    return keys[0]


def pick_samplers(samplers):
    """An independent and correlated samplers to compare: (independent or None, [correlated...])."""
    samplers = list(dict.fromkeys(str(s) for s in samplers))
    independent = [s for s in samplers if not is_correlated(s)]
    ind = next((s for s in INDEPENDENT if s in independent), independent[0] if independent else None)
    corr = [s for s in samplers if is_correlated(s)]
    corr.sort(key=lambda s: (s != "zsobol", s != f"bluenoise-dither:{ind}", s))
    return ind, corr


def curves(spec, scene, spp, kind="error"):
    """{sampler: (frequency, power)} at one spp for the scene's common method; empty when none."""
    s = spec[(spec["scene"] == str(scene)) & (spec["spp"] == int(spp)) & (spec["kind"] == kind)]
    s = s[s["prefilter"] == "none"] if (s["prefilter"] == "none").any() else s
    if not len(s):
        return {}
    filt, radius, recon = common_method(s)
    s = s[(s["filter"] == filt) & (s["radius"] == radius) & (s["reconstruction"] == recon)]
    out = {}
    for sampler, g in s.groupby("sampler", sort=True):
        g = g.sort_values("bin")
        out[str(sampler)] = (g["frequency"].to_numpy(dtype=float), g["power"].to_numpy(dtype=float))
    return out


def chart(spec, scene, spp, path, samplers=None, title=None):
    """Overlays the radially averaged error spectra of `samplers` (default: all) at `spp`; marks the
    quarter-Nyquist cutoff; legend outside the axes. Returns the path, or None when there is nothing to draw."""
    data = curves(spec, scene, spp)
    if samplers is not None:
        data = {k: v for k, v in data.items() if k in samplers}
    data = {k: (f, p) for k, (f, p) in data.items() if np.any(p > 0)}
    if not data:
        return None
    filt, radius, recon = common_method(spec[(spec["scene"] == str(scene)) & (spec["spp"] == int(spp))])
    fig, ax = plt.subplots(figsize=(7.2, 3.6))
    order = sorted(data, key=lambda s: (is_correlated(s), s))
    for sampler in order:
        f, p = data[sampler]
        keep = p > 0
        ax.plot(f[keep], p[keep], lw=1.6, ls="--" if is_correlated(sampler) else "-", color=palette.sampler_colour(sampler),
                label=sampler + (" (correlated)" if is_correlated(sampler) else ""))
    ax.axvline(CUTOFF, color="0.3", lw=1, ls=":")
    ax.text(CUTOFF, 1.01, " quarter Nyquist", transform=ax.get_xaxis_transform(), fontsize=8, color="0.3",
            va="bottom")
    ax.set_yscale("log")
    lo, hi = ax.get_ylim()
    if hi / lo < 30:  # less than ~1.5 decades: label the minor ticks too, or the axis has one number
        ax.yaxis.set_minor_locator(ticker.LogLocator(subs=(2.0, 5.0)))
        ax.yaxis.set_minor_formatter(ticker.LogFormatterSciNotation(labelOnlyBase=False,
                                                                   minor_thresholds=(3, 3)))
        ax.tick_params(axis="y", which="minor", labelsize=7)
    ax.set_xlim(0, max(float(np.max(f)) for f, _ in data.values()) * 1.02)
    ax.set_xlabel("frequency (cycles per pixel; Nyquist = 0.5 along an axis)")
    ax.set_ylabel("error power (radial mean)\nlower is better")
    ax.set_title(title or f"{scene}: error spectrum at {int(spp)} spp ({filt} r={float(radius):g}, {recon})",
                 fontsize=10, loc="left", pad=14)
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=110)
    figures.quantize_png(path)
    plt.close(fig)
    return path


def chart_path(charts_dir, scene, spp, tag="spectrum"):
    return os.path.join(charts_dir, f"{tag}_{figures.slug(scene)}_spp{int(spp)}.png")


def pick_spp(levels, wanted=16):
    """The spp level for the overview chart: `wanted` if present, else the closest."""
    levels = sorted(int(s) for s in levels)
    return min(levels, key=lambda s: (abs(np.log2(s) - np.log2(wanted)), s)) if levels else None
