"""Charts of a sweep CSV (read with study_csv.load_study; definitions in docs/science.md).

Usage: /usr/bin/python3 -m analysis charts study.csv --out DIR [--filter NAME] [--svg]

Every ranking and every "error" axis is the error against the study's common
target (column mse_target; a CSV with several targets is drawn for one, the
caller's choice: the report passes the primary target's rows; for CSVs of older sweeps without it, mse_area, the
error against the pixel-area reference, and the charts say so). A filter's own
mse is not used for ranking: it ignores blur, so the widest filter would win.

Writes into DIR, each as .png (and .svg with --svg):
  speed_accuracy_<scene>  error against the target vs time per image (cpu_ms,
                          else wall time), log-log; colour = sampler, marker =
                          filter, pre-filtered rows (when the CSV has a
                          prefilter column) ringed in black; flagged rows
                          hollow and kept; the fixed grid (deterministic) as
                          crosses; the front (stats/fronts.py: no point beaten in both)
                          numbered, its methods listed beside the chart;
                          error bars +-2 standard errors (mse_target_se)
  decomposition_<scene>   per spp level: the error of the best methods (flagged
                          ones kept and marked) split
                          into noise, aliasing and blur as stacked bars, the
                          cross term as its own (signed) bar, the total with
                          +-2 se; negative terms drawn left of 0
  radius_<scene>          the radius trade-off: error, noise and blur against
                          radius, one panel per filter (one shared y range),
                          one colour per spp; degenerate points at the top
  convergence_<scene>     error, noise and aliasing against spp per sampler;
                          slopes only when >= 3 spp levels
  heatmap_<scene>         log10 error over sampler x filter x radius, one panel
                          per spp level; degenerate cells (degenerate.py)
                          hatched and out of the colour scale
  stability               undefined / negative / NaN pixel counts per method,
                          and flagged rows per method (empty panels say so)
  blur_curve_<scene>      the error left after a Gaussian blur of sigma 0.5-4 px
                          per sampler, beside white noise's curve (CSVs with
                          the blur_ratio columns)
and the tables pareto.csv (the front of every scene), flagged.csv and
decomposition.csv.gz. A CSV repeating a configuration is refused (exit 2).

Colours and markers: palette.py; matplotlib (Agg) and saving: figures.py. One module per chart family (axes.py:
what they share); draw_all draws them all, cli.py is the command. Beside the study's charts, the charts of
the other programs and records: convergence_experiment.py (`convergence`), pointsets.py (`pointsets`),
filter_profiles.py (`filters`), spectra.py (the error spectra beside a study CSV, for the report),
motion_loop.py (the animated loop of a motion study's frames).
"""
from ..io import errors
from .blur_curve import blur_curve
from .convergence import convergence
from .decomposition import decomposition
from .heatmap import heatmaps
from .radius import radius_tradeoff
from .speed import speed_accuracy
from .stability import stability


def draw_all(df, out_dir, filter_name=None):
    """Every chart and table of a study loaded with study_csv.load_study."""
    errors.prepare_out(out_dir)
    speed_accuracy(df, out_dir)
    decomposition(df, out_dir)
    radius_tradeoff(df, out_dir)
    convergence(df, out_dir, filter_name)
    heatmaps(df, out_dir)
    stability(df, out_dir)
    blur_curve(df, out_dir)  # draws nothing for a CSV without the blur_ratio columns
