"""The one palette: each sampler's colour and each filter's marker (and line colour), defined here once and
used by every chart (charts/, report/summary_chart.py, spectra.py, pointsets.py, convergence_experiment.py,
filter_profiles.py) and by the page's script (as_json, css_variables).

The colours are the Okabe-Ito and Paul Tol "muted" sets, chosen to stay apart under the common forms of
colour blindness; families share a hue range so that a reader can group them even where two are close:
the grid (uniform, uniform-shifted) vermillion and orange, random indigo, the stratified patterns blues and
greens, the low-discrepancy sequences olive to purple, blue noise brown. No sampler is grey (grey is kept
for legends' neutral keys and for clipped points) or black (the front line and the pre-filtered ring).
A sampler built on another (adaptive-contrast:jittered, bluenoise-dither:sobol) takes its base's colour;
an unknown name takes one of EXTRA, the same one on every chart (chosen from the name, not its position).
"""
import json
import zlib

SAMPLER_COLOURS = {
    "uniform": "#D55E00",          # vermillion: the fixed grid
    "uniform-shifted": "#E69F00",  # orange: the grid shifted per seed
    "random": "#332288",           # indigo
    "jittered": "#0072B2",         # blue
    "nrooks": "#56B4E9",           # sky blue
    "multijittered": "#44AA99",    # teal
    "cmj": "#117733",              # green
    "halton": "#999933",           # olive
    "hammersley": "#DDCC77",       # sand
    "sobol": "#CC6677",            # rose
    "zsobol": "#882255",           # wine
    "pmj02": "#AA4499",            # purple
    "bluenoise": "#8C564B",        # brown
}
EXTRA = ["#6699CC", "#EE7733", "#009988", "#EE3377", "#33BBEE", "#997700"]

FILTER_MARKERS = {"box": "s", "tent": "^", "gaussian": "o", "mitchell": "D", "catmullrom": "v",
                  "lanczos": "P", "hann": "X", "blackmanharris": "*"}
EXTRA_MARKERS = ["<", ">", "h", "p", "d", "8"]
FILTER_COLOURS = {"box": "#0072B2", "tent": "#E69F00", "gaussian": "#009E73", "mitchell": "#D55E00",
                  "catmullrom": "#CC79A7", "lanczos": "#332288", "hann": "#999933", "blackmanharris": "#882255"}


def _pick(name, options):
    return options[zlib.crc32(str(name).encode("utf-8")) % len(options)]


def base_sampler(name):
    """The sampler a composite name is built on: 'adaptive-contrast:jittered' -> 'jittered'."""
    name = str(name)
    return name.rsplit(":", 1)[-1] if ":" in name else name


def sampler_colour(name):
    """The sampler's colour as '#RRGGBB' (its base's for a composite name; a fixed EXTRA one if unknown)."""
    return SAMPLER_COLOURS.get(str(name)) or SAMPLER_COLOURS.get(base_sampler(name)) or _pick(name, EXTRA)


def filter_marker(name):
    """The filter's matplotlib marker."""
    return FILTER_MARKERS.get(str(name)) or _pick(name, EXTRA_MARKERS)


def filter_colour(name):
    """The filter's colour, for charts whose series are filters (the filter profiles)."""
    return FILTER_COLOURS.get(str(name)) or _pick(name, EXTRA)


def as_json():
    """The palette for the page's script: {"samplers": {...}, "filters": {...}}."""
    return json.dumps({"samplers": SAMPLER_COLOURS, "filters": FILTER_COLOURS}, sort_keys=True)


def css_variables():
    """The sampler colours as CSS custom properties (--sampler-NAME) and classes (.sampler-NAME)."""
    props = "".join(f"--sampler-{k}:{v};" for k, v in SAMPLER_COLOURS.items())
    classes = "".join(f".sampler-{k}{{border-left:4px solid var(--sampler-{k})}}" for k in SAMPLER_COLOURS)
    return f":root{{{props}}}{classes}"
