"""The negative control and the grid against jittered, every number from a CSV:

  control(df)      on each scene negative_sppN at N spp (a grating of exactly sqrt(N) cycles per pixel, box r = 0.5):
                   random's noise against 1/(8N), each sampler's noise as a multiple of random's with its se, the
                   fixed grid's error against 1/4; from a study of scenes/controls/negative_spp*.txt
                   (results/negative_control/study.csv)
  grid_vs_jittered(rows)  the study's own scenes at its lowest spp, box r = 0.5: the fixed grid (one alignment)
                   and the grid shifted by one offset per image (a randomised lattice, over seeds) as multiples of
                   jittered's error against the target
  html(...)        the teaching strand's paragraphs; markdown(df) the record results/negative_control.md

    python3 -m analysis.aliaslab_analysis.teaching.negative results/negative_control/study.csv \\
        > results/negative_control.md
"""
import math
import os
import re
import sys

import numpy as np

NAME = re.compile(r"^negative_spp(\d+)$")
SIZE = 64  # the size the control scenes are made for (their `# render:` line): sqrt(N) cycles per pixel there
ORDER = ["random", "jittered", "uniform-shifted", "uniform", "nrooks", "multijittered", "cmj", "halton", "hammersley",
         "sobol", "pmj02", "bluenoise", "zsobol"]


def box_rows(df):
    f = df["filter_name"] if "filter_name" in df.columns else df["filter"]
    keep = ((f.astype(str) == "box") & np.isclose(df["radius"].to_numpy(dtype=float), 0.5)
            & (df["reconstruction"].astype(str) == "weighted") & (df["prefilter"].astype(str) == "none"))
    if "target" in df.columns:
        keep &= df["target"].astype(str) == "box:0.5"
    return df[keep]


def control(df):
    """{N: {"random": noise, "random_se", "expected": 1/(8N), "samplers": {name: (ratio, se)}, "uniform_error",
    "uniform_error_se", "uniform_noise"}} for every negative_sppN of the CSV at N spp and its own size."""
    out = {}
    rows = box_rows(df)
    for scene in sorted(set(rows["scene"])):
        m = NAME.match(str(scene))
        if not m:
            continue
        n = int(m.group(1))
        sd = rows[(rows["scene"] == scene) & (rows["spp"].astype(int) == n) & (rows["width"].astype(int) == SIZE)]
        rnd = sd[sd["sampler"] == "random"]
        if rnd.empty:
            continue
        b, sb = float(rnd["noise"].iloc[0]), float(rnd["noise_se"].iloc[0])
        entry = dict(random=b, random_se=sb, expected=1 / (8 * n), samplers={})
        for r in sd.itertuples():
            if r.sampler == "random":  # the yardstick itself: 1 exactly, no se of a ratio to itself
                entry["samplers"]["random"] = (1.0, 0.0)
                continue
            a, sa = float(r.noise), float(r.noise_se)
            ratio = a / b
            se = ratio * math.sqrt(((sa / a) if a > 0 else 0.0) ** 2 + (sb / b) ** 2)
            entry["samplers"][r.sampler] = (ratio, se)
            if r.sampler == "uniform":
                entry.update(uniform_error=float(r.mse_target), uniform_error_se=float(r.mse_target_se),
                             uniform_noise=a)
        out[n] = entry
    return out


def grid_vs_jittered(rows):
    """(spp, {scene: {"uniform": ratio, "uniform-shifted": ratio}}) at the lowest spp, box r = 0.5, against the
    rows' target: error as a multiple of jittered's."""
    rows = rows[rows["filter_name"].astype(str) == "box"]
    rows = rows[np.isclose(rows["radius"].to_numpy(dtype=float), 0.5)]
    spp = int(rows["spp"].min())
    out = {}
    for scene, sd in rows[rows["spp"].astype(int) == spp].groupby("scene"):
        j = sd[sd["sampler"] == "jittered"]
        if j.empty or not float(j["mse_target"].iloc[0]) > 0:
            continue
        e = float(j["mse_target"].iloc[0])
        out[str(scene)] = {s: float(sd[sd["sampler"] == s]["mse_target"].iloc[0]) / e
                           for s in ("uniform", "uniform-shifted") if (sd["sampler"] == s).any()}
    return spp, out


def span(values):
    return f"{min(values):.2f}" if len(values) == 1 else f"{min(values):.2f} to {max(values):.2f}"


def control_sentences(c):
    """The control's findings in words (every number from `c`)."""
    if not c:
        return ""
    ns = sorted(c)
    jit = [c[n]["samplers"]["jittered"] for n in ns if "jittered" in c[n]["samplers"]]
    shifted = [(n, c[n]["samplers"]["uniform-shifted"]) for n in ns if "uniform-shifted" in c[n]["samplers"]]
    text = (f"On a grating of exactly sqrt(N) cycles per pixel (scenes/controls/negative_sppN, at N = "
            f"{', '.join(map(str, ns))} spp) every cell of the sqrt(N) x sqrt(N) grid holds one whole period, so "
            "stratifying by that grid cannot help. ")
    if jit:
        text += ("Jittered's noise is random's: " + ", ".join(f"{r:.3f} &plusmn; {se:.3f}" for r, se in jit)
                 + " times it (expected 1). ")
    if shifted:
        text += ("The grid shifted by one random offset puts every sample of a pixel at the same phase: "
                 + ", ".join(f"{r:.1f} &plusmn; {se:.1f} times random's at N = {n}" for n, (r, se) in shifted)
                 + " (expected N; one offset per image, so only 8 values behind each estimate). ")
    unif = [(n, c[n]) for n in ns if "uniform_error" in c[n]]
    if unif:
        text += ("The fixed grid samples every trough: its error against the pixel value is "
                 + ", ".join(f"{e['uniform_error']:.4f}" for _, e in unif)
                 + " (expected (1/2)<sup>2</sup> = 0.25 in every pixel) with noise "
                 + ", ".join(f"{e['uniform_noise']:g}" for _, e in unif) + ". ")
    return text + "Where stratification cannot help, jittered is random and a grid is worst."


def control_table(c):
    samplers = [s for s in ORDER if any(s in c[n]["samplers"] for n in c)]
    head = "".join(f"<th>N = {n}</th>" for n in sorted(c))
    body = ""
    for s in samplers:
        cells = "".join(f"<td>{c[n]['samplers'][s][0]:.3g} &plusmn; {c[n]['samplers'][s][1]:.2g}</td>"
                        if s in c[n]["samplers"] else "<td></td>" for n in sorted(c))
        body += f"<tr><td>{s}</td>{cells}</tr>"
    return f"<table><tr><th>noise / random's noise</th>{head}</tr>{body}</table>"


def html(c, spp, grid):
    """The teaching strand's opening of the grid section."""
    parts = []
    if c:
        parts.append(f"<p>{control_sentences(c)}</p>" + control_table(c))
    if grid:
        fixed = [v["uniform"] for v in grid.values() if "uniform" in v]
        shifted = [v["uniform-shifted"] for v in grid.values() if "uniform-shifted" in v]
        text = f"<p>What this study's CSV says at {spp} spp with the box r = 0.5, as multiples of jittered's error: "
        if shifted:
            worse = sum(x > 1 for x in shifted)
            text += (f"the grid shifted by one random offset per image (a randomised lattice, its error averaged "
                     f"over the seeds) is {span(shifted)} times jittered's, worse in {worse} of {len(shifted)} "
                     "scenes; ")
        if fixed:
            text += (f"the fixed grid, one alignment of the grid with each scene, is {span(fixed)} times jittered's, "
                     f"lower in {sum(x < 1 for x in fixed)} of {len(fixed)} scenes: on content smooth within a pixel "
                     "it is the midpoint rule, systematically better. A grid aliases only content above its own "
                     f"rate (a {int(round(math.sqrt(spp)))} x {int(round(math.sqrt(spp)))} grid resolves up to "
                     f"{math.sqrt(spp) / 2:g} cycles per pixel), which is what the control above is made of. ")
        parts.append(text + "</p>")
    return "".join(parts)


def markdown(c, source):
    lines = ["# The negative control: where stratification cannot help", "",
             f"_Generated from `{source}` by `python3 -m analysis.aliaslab_analysis.teaching.negative`; every number "
             "below is recomputed by analysis/tests/test_teaching_negative.py._", "",
             "The scenes `scenes/controls/negative_spp4.txt`, `_spp16`, `_spp64` (scenes/README.md) at their own "
             "spp and 64 px, box r = 0.5, 8 seeds, 4096-spp references, every registered sampler:", "",
             "```sh",
             "S=scenes/controls; build/bin/sweep --scenes $S/negative_spp4.txt,$S/negative_spp16.txt,"
             "$S/negative_spp64.txt \\",
             "  --samplers random,uniform,uniform-shifted,jittered,nrooks,multijittered,cmj,halton,hammersley,sobol,"
             "pmj02,bluenoise,zsobol \\",
             "  --spp 4,16,64 --filters box --radii 0.5 --seeds 8 --ref-spp 4096 --target area "
             "--out results/negative_control", "```", "",
             control_sentences(c).replace("&plusmn;", "±").replace("<sup>2</sup>", "^2"), "",
             "| sampler | " + " | ".join(f"N = {n}" for n in sorted(c)) + " |",
             "|---|" + "---|" * len(c)]
    for s in ORDER:
        if any(s in c[n]["samplers"] for n in c):
            lines.append(f"| {s} | " + " | ".join(
                f"{c[n]['samplers'][s][0]:.3g} ± {c[n]['samplers'][s][1]:.2g}" if s in c[n]["samplers"] else ""
                for n in sorted(c)) + " |")
    lines += ["", "Noise as a multiple of random's noise at the control's own spp (random's noise: "
              + ", ".join(f"{c[n]['random']:.4g} ± {c[n]['random_se']:.2g} at N = {n}, expected {c[n]['expected']:.4g}"
                          for n in sorted(c)) + "). Patterns whose x projection is stratified finer than a period "
              "(nrooks, sobol, pmj02, halton, ...) are far below random: the grating depends on x alone. The grid "
              "shifted by one random offset per *pixel* is not a registered sampler; tests/programs/contract_test.cpp "
              "builds it and finds its noise N times random's within 3 se, with far tighter errors than "
              "`uniform-shifted`'s one offset per image.", ""]
    return "\n".join(lines)


def main(argv=None):
    from ..io.study_csv import load_study
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        print("usage: python3 -m analysis.aliaslab_analysis.teaching.negative STUDY.csv", file=sys.stderr)
        return 2
    df, _ = load_study(argv[0])
    source = os.path.relpath(os.path.abspath(argv[0]))
    sys.stdout.write(markdown(control(df), source))
    return 0


if __name__ == "__main__":
    sys.exit(main())
