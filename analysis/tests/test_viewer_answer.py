"""The viewer holds the answer: every method answer.csv names (equivalent to the best, the best
of each sampler) is among the committed viewer's configurations, found from answer.csv with the csv module,
independently of the viewer's own choice (viewer/answer.py)."""
import csv
import io
import json
import os
import unittest

import numpy as np

from .test_viewer import ANSWER, STUDY, VIEWER, load_js
from ..aliaslab_analysis.io import text_file


def answer_rows():
    """answer.csv beside the viewer data (read with the csv module), else the report's answer table computed from
    the study (the code that writes answer.csv), as rows of strings."""
    if os.path.isfile(ANSWER):
        with io.StringIO(text_file.read_text(ANSWER), newline="") as f:
            return list(csv.DictReader(f))
    from ..aliaslab_analysis.io import study_csv
    from ..aliaslab_analysis.findings.study import Study
    df, notes = study_csv.load_study(STUDY)
    return [{k: str(v) for k, v in r.items()} for r in Study(df, notes).answer.to_dict("records")]


def named_methods(rows, scenes):
    """{scene: {(sampler, spp, filter, radius): why}}: what answer.csv names, found independently of the viewer's
    code: the rows called equivalent (a scene's, or across scenes: every scene) and, per (target, spp, sampler),
    the across-scene row with the lowest ratio (ties: more scenes equivalent), plain weighted sampling only."""
    rows = [r for r in rows if r["reconstruction"] == "weighted" and r["prefilter"] in ("none", "")]
    key = lambda r: (r["sampler"], int(float(r["spp"])), r["filter"], float(r["radius"]))  # noqa: E731
    out = {s: {} for s in scenes}
    for r in rows:
        if r["verdict"] == "equivalent":
            for s in (scenes if r["scope"] == "all" else [r["scope"]]):
                out[s][key(r)] = f"equivalent ({r['target']}, {r['spp']} spp, {r['scope']})"
    best = {}
    for r in rows:
        if r["scope"] != "all" or not np.isfinite(float(r["ratio"] or "nan")):
            continue
        k = (r["target"], r["spp"], r["sampler"])
        rank = (float(r["ratio"]), -int(float(r["equivalent_scenes"])))
        if k not in best or rank < best[k][0]:
            best[k] = (rank, r)
    for (t, spp, sampler), (_, r) in best.items():
        for s in scenes:
            out[s].setdefault(key(r), f"best of {sampler} ({t}, {spp} spp)")
    return out


class TheAnswerIsInTheViewer(unittest.TestCase):
    def test_every_method_answer_csv_names_is_in_the_viewer(self):
        with open(os.path.join(VIEWER, "index.json"), encoding="utf-8") as f:
            index = json.load(f)
        held, whole, primary = {}, {}, {}
        for s, v in index["scenes"].items():
            d = load_js(os.path.join(VIEWER, v["file"]))
            held[s] = {(c["sampler"], c["spp"], c["filter"], float(c["radius"])) for c in d["configs"]}
            # the methods equivalent to the best: their whole image and whole FLIP maps (--whole answer or all;
            # --whole headline: those against the primary target at the lowest spp; --whole view: the opening
            # view's only, the rest rendered on demand with --serve)
            whole[s] = {(c["sampler"], c["spp"], c["filter"], float(c["radius"])) for c in d["configs"]
                        if c["whole"] and set(c["flipWhole"]) == set(d["targets"])}
            primary[s] = d["primary"]
            for c in d["configs"]:
                if "E" in c["sets"] and index.get("whole", "answer") in ("answer", "all"):
                    self.assertTrue(c["whole"] and set(c["flipWhole"]) == set(d["targets"]), (s, c["id"]))
        rows = answer_rows()
        if index.get("whole") == "headline":
            low = min(int(float(r["spp"])) for r in rows)
            target = next(iter(primary.values()))  # the study's primary target (every scene's)
            first = [r for r in rows if r["target"] == target and int(float(r["spp"])) == low]
            wanted = named_methods(first, sorted(held))
            headline = [(s, k) for s in wanted for k, why in wanted[s].items() if why.startswith("equivalent")]
            self.assertGreater(len(headline), 0)
            self.assertEqual([x for x in headline if x[1] not in whole[x[0]]], [],
                             "methods equivalent to the best at the lowest spp against the primary target without "
                             "their whole image and whole FLIP maps")
        named = named_methods(rows, sorted(held))
        missing = [(s, k, why) for s in named for k, why in named[s].items() if k not in held[s]]
        self.assertGreater(sum(map(len, named.values())), 0)
        self.assertEqual(missing, [], f"{len(missing)} named methods missing from {VIEWER} (regenerate it: "
                                      "python3 -m analysis viewer)")


if __name__ == "__main__":
    unittest.main()
