"""Renders the viewer's images with the project's own raytracer: one EXR per (configuration, seed), the same
sampler, seed, filter and tracing flags as the sweep's seed k (makeSampleSource(sampler, spp, k) in both), so
the images are the ones the study measured; export.py checks each against the CSV's per-seed mse_target.
Images already in the work folder are kept (a rerun renders only what is missing)."""
import os
import shlex
import subprocess
from concurrent.futures import ThreadPoolExecutor

from ..io import errors
from .plan import image_stem


def tracing_flags(manifest):
    """The scene's tracing flags as recorded by the sweep in its reference manifest (e.g. -bounces 0 -weight 0)."""
    return shlex.split(manifest.get("tracing", ""))


def command(raytracer, scene_path, size, manifest, c, seed, out):
    cmd = [raytracer, "--input", scene_path, "--size", str(size[0]), str(size[1]), "--sampler", c["sampler"],
           "--spp", str(c["spp"]), "--filter", c["filter"], "--radius", f"{c['radius']:g}", "--seed", str(seed),
           "--threads", "1", "--output", out] + tracing_flags(manifest)
    # `--filter gaussian` is the library's gaussian (sigma = r / 3), the sweep's: no width rule is repeated here
    return cmd


def render_all(raytracer, jobs_list, jobs=2, quiet=False):
    """jobs_list: (command, output path) pairs; runs the missing ones on `jobs` processes."""
    todo = [(cmd, out) for cmd, out in jobs_list if not os.path.isfile(out)]
    todo.sort(key=lambda j: (not j[1].endswith("-seed0.exr"),))  # every seed 0 first: the flip-book seeds after

    def one(item):
        cmd, out = item
        os.makedirs(os.path.dirname(out), exist_ok=True)
        tmp = out[:-4] + ".partial.exr"
        run = subprocess.run([tmp if a == out else a for a in cmd], capture_output=True, text=True)
        if run.returncode != 0 or not os.path.isfile(tmp):
            return f"{' '.join(cmd)}: {run.stderr.strip()[:400]}"
        os.replace(tmp, out)
        return None
    failures = []
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        for i, err in enumerate(pool.map(one, todo)):
            if err:
                failures.append(err)
            if not quiet and (i + 1) % 50 == 0:
                print(f"  rendered {i + 1}/{len(todo)}", flush=True)
    if failures:
        errors.fail(f"{len(failures)} render(s) failed, first: {failures[0]}")
    return len(todo)


def scene_jobs(raytracer, scene_path, size, manifest, configs, work):
    out = []
    for c in configs:
        for seed in c["seeds"]:
            path = os.path.join(work, image_stem(c, seed) + ".exr")
            out.append((command(raytracer, scene_path, size, manifest, c, seed, path), path))
    return out
