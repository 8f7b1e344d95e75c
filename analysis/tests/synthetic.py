"""A small sweep CSV with known structure, for the analysis tests.

Every metric follows a stated law, so tests can check the charts and the
comparison against the law, not against what the scripts printed:
  noise    = n0(sampler) * spp^-1            (seed-to-seed error)
  aliasing = a0(filter) * radius * spp^-0.5  (structured error)
  mse      = aliasing + noise
  trace_ms = 2 * spp, reconstruct_ms = 10 * radius
Filter 'lanczos' with radius 1 has 5 negative pixels, radius 0.5 of 'box'
with sampler 'uniform' 3 undefined pixels; scene 'b' rows of 'random' at
spp 1 are flagged.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import common  # noqa: E402

SAMPLERS = {"random": 0.02, "jittered": 0.01, "uniform": 0.0}
FILTERS = {"box": 0.004, "lanczos": 0.002}
RADII = [0.5, 1.0]
SPPS = [1, 4, 16, 64]
SCENES = ["a", "b.scene"]
SEEDS = 8


def rows(scale=1.0):
    """Yields dicts of the study CSV; `scale` multiplies mse and aliasing."""
    for scene in SCENES:
        for sampler, n0 in SAMPLERS.items():
            for filt, a0 in FILTERS.items():
                for radius in RADII:
                    for spp in SPPS:
                        noise = n0 / spp
                        aliasing = a0 * radius * spp ** -0.5 * scale
                        mse = aliasing + noise
                        yield {
                            "scene": scene, "width": 32, "height": 24, "sampler": sampler, "spp": spp,
                            "filter": filt, "radius": radius,
                            "filter_params": "" if filt == "box" else "tau=3",
                            "reconstruction": "weighted", "seeds": SEEDS, "mse": mse, "aliasing": aliasing,
                            "noise": noise, "mse_area": mse * 1.5, "psnr": -10 * __import__("math").log10(mse),
                            "ref_spp": 4096, "ref_error": 1e-7,
                            "flagged": int(scene == "b.scene" and sampler == "random" and spp == 1),
                            "nan_pixels": 0, "negative_pixels": 5 if (filt == "lanczos" and radius == 1.0) else 0,
                            "undefined_pixels": 3 if (filt == "box" and radius == 0.5 and sampler == "uniform") else 0,
                            "trace_ms": 2.0 * spp, "reconstruct_ms": 10.0 * radius, "threads": 2,
                        }


def write(path, scale=1.0, modify=None):
    """Writes the CSV; `modify(row)` may change a row in place."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=common.STUDY_COLUMNS)
        w.writeheader()
        for r in rows(scale):
            if modify:
                modify(r)
            w.writerow(r)
    return path
