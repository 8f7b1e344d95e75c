"""docs/notebook.py runs headless and its numbers hold: its recomputed answer (every across-scene verdict at the
primary target's highest spp) equals results/answer.csv.gz read here with the csv module, and each error map's mse
equals one computed here from the programs' own images (the raytracer's EXR, the reference program's EXR and
manifest)."""
import csv
import gzip
import json
import os
import subprocess
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import support  # noqa: E402


class Notebook(support.TempCase):
    def test_the_notebook_runs_and_its_numbers_hold(self):
        env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=os.pathsep.join(
            [os.environ.get("PYTHONPATH", ""), support.ROOT]))
        r = subprocess.run([sys.executable, os.path.join(support.ROOT, "docs", "notebook.py"), self.tmp],
                           capture_output=True, text=True, env=env, cwd=support.ROOT)
        self.assertEqual(r.returncode, 0, r.stderr)
        s = json.load(open(os.path.join(self.tmp, "summary.json")))
        self.assertTrue(os.path.getsize(os.path.join(self.tmp, "error_maps.png")) > 1000)

        # the answer: every across-scene verdict, from answer.csv directly
        a = s["answer"]
        want = {f"{r['sampler']} {r['filter']} r={float(r['radius']):g} {r['reconstruction']}": r["verdict"]
                for r in csv.DictReader(gzip.open(os.path.join(support.ROOT, "results", "answer.csv.gz"), "rt", newline=""))
                if r["scope"] == "all" and r["target"] == a["target"] and int(r["spp"]) == a["spp"]}
        self.assertTrue(want)
        self.assertEqual(a["verdicts"], want)
        self.assertTrue(a["matches_answer_csv"])

        # the error maps' numbers, from the programs' images
        rd = s["render"]
        w, h = rd["size"]
        support.run("reference", "--scene", os.path.join(support.ROOT, rd["scene"]), "--filters", "box", "--radii",
                    0.5, "--spp", 1024, "--size", w, h, "--out", self.tmp)
        ref = support.read_exr(os.path.join(self.tmp, "zoneplate-box-r0.5.exr"))[:, :, :3].astype(np.float64)
        manifest = json.load(open(os.path.join(self.tmp, "manifest.json")))
        ref_error = [f for f in manifest["filters"] if f["filter"] == "box"][0]["ref_error"]
        self.assertAlmostEqual(rd["ref_error"], ref_error, delta=1e-5 * ref_error)
        self.assertEqual(len(rd["methods"]), 2)
        for label, m in rd["methods"].items():
            out = os.path.join(self.tmp, "m.exr")
            support.run("raytracer", "-input", os.path.join(support.ROOT, rd["scene"]), "-size", w, h, "--sampler",
                        m["sampler"], "--spp", rd["spp"], "--filter", m["filter"], "--radius", m["radius"],
                        "--seed", 0, "-output", out)
            image = support.read_exr(out)[:, :, :3].astype(np.float64)
            mse = float(np.mean((image - ref) ** 2) - ref_error)
            self.assertAlmostEqual(m["mse"], mse, delta=1e-5 * abs(mse), msg=label)


if __name__ == "__main__":
    unittest.main()
