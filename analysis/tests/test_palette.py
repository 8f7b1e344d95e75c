"""One palette: every chart that colours samplers takes each sampler's colour from
palette.py, whatever samplers the study holds and in whatever order, and each filter's marker likewise.

Behavioural, not a grep: each chart module draws a small synthetic study with pyplot's close() intercepted, and
the colours of what it drew are read back from the figure: every coloured (non-grey) mark is the palette
colour of one of the study's samplers, each sampler's colour appears on the data, and a legend entry named
after a sampler has that sampler's colour. Drawn twice, with the samplers in two different subsets, so that
a colour given by position (the i-th colour of a list) would fail."""
import os
import tempfile
import unittest
from unittest import mock

import matplotlib.colors
import numpy as np
import pandas as pd

from . import synthetic
from ..aliaslab_analysis.charts import (convergence_experiment, filter_profiles, palette, pointsets, spectra)
from ..aliaslab_analysis.io import study_csv
from ..aliaslab_analysis.charts import speed
from ..aliaslab_analysis.charts.convergence import convergence as study_convergence
from ..aliaslab_analysis.charts.figures import plt
from ..aliaslab_analysis.findings import Study
from ..aliaslab_analysis.report import summary_chart


def hexes(colours):
    """'#rrggbb' of every colour given (RGBA arrays, names), those drawn at all (alpha > 0)."""
    out = []
    for c in np.atleast_2d(matplotlib.colors.to_rgba_array(colours)) if len(np.atleast_1d(colours)) else []:
        if c[3] > 0:
            out.append(matplotlib.colors.to_hex(c[:3]))
    return out


def neutral(h):
    r, g, b = matplotlib.colors.to_rgb(h)
    return abs(r - g) < 0.02 and abs(g - b) < 0.02  # black, greys, white


def drawn(fig):
    """(data colours, {legend label: colour}, data markers) of a figure."""
    data, legend, markers = [], {}, []
    for ax in fig.axes:
        for line in ax.lines:
            data += hexes([line.get_color(), line.get_markerfacecolor(), line.get_markeredgecolor()])
        for coll in ax.collections:
            data += hexes(coll.get_facecolors()) + hexes(coll.get_edgecolors())
        for leg in [ax.get_legend()] + list(fig.legends):
            if leg is None:
                continue
            handles = getattr(leg, "legend_handles", None) or leg.legendHandles
            for h, t in zip(handles, leg.get_texts()):
                colour = h.get_color() if hasattr(h, "get_color") else h.get_facecolor()
                c = hexes([colour[0] if isinstance(colour, np.ndarray) and colour.ndim == 2 else colour])
                if c:
                    legend[t.get_text()] = c[0]
    return data, legend, markers


class Capture:
    """Intercepts pyplot.close, keeping the figures the chart functions draw."""

    def __enter__(self):
        self.figs = []
        self.patch = mock.patch.object(plt, "close", side_effect=lambda fig=None: self.figs.append(fig) if hasattr(fig, "axes") else None)
        self.patch.start()
        return self

    def __exit__(self, *exc):
        self.patch.stop()
        for f in self.figs:
            plt.close(f)


class OnePalette(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def check(self, figs, samplers, name):
        self.assertTrue(figs, name)
        want = {s: palette.sampler_colour(s).lower() for s in samplers}
        for fig in figs:
            data, legend, _ = drawn(fig)
            coloured = {c for c in data if not neutral(c)}
            self.assertLessEqual(coloured, set(want.values()), f"{name}: a colour outside the palette")
            for s, c in want.items():
                self.assertIn(c, data, f"{name}: {s} not drawn in its palette colour {c}")
            for label, c in legend.items():
                first = label.split(" ")[0]
                if first in want:
                    self.assertEqual(c, want[first], f"{name}: legend entry {label!r}")

    def study(self, samplers):
        path = os.path.join(self.tmp.name, "-".join(samplers) + ".csv")
        synthetic.write(path, scenes=["a"], modify=None)
        df, notes = study_csv.load_study(path)
        return df[df["sampler"].isin(samplers)].reset_index(drop=True), notes

    def test_study_charts_take_sampler_colours_from_the_palette(self):
        for samplers in (["random", "jittered", "uniform"], ["uniform", "jittered"]):
            df, notes = self.study(samplers)
            out = os.path.join(self.tmp.name, "charts")
            for name, draw in (("speed_accuracy", lambda: speed.speed_accuracy(df, out)),
                               ("convergence", lambda: study_convergence(df, out, None)),
                               ("summary_chart", lambda: summary_chart.summary_chart(Study(df, notes), out))):
                with Capture() as cap:
                    draw()
                self.check(cap.figs, samplers, f"{name} {samplers}")

    def test_spectra_pointsets_and_integrand_charts_take_the_palette(self):
        for samplers in (["random", "jittered", "uniform", "zsobol"], ["zsobol", "uniform"]):
            synthetic.write_spectra(self.tmp.name, samplers, scenes=["a"])
            spec = spectra.load(os.path.join(self.tmp.name, "study.csv"))
            with Capture() as cap:
                spectra.chart(spec, "a", 4, os.path.join(self.tmp.name, "s.png"))
            self.check(cap.figs, samplers, f"spectra {samplers}")
            n = [16, 64]
            sp = pd.DataFrame([dict(sampler=s, n=k, sets=4, k_norm=x, power=1 + x) for s in samplers for k in n
                               for x in (0.5, 1.0, 2.0)])
            ps = pd.DataFrame([dict(sampler=s, n=k, l2star_mean=1 / k, l2star_sd=0.1 / k, min_dist_norm_mean=0.5)
                               for s in samplers for k in n])
            conv = pd.DataFrame([dict(sampler=s, integrand="disk", n=k, rmse=1 / k, realisations=8)
                                 for s in samplers for k in (16, 32, 64)])
            for name, draw in (("pointsets spectra", lambda: pointsets.spectra_chart(sp, self.tmp.name)),
                               ("discrepancy", lambda: pointsets.discrepancy_chart(ps, self.tmp.name)),
                               ("integrands", lambda: convergence_experiment.chart(conv, self.tmp.name, 16, 64))):
                with Capture() as cap:
                    draw()
                self.check(cap.figs, samplers, f"{name} {samplers}")

    def test_filters_take_their_marker_and_colour(self):
        df = pd.DataFrame([dict(filter=f, radius=1.0, describe=f, kind=k, x=x, value=1 - x / 4)
                           for f in ("lanczos", "box") for k in ("profile", "response") for x in np.linspace(0, 2, 11)])
        with Capture() as cap:
            filter_profiles.chart(df, self.tmp.name)
        lines = [l for ax in cap.figs[0].axes for l in ax.lines if l.get_label() in ("lanczos", "box")]
        self.assertEqual(len(lines), 4)
        for line in lines:
            self.assertEqual(line.get_marker(), palette.filter_marker(line.get_label()))
            self.assertEqual(matplotlib.colors.to_hex(line.get_color()), palette.filter_colour(line.get_label()).lower())
        df, _ = self.study(["jittered"])
        with Capture() as cap:
            speed.speed_accuracy(df, os.path.join(self.tmp.name, "c"))
        used = {p.get_label(): p for ax in cap.figs[0].axes for p in ax.collections}
        markers = [h for ax in cap.figs[0].axes for h in ax.get_legend().legendHandles
                   if hasattr(h, "get_marker")]
        by_label = {h.get_label(): h.get_marker() for h in markers}
        for f in ("box", "lanczos"):
            self.assertEqual(by_label[f], palette.filter_marker(f))
        self.assertTrue(used)

    def test_the_palette_itself(self):
        colours = list(palette.SAMPLER_COLOURS.values())
        self.assertEqual(len(colours), len(set(c.lower() for c in colours)), "two samplers share a colour")
        self.assertFalse(any(neutral(c) for c in colours), "a sampler is grey, black or white")
        self.assertEqual(palette.sampler_colour("adaptive-contrast:jittered"), palette.sampler_colour("jittered"))
        self.assertEqual(palette.sampler_colour("newsampler"), palette.sampler_colour("newsampler"))
        self.assertIn("--sampler-uniform:" + palette.SAMPLER_COLOURS["uniform"], palette.css_variables())


if __name__ == "__main__":
    unittest.main()
