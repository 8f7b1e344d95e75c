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

With the newer columns (coord/COLUMNS.md; write(..., new_columns=True), the
default), against the common target box:0.5 (the pixel area):
  blur       = b0(filter) * radius^2          (the filter's own deviation)
  cross      = +0.1 sqrt(aliasing blur) for box, -0.1 sqrt(aliasing blur) for lanczos
  mse_target = noise + aliasing + blur + cross (exactly)
  mse_se = mse_target_se = aliasing_se = noise sqrt(2 / K), noise_se = noise sqrt(2 / (K - 1))
  flip = sqrt(mse_target), lowfreq_error = aliasing / 2, blurred_mse = mse / 4
With prefilter=True every configuration also comes pre-filtered ('footprint'):
aliasing / 10 and trace_ms * 1.5.
"""
import contextlib
import csv
import io
import math
import os

from ..aliaslab_analysis.charts import figures
from ..aliaslab_analysis.io import study_csv
from ..aliaslab_analysis.report import cli as report_cli

SAMPLERS = {"random": 0.02, "jittered": 0.01, "uniform": 0.0}
FILTERS = {"box": 0.004, "lanczos": 0.002}
RADII = [0.5, 1.0]
SPPS = [1, 4, 16, 64]
SCENES = ["a", "b.scene"]
SEEDS = 8


BLUR = {"box": 0.003, "lanczos": 0.0005}
NEW_COLUMNS = ["target", "mse_target", "blur", "cross", "mse_se", "noise_se", "aliasing_se", "mse_target_se",
               "flip", "lowfreq_error", "lowfreq_error_se", "blurred_mse"]


def add_new_columns(r):
    """Adds the newer columns to an old-style row dict, following the laws above."""
    noise, aliasing, radius = r["noise"], r["aliasing"], r["radius"]
    blur = BLUR[r["filter"]] * radius ** 2
    cross = (0.1 if r["filter"] == "box" else -0.1) * math.sqrt(max(aliasing, 0.0) * blur)
    se = noise * math.sqrt(2 / SEEDS)
    r.update(target="box:0.5", blur=blur, cross=cross, mse_target=noise + aliasing + blur + cross,
             mse_se=se, noise_se=noise * math.sqrt(2 / (SEEDS - 1)), aliasing_se=se, mse_target_se=se,
             flip=math.sqrt(noise + aliasing + blur + cross), lowfreq_error=aliasing / 2,
             lowfreq_error_se=se / 2, blurred_mse=r["mse"] / 4)


def rows(scale=1.0, new_columns=False, prefilter=False, scenes=None):
    """Yields dicts of the study CSV; `scale` multiplies mse and aliasing."""
    for r in old_rows(scale, scenes):
        variants = [("none", r)]
        if prefilter:
            p = dict(r)
            p["aliasing"] /= 10
            p["mse"] = p["aliasing"] + p["noise"]
            p["mse_area"] = p["mse"] * 1.5
            p["trace_ms"] *= 1.5
            variants.append(("footprint", p))
        for name, v in variants:
            if new_columns:
                add_new_columns(v)
            if prefilter:
                v["prefilter"] = name
            yield v


def old_rows(scale=1.0, scenes=None):
    """The rows with the original columns only (study_csv.STUDY_COLUMNS)."""
    for scene in scenes or SCENES:
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


def write(path, scale=1.0, modify=None, new_columns=True, prefilter=False, scenes=None):
    """Writes the CSV; `modify(row)` may change a row in place. new_columns=False writes an older CSV
    (without the columns of coord/COLUMNS.md); prefilter=True adds the `prefilter` column and a
    pre-filtered copy of every configuration; `scenes` replaces SCENES (e.g. ["a"] for a smaller CSV)."""
    fields = list(study_csv.STUDY_COLUMNS) + (NEW_COLUMNS if new_columns else []) + (["prefilter"] if prefilter else [])
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for r in rows(scale, new_columns, prefilter, scenes):
            if modify:
                modify(r)
            w.writerow(r)
    return path


def tiny_png(path, value=0.5):
    """A 6 x 4 grey PNG (stands in for a sweep image)."""
    import numpy as np
    from ..aliaslab_analysis.charts.figures import plt
    os.makedirs(os.path.dirname(path), exist_ok=True)
    plt.imsave(path, np.full((4, 6), value), cmap="gray", vmin=0, vmax=1)
    return path


SPECTRUM_BINS = 16
SPECTRUM_BIN_WIDTH = 0.5 * 2 ** 0.5 / SPECTRUM_BINS  # up to the frequency square's corner


def spectrum_power(sampler, spp, frequency):
    """Synthetic radially averaged error power: flat (white) for independent samplers, rising with
    frequency (blue) for the correlated `zsobol`."""
    base = SAMPLERS.get(sampler, 0.02) / spp + 1e-4
    return base * (8 * frequency ** 2 if sampler == "zsobol" else 1.0)


def add_correlated(csv_path):
    """Appends a copy of every `random` row as `zsobol` (a correlated sampler) to the CSV."""
    with open(csv_path, newline="") as f:
        reader = csv.DictReader(f)
        fields, table = reader.fieldnames, list(reader)
    extra = []
    for r in table:
        if r["sampler"] == "random":
            z = dict(r, sampler="zsobol", flagged="0")
            if "lowfreq_error" in z and z["lowfreq_error"] != "":
                z["lowfreq_error"] = str(float(z["lowfreq_error"]) / 5)
                z["blurred_mse"] = str(float(z["blurred_mse"]) / 3)
            extra.append(z)
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(table + extra)


def write_spectra(study_dir, samplers, scenes=None):
    """spectra/<scene>.csv as the sweep writes them (lib/measure/spectrum.h): every sampler x spp x filter x
    radius, kinds error and noise, SPECTRUM_BINS bins."""
    folder = os.path.join(study_dir, "spectra")
    os.makedirs(folder, exist_ok=True)
    fields = ["scene", "sampler", "spp", "filter", "radius", "reconstruction", "prefilter", "kind", "bin",
              "frequency", "power", "energy"]
    for scene in scenes or SCENES:
        name = os.path.splitext(os.path.basename(scene))[0]
        with open(os.path.join(folder, name + ".csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=fields)
            w.writeheader()
            for sampler in samplers:
                for spp in SPPS:
                    for filt in FILTERS:
                        for radius in RADII:
                            for kind in ("error", "noise"):
                                for b in range(SPECTRUM_BINS):
                                    fr = (b + 0.5) * SPECTRUM_BIN_WIDTH
                                    pw = spectrum_power(sampler, spp, fr)
                                    w.writerow(dict(scene=scene, sampler=sampler, spp=spp, filter=filt,
                                                    radius=radius, reconstruction="weighted", prefilter="none",
                                                    kind=kind, bin=b, frequency=fr, power=pw,
                                                    energy=pw * (b + 1)))


def make_results(folder, new_columns=True, prefilter=False, shards=True, engineering=True, spectra=False):
    """A results folder as the sweep and the experiments leave it: study/study.csv (the merged CSV),
    two shard CSVs beside it holding the same rows (when `shards`), study/images with a contact sheet
    per scene and the seed-0 image and error image of every configuration at the highest spp, and
    (when `engineering`) a benchmark and a fuzzing record. With `spectra`, the study also holds a
    correlated sampler `zsobol` (a copy of `random`'s rows), spectra/<scene>.csv for every sampler and the
    images of random and zsobol at 4 and 16 spp. Returns the study CSV's path."""
    study = os.path.join(folder, "study")
    os.makedirs(study, exist_ok=True)
    csv_path = write(os.path.join(study, "study.csv"), new_columns=new_columns, prefilter=prefilter)
    if spectra:
        add_correlated(csv_path)
        write_spectra(study, list(SAMPLERS) + ["zsobol"])
    if shards:
        with open(csv_path) as f:
            lines = f.read().splitlines()
        half = (len(lines) - 1) // 2
        for i, part in enumerate((lines[1:1 + half], lines[1 + half:])):
            with open(os.path.join(study, f"study.shard-{i}-of-2.csv"), "w") as f:
                f.write("\n".join([lines[0]] + part) + "\n")
    images = os.path.join(study, "images")
    for scene in SCENES:
        stem = figures.slug(scene)
        tiny_png(os.path.join(images, f"contact-{stem}.png"), 0.3)
        with open(os.path.join(images, f"contact-{stem}.txt"), "w") as f:
            f.write(f"contact sheet of {stem}: rows top to bottom\n")
        tiny_png(os.path.join(images, stem, "reference-area.png"), 0.6)
        for sampler in SAMPLERS:
            for filt in FILTERS:
                for radius in RADII:
                    base = f"{sampler}-spp{max(SPPS)}-{filt}-r{radius:g}-weighted"
                    tiny_png(os.path.join(images, stem, base + ".png"), 0.5)
                    tiny_png(os.path.join(images, stem, base + "-error.png"), 0.1)
        for sampler in (("random", "zsobol") if spectra else ()):
            for spp in (4, 16):
                base = f"{sampler}-spp{spp}-box-r0.5-weighted"
                tiny_png(os.path.join(images, stem, base + ".png"), 0.5)
                tiny_png(os.path.join(images, stem, base + "-error.png"), 0.2)
    if engineering:
        with open(os.path.join(folder, "study_speed.md"), "w") as f:
            f.write("# Study speed (measured)\n\nbefore the fused pass, after the fused pass.\n\n"
                    "| what | ms |\n|---|---:|\n| trace | 12.5 |\n")
        with open(os.path.join(folder, "fuzzing.md"), "w") as f:
            f.write("# Fuzzing\n\n| target | executions |\n|---|---:|\n| fuzz_scene | 1000 |\n")
    return csv_path


def run(main, args):
    """(exit status, stdout, stderr) of main(args); an uncaught exception fails the test as an error."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(args) or 0
        except SystemExit as e:
            code = e.code
    return code, out.getvalue(), err.getvalue()


def report_page(results, *args):
    """The page `report RESULTS ARGS` writes (RESULTS/index.html); the report must succeed."""
    code, _, err = run(report_cli.main, [results, *args])
    assert code == 0, err
    with open(os.path.join(results, "index.html"), encoding="utf-8") as f:
        return f.read()
