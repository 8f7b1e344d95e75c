# %% [markdown]
# # aliaslab from Python: a notebook
#
# A notebook as a Python script with `# %%` cells (VS Code, Jupyter with jupytext, Spyder run them cell by cell;
# `python3 docs/notebook.py` runs them all). It needs the module built (`build/python` on PYTHONPATH, see
# docs/python.md) and runs from the repository root with Debian's /usr/bin/python3:
#
#     PYTHONPATH=build/python /usr/bin/python3 docs/notebook.py [OUT_FOLDER]
#
# It (1) loads the committed study and recomputes one of the page's answers with the analysis API, checking it
# against results/answer.csv.gz, and (2) renders two methods of one scene through the module and shows their error
# maps against the scene's reference. Figures and a summary.json go to OUT_FOLDER (default: a new temporary
# folder); the test suite runs it headless (python/tests/test_notebook.py) and checks the summary's numbers.

# %%
import json
import os
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")  # headless: figures are saved, never shown
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

# The repository root: the analysis package imports from there, and the study, answer.csv and scenes are read
# from there (as a script: this file's parent folder; in Jupyter, started in docs/: the current folder's parent).
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__))) if "__file__" in globals() else \
    os.path.dirname(os.getcwd())
os.chdir(ROOT)
sys.path.insert(0, ROOT)
import aliaslab  # noqa: E402  (build/python on PYTHONPATH)
from analysis.aliaslab_analysis import api  # noqa: E402

OUT = sys.argv[1] if len(sys.argv) > 1 else tempfile.mkdtemp(prefix="aliaslab-notebook-")
os.makedirs(OUT, exist_ok=True)
summary = {}

# %% [markdown]
# ## 1. One of the page's answers, recomputed
#
# The page's answer: at each spp, how each method compares with each scene's best across the scenes (the median
# ratio of its error to the best's, with a bootstrap interval over scenes) and its verdict at the margin:
# *equivalent* (interval below 1 + margin, and equivalent in at least half the scenes), *worse* (interval above
# it) or *undetermined*. `api.answer` applies the same rules to the study's rows; we take the primary target at
# the highest spp and list the methods not shown worse, the contenders.

# %%
df, notes = api.load_study(api.study_path("results/presented"))
answer = api.answer(df)
target = api.targets(df)[0]  # the primary target, the page's first
top = int(answer["spp"].max())


def verdicts(table):
    """{'sampler filter r=radius reconstruction': across-scene verdict} at (target, top spp)."""
    t = table[(table["scope"] == api.ALL) & (table["target"].astype(str) == target) & (table["spp"] == top)]
    return {f"{r.sampler} {r.filter} r={float(r.radius):g} {r.reconstruction}": r.verdict for r in t.itertuples()}


def contenders(table):
    """The methods whose across-scene verdict at (target, top spp) is not 'worse', sorted."""
    return sorted(m for m, v in verdicts(table).items() if v != api.WORSE)


mine = contenders(answer)
committed = contenders(pd.read_csv("results/answer.csv.gz", keep_default_na=False, low_memory=False))
print(f"against {target} at {top} spp, {len(mine)} of {len(verdicts(answer))} methods are not shown worse than "
      f"each scene's best (margin {api.MARGIN:g}):")
rows = answer[(answer["scope"] == api.ALL) & (answer["target"].astype(str) == target) & (answer["spp"] == top)]
print(rows[rows["verdict"] != api.WORSE][["sampler", "filter", "radius", "ratio", "ci_low", "ci_high", "verdict",
                                          "equivalent_scenes"]].to_string(index=False))
print("the same as results/answer.csv.gz:", mine == committed)
summary["answer"] = {"target": target, "spp": top, "contenders": mine, "verdicts": verdicts(answer),
                     "matches_answer_csv": mine == committed}

# %% [markdown]
# ## 2. Two methods of one scene, and their error maps
#
# The zone plate at 64 x 64 pixels, 16 samples per pixel: independent random points with the pixel-area box
# against Sobol points with a Mitchell filter of radius 2. The target is the pixel-area reference (box of radius
# 0.5, 1024 spp), itself an estimate: its variance (the mean of D^2, `ref["error"]`) is subtracted from each
# mean squared error, as the study does. The Mitchell filter's error holds its blur against this target too
# (the decomposition splits it: docs/science.md).

# %%
SCENE, SIZE, SPP = "scenes/zoneplate.txt", (64, 64), 16
ref = aliaslab.reference(SCENE, filter="box", radius=0.5, spp=1024, size=SIZE)
methods = {"random + box 0.5": dict(sampler="random", filter="box", radius=0.5),
           "sobol + mitchell 2": dict(sampler="sobol", filter="mitchell", radius=2.0)}
fig, axes = plt.subplots(1, len(methods) + 1, figsize=(4 * (len(methods) + 1), 4))
axes[0].imshow(np.clip(ref["image"], 0, 1))
axes[0].set_title("reference (box 0.5, 1024 spp)")
summary["render"] = {"scene": SCENE, "size": list(SIZE), "spp": SPP, "ref_error": ref["error"], "methods": {}}
for ax, (label, m) in zip(axes[1:], methods.items()):
    image = aliaslab.render(SCENE, spp=SPP, seed=0, size=SIZE, **m)
    err = np.mean((image.astype(np.float64) - ref["image"]) ** 2, axis=2)  # per pixel, mean over channels
    mse = float(err.mean() - ref["error"])
    shown = ax.imshow(err, cmap="magma")
    ax.set_title(f"{label}: mse {mse:.3g}")
    fig.colorbar(shown, ax=ax, fraction=0.046)
    summary["render"]["methods"][label] = dict(m, mse=mse)
    print(f"{label}: mse against the reference {mse:.4g}")
for ax in axes:
    ax.axis("off")
fig.tight_layout()
fig.savefig(os.path.join(OUT, "error_maps.png"), dpi=80)
plt.close(fig)

# %%
with open(os.path.join(OUT, "summary.json"), "w") as f:
    json.dump(summary, f, indent=1)
print("figures and summary.json in", OUT)
