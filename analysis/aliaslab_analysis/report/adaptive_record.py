"""The adaptive samplers against their base, before and after they kept the base's stratification:
the tables and the chart of results/adaptive.md's section "Keeping the base's stratification", generated from
the sweeps' CSVs (every number there comes from here; analysis/tests/test_adaptive_record.py recomputes them).

    python3 -m analysis.aliaslab_analysis.report.adaptive_record --before B1.csv [B2.csv ...] --after A1.csv [A2.csv ...]
            --out FOLDER

Rows: box r = 0.5, weighted, the error mse_target against the pixel area with its se. Several CSVs of one side
are the same study run again (the same errors; cpu_ms, the thread CPU time per image, averaged over them).

At equal spp: each adaptive sampler against its base (the name after ':') in the same study, ratio and z.
At equal CPU time: the base's error at the adaptive row's cpu_ms, interpolated in log(error) against log(cpu_ms)
between the base's two rows around it (the study's spp levels of the base), extrapolated from the last two
beyond them (said so); its se interpolated alike as a relative error. Verdict on log(ratio) with
se = sqrt((se_a / a)^2 + (se_b / b)^2): wins or loses beyond 2 se, else tied.
"""
import argparse
import math
import os
import sys

import numpy as np

Z = 2.0


def load(paths):
    """{(scene, sampler, spp): dict(mse, se, cpu, max_spp)} with cpu_ms averaged over the files."""
    import csv
    out = {}
    for path in paths:
        with open(path, newline="") as f:
            for r in csv.DictReader(f):
                if r["filter"] != "box" or float(r["radius"]) != 0.5 or r["reconstruction"] != "weighted":
                    continue
                key = (r["scene"], r["sampler"], int(r["spp"]))
                d = out.setdefault(key, dict(mse=float(r["mse_target"]), se=float(r["mse_target_se"]), cpu=[],
                                             max_spp=int(r["max_spp"])))
                d["cpu"].append(float(r["cpu_ms"]))
    for d in out.values():
        d["cpu"] = float(np.mean(d["cpu"]))
    return out


def base_of(sampler):
    return sampler.split(":", 1)[1].split("+")[0] if sampler.startswith("adaptive-") else None


def at_time(rows, scene, base, cpu):
    """(error, se, extrapolated) of the base at cpu ms: log-log interpolation between its rows."""
    pts = sorted((d["cpu"], d["mse"], d["se"]) for (s, b, _), d in rows.items() if s == scene and b == base)
    if len(pts) < 2:
        return None
    i = next((k for k in range(1, len(pts)) if pts[k][0] >= cpu), len(pts) - 1)
    (c0, e0, s0), (c1, e1, s1) = pts[i - 1], pts[i]
    t = (math.log(cpu) - math.log(c0)) / (math.log(c1) - math.log(c0))
    err = math.exp((1 - t) * math.log(e0) + t * math.log(e1))
    rel = (1 - t) * s0 / e0 + t * s1 / e1
    return err, rel * err, not (pts[0][0] <= cpu <= pts[-1][0])


def compare(before, after):
    """The rows of both tables: at equal spp and at equal CPU time, for every adaptive sampler of `after`."""
    same_spp, same_time = [], []
    for (scene, sampler, spp), a in sorted(after.items()):
        base = base_of(sampler)
        if base is None or (scene, base, spp) not in after:
            continue
        b = after[(scene, base, spp)]
        old = before.get((scene, sampler, spp))
        row = dict(scene=scene, sampler=sampler, spp=spp, after=a["mse"], after_se=a["se"], base=b["mse"],
                   base_se=b["se"], ratio=a["mse"] / b["mse"], z=(a["mse"] - b["mse"]) / math.hypot(a["se"], b["se"]),
                   max_spp=a["max_spp"])
        if old:
            row.update(before=old["mse"], before_se=old["se"], before_ratio=old["mse"] / b["mse"],
                       before_z=(old["mse"] - b["mse"]) / math.hypot(old["se"], b["se"]))
        same_spp.append(row)
        t = at_time(after, scene, base, a["cpu"])
        if t:
            err, se, extra = t
            lr = math.log(a["mse"] / err)
            lse = math.hypot(a["se"] / a["mse"], se / err)
            verdict = "wins" if lr < -Z * lse else "loses" if lr > Z * lse else "tied"
            same_time.append(dict(scene=scene, sampler=sampler, spp=spp, cpu=a["cpu"], base_cpu=b["cpu"],
                                  base_at=err, ratio=math.exp(lr), z=lr / lse, verdict=verdict, extrapolated=extra))
    return same_spp, same_time


def fmt(v, d=3):
    return f"{v:.{d}g}"


def markdown(same_spp, same_time, levels=(16, 64)):
    out = ["| scene | spp | sampler | before: error (x base, z) | after: error ± se (x base, z) | max_spp |",
           "|---|---|---|---|---|---|"]
    for r in same_spp:
        if r["spp"] not in levels:
            continue
        before = (f"{fmt(r['before'])} ({fmt(r['before_ratio'])}x, {r['before_z']:+.1f})" if "before" in r else "")
        out.append(f"| {r['scene']} | {r['spp']} | {r['sampler']} | {before} | {fmt(r['after'])} ± "
                   f"{fmt(r['after_se'], 2)} ({fmt(r['ratio'])}x, {r['z']:+.1f}) | {r['max_spp']} |")
    out += ["", "| scene | spp | sampler | cpu ms (base at spp) | base's error at that time | adaptive / base | verdict |",
            "|---|---|---|---|---|---|---|"]
    for r in same_time:
        out.append(f"| {r['scene']} | {r['spp']} | {r['sampler']} | {fmt(r['cpu'])} ({fmt(r['base_cpu'])}) | "
                   f"{fmt(r['base_at'])}{' (extrapolated)' if r['extrapolated'] else ''} | {fmt(r['ratio'])}x "
                   f"(z = {r['z']:+.1f}) | {r['verdict']} |")
    heads = []
    for r in same_spp:
        if r["sampler"] == "adaptive-contrast:jittered" and r["spp"] == 16 and "before" in r:
            heads.append(f"{r['scene']} {fmt(r['before_ratio'])}x -> {fmt(r['ratio'])}x (z = {r['z']:+.1f})")
    if heads:
        out = ["adaptive-contrast:jittered against jittered at 16 spp, before -> after: " + "; ".join(heads) + ".",
               ""] + out
    counts = {}
    for r in same_time:
        counts.setdefault(r["sampler"], {"wins": 0, "tied": 0, "loses": 0})[r["verdict"]] += 1
    summary = "; ".join(f"{s}: wins {c['wins']}, tied {c['tied']}, loses {c['loses']}" for s, c in sorted(counts.items()))
    return "\n".join(out), summary, counts


BEGIN, END = "<!-- generated by adaptive_record.py -->", "<!-- end of generated -->"


def block(table, summary):
    """The generated text as results/adaptive.md holds it, between the markers."""
    return f"{BEGIN}\n{table}\n\nAt equal CPU time: {summary}.\n{END}\n"


def chart(path, after, before, same_time):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scenes = sorted({r["scene"] for r in same_time})
    fig, axes = plt.subplots(1, len(scenes), figsize=(4.2 * len(scenes), 3.8), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for base, colour in (("jittered", "k"), ("sobol", "tab:blue")):
            pts = sorted((d["cpu"], d["mse"]) for (s, b, _), d in after.items() if s == scene and b == base)
            if pts:
                ax.plot(*zip(*pts), "-o", color=colour, ms=3, label=base)
        for (s, sampler, spp), d in sorted(after.items()):
            if s != scene or not sampler.startswith("adaptive-"):
                continue
            colour = "k" if base_of(sampler) == "jittered" else "tab:blue"
            marker = {"adaptive-contrast": "^", "adaptive-error": "s", "adaptive-subdiv": "D"}[sampler.split(":")[0]]
            ax.plot(d["cpu"], d["mse"], marker, color=colour, ms=5)
            old = before.get((s, sampler, spp))
            if old:
                ax.plot(old["cpu"], old["mse"], marker, mfc="none", color=colour, ms=5, alpha=0.6)
        ax.set_xscale("log"), ax.set_yscale("log")
        ax.set_title(scene, fontsize=10)
        ax.set_xlabel("thread CPU ms per image")
        ax.grid(alpha=0.3, which="both")
    axes[0][0].set_ylabel("error against the pixel area (mse_target)")
    axes[0][0].legend(fontsize=7, title="base (line: its spp levels)", title_fontsize=7)
    fig.suptitle("adaptive: contrast ^, error s, subdiv D; filled: continuing the base's sequence (after), "
                 "hollow: before", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python3 -m analysis.aliaslab_analysis.report.adaptive_record")
    ap.add_argument("--before", nargs="+", required=True)
    ap.add_argument("--after", nargs="+", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args(argv)
    before, after = load(a.before), load(a.after)
    same_spp, same_time = compare(before, after)
    table, summary, _ = markdown(same_spp, same_time)
    os.makedirs(a.out, exist_ok=True)
    chart(os.path.join(a.out, "equal_time.png"), after, before, same_time)
    with open(os.path.join(a.out, "tables.md"), "w", encoding="utf-8") as f:
        f.write(block(table, summary))
    print(summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
