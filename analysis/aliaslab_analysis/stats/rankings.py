"""What a method and a cell are, for every ranking (stats/equivalence.py, factors.py, fronts.py).

METHOD  the columns naming a method: sampler, filter, radius, shape parameters, reconstruction, pre-filter
         (method_label: how a chart or a finding names one)
CELL    the columns naming a cell whose rows are compared with each other: target, scene, spp
(Methods are compared by effect sizes with a margin of equivalence: stats/effect.py;
stats/ties.py keeps the standard error of a paired or independent difference, which other sections use.)
"""
METHOD = ["sampler", "filter_name", "radius", "filter_params", "reconstruction", "prefilter"]
CELL = ["target", "scene", "spp"]


def method_label(row, show_recon=False, sampler=True):
    label = f"{row['filter_name']} r={row['radius']:g}"
    if sampler:
        label = f"{row['sampler']} " + label
    if show_recon:
        label += f" {row['reconstruction']}"
    if row.get("prefilter", "none") not in ("none", ""):
        label += f" [{row['prefilter']}]"
    return label
