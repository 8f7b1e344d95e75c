"""What the study charts share: the method key and labels, the rows a log axis can show, the scene's best
row, and the drawing helpers (empty panels that say why, log-axis labels, numbered Pareto points that do
not overlap, outliers capped, +-2 se error bars that stay positive).
"""
import matplotlib.patheffects
import matplotlib.ticker
import numpy as np

from ..stats.rankings import METHOD, method_label  # noqa: F401 (the charts' method key and label)

ERROR_LABEL = {True: "error against the target (mse_target, per pixel and channel; lower is better)",
               False: "error against the pixel-area reference (mse_area, per pixel and channel; lower is better)"}
COMPONENT_COLOURS = {"noise": "#4c72b0", "aliasing": "#dd8452", "blur": "#55a868", "cross": "#8c8c8c",
                     "blur_cross": "#55a868"}
BEST_SHOWN = 10


def has_target(df):
    return "mse_target" in df.columns


def usable(df, column="error"):
    """Rows with a finite, positive value of `column` (what log axes can show)."""
    v = df[column].to_numpy(dtype=float)
    with np.errstate(invalid="ignore"):
        return df[np.isfinite(v) & (v > 0)]


def best_row(sd):
    """The scene's lowest-error unflagged row at its highest spp level (None if there is none)."""
    ok = sd[(sd["flagged"] == 0) & np.isfinite(sd["error"].to_numpy(dtype=float))]
    if ok.empty:
        return None
    top = ok[ok["spp"] == ok["spp"].max()]
    return top.loc[top["error"].idxmin()]


def empty_panel(ax, text):
    """Draws ax as an empty panel that says why it is empty."""
    ax.set_xticks([])
    ax.set_yticks([])
    ax.text(0.5, 0.5, text, ha="center", va="center", transform=ax.transAxes, fontsize=9, color="#555",
            wrap=True)


def label_log_axis(ax):
    """Labels minor ticks of a log y axis that spans less than about two decades (else one label)."""
    lo, hi = ax.get_ylim()
    if lo > 0 and hi / lo < 100:
        ax.yaxis.set_minor_formatter(matplotlib.ticker.LogFormatterSciNotation(labelOnlyBase=False,
                                                                               minor_thresholds=(2, 0.4)))
        ax.tick_params(axis="y", which="minor", labelsize=7)


def number_points(ax, xs, ys, fontsize=8, start=1):
    """Numbers the points (xs[k], ys[k]) 1, 2, ... on the axes without two numbers overlapping: each label
    takes the first free spot of a ring of offsets around its point (nearest first), further rings once the
    near ones are taken, with a thin leader line when it sits away from its point. Call it after the axes'
    limits are final (it works in display space)."""
    fig = ax.figure
    fig.canvas.draw()  # settles the layout so that data -> display is final
    to_points = 72.0 / fig.dpi
    placed = []  # centres (in points) of the labels placed so far
    w, h = 0.62 * fontsize, 1.0 * fontsize  # one digit's box, in points
    rings = [(dx * r, dy * r) for r in (1, 2, 3, 4, 5) for dx, dy in
             ((1, 1), (1, -1), (-1, 1), (-1, -1), (0, 1.4), (0, -1.4), (1.4, 0), (-1.4, 0))]
    for k, (x, y) in enumerate(zip(xs, ys), start):
        px, py = (v * to_points for v in ax.transData.transform((x, y)))
        text = str(k)
        tw = w * len(text)
        choice = None
        for dx, dy in rings:
            ox, oy = dx * (tw / 2 + 4), dy * (h / 2 + 3)
            cx, cy = px + ox, py + oy
            if all(abs(cx - qx) >= (tw + qw) / 2 + 1 or abs(cy - qy) >= h + 1 for qx, qy, qw in placed):
                choice = (ox, oy)
                break
        if choice is None:
            choice = (rings[-1][0] * (tw / 2 + 4), rings[-1][1] * (h / 2 + 3))
        ox, oy = choice
        far = abs(ox) > tw + 6 or abs(oy) > 1.5 * h + 4
        ax.annotate(text, (x, y), textcoords="offset points", xytext=(ox, oy), fontsize=fontsize, weight="bold",
                    ha="center", va="center", zorder=6,
                    path_effects=[matplotlib.patheffects.withStroke(linewidth=2.5, foreground="white")],
                    arrowprops=dict(arrowstyle="-", lw=0.5, color="0.4", shrinkA=0, shrinkB=2) if far else None)
        placed.append((px + ox, py + oy, tw))


def plain_log_x(ax):
    """Tick labels of a log x axis as plain numbers (0.5, 2, 300), major and minor."""
    fmt = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
    ax.xaxis.set_major_formatter(fmt)
    ax.xaxis.set_minor_formatter(matplotlib.ticker.FuncFormatter(
        lambda v, _: f"{v:g}" if f"{v:.0e}"[0] in "25" else ""))
    ax.tick_params(axis="x", which="minor", labelsize=7)


OUTLIER_FACTOR = 30.0


def clip_outliers(ax, x, y, colour="grey"):
    """Caps a log y axis at OUTLIER_FACTOR x the 75th percentile of y when the values span more than
    four decades; the points above are drawn at the cap as grey triangles. Returns a note ('' if none)."""
    y = np.asarray(y, dtype=float)
    x = np.asarray(x, dtype=float)
    if len(y) < 4 or y.max() / y.min() < 1e4:
        return ""
    cap = float(np.quantile(y, 0.75)) * OUTLIER_FACTOR
    above = y > cap
    if not above.any():
        return ""
    ax.set_ylim(top=cap * 1.6)
    ax.scatter(x[above], np.full(above.sum(), cap * 1.3), marker="^", color=colour, s=30, zorder=4,
               clip_on=False)
    return f"{int(above.sum())} point(s) above {cap:.2g} (up to {y.max():.2g}) drawn as grey triangles at the top"


def yerr_log(values, se):
    """Asymmetric +-2 se error bars that stay positive on a log axis (None when se is unknown)."""
    se = np.asarray(se, dtype=float)
    if not np.isfinite(se).any():
        return None
    v = np.asarray(values, dtype=float)
    se = np.where(np.isfinite(se), se, 0.0)
    lower = np.minimum(2 * se, v * 0.999)
    return np.vstack([lower, 2 * se])
