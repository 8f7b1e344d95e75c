"""Matplotlib set up once (the Agg backend, no display needed), file-name-safe names
and the saving of a figure as PNG (and SVG when asked: the commands' --svg, add_svg_option). Import plt from
here, never matplotlib.pyplot directly (the backend must be chosen before pyplot is imported). Series colours
and markers: palette.py.
"""
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

def slug(text):
    """A file-name-safe version of a scene or method name."""
    base = os.path.splitext(os.path.basename(str(text)))[0]
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", base) or "unnamed"


def quantize_png(path):
    """Rewrites a chart's PNG with a 256-colour palette (no dithering): about a third of the bytes, and a chart
    has far fewer colours than that (the page loads these files). Left as is where Pillow (a dependency of
    Debian's matplotlib) is missing. Never for renders: their pixels are data."""
    try:
        from PIL import Image
    except ImportError:
        return path
    with Image.open(path) as im:
        small = im.convert("RGB").quantize(colors=256, dither=Image.Dither.NONE)
    small.save(path, "PNG", optimize=True)
    return path


FORMATS = ["png"]  # what save_figure writes: PNG (the pages show it), SVG too after write_svg(True)


def write_svg(on):
    """Whether save_figure also writes name.svg (off by default: the pages use the PNGs only, and SVGs are large)."""
    FORMATS[:] = ["png", "svg"] if on else ["png"]


def add_svg_option(ap):
    """The --svg option of a command that draws charts; call write_svg(args.svg) after parsing."""
    ap.add_argument("--svg", action="store_true", help="also write each chart as SVG (default: PNG only)")


def save_figure(fig, out_dir, name):
    """Writes name.png (palette-coded: quantize_png) into out_dir, and name.svg after write_svg(True); returns
    the paths written."""
    os.makedirs(out_dir, exist_ok=True)
    paths = []
    for ext in FORMATS:
        path = os.path.join(out_dir, f"{name}.{ext}")
        fig.savefig(path, dpi=120, bbox_inches="tight")
        paths.append(quantize_png(path) if ext == "png" else path)
    plt.close(fig)
    return paths
