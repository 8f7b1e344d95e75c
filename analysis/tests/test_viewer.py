"""The comparison viewer's data.

The committed viewer data of the presented study (results/viewer) against its CSV, read here with the csv module
(not the package's loader): every value the viewer displays beside an image equals the CSV row's. The image
encoding round trip, the crop choice and the plan's filter choice against independent computations. (The viewer
holds the answer: test_viewer_answer; the teaching strand's rules: test_teaching_facts.)"""
import csv
import io
import json
import os
import shutil
import subprocess
import tempfile
import unittest

import numpy as np

from ..aliaslab_analysis.viewer import export, flip, plan
from ..aliaslab_analysis.report import viewer_section as section
from ..aliaslab_analysis.io.exr import read_exr
from ..aliaslab_analysis.io import text_file

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
IMGDIFF = os.path.join(REPO, "build", "bin", "imgdiff")
# ALIASLAB_VIEWER_DATA: check viewer data made elsewhere (e.g. a scratch export of the presented study)
VIEWER = os.environ.get("ALIASLAB_VIEWER_DATA") or os.path.join(REPO, "results", "viewer")
STUDY = os.environ.get("ALIASLAB_VIEWER_STUDY") or os.path.join(REPO, "results", "presented", "study.csv.gz")
ANSWER = os.path.join(os.path.dirname(VIEWER), "answer.csv.gz")
WHOLE_BUDGET = 20_000_000  # bytes of the whole-image files of all scenes (loaded only when asked for; 19.2 MB)


def load_js(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    head = "ALIASLAB_VIEWER_ADD("
    assert text.startswith(head) and text.rstrip().endswith(");"), path
    d = json.loads(text[len(head):text.rstrip().rindex(")")])
    for c in d["configs"]:  # the rows as the viewer reads them: arrays in the order of rowColumns
        c["rows"] = {t: dict(zip(d["rowColumns"], v, strict=True)) for t, v in c["rows"].items()}
    return d


def load_whole(path, scene):
    """The entries of a scene's second file (<scene>_whole.js: ALIASLAB_VIEWER_WHOLE("scene", {...});)."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    head = f"ALIASLAB_VIEWER_WHOLE({json.dumps(scene)}, "
    assert text.startswith(head) and text.rstrip().endswith(");"), path
    return json.loads(text[len(head):text.rstrip().rindex(")")])


def csv_rows():
    out = {}
    with io.StringIO(text_file.read_text(STUDY), newline="") as f:
        for r in csv.DictReader(f):
            if r["reconstruction"] == "weighted" and r["prefilter"] == "none":
                out[(r["scene"], r["sampler"], int(r["spp"]), r["filter"], float(r["radius"]), r["target"])] = r
    return out


class CommittedViewerData(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(os.path.join(VIEWER, "index.json"), encoding="utf-8") as f:
            cls.index = json.load(f)
        cls.scenes = {s: load_js(os.path.join(VIEWER, v["file"])) for s, v in cls.index["scenes"].items()}
        cls.whole = {s: load_whole(os.path.join(VIEWER, d["wholeFile"]), s) for s, d in cls.scenes.items()}
        cls.rows = csv_rows()

    def test_every_scene_of_the_study(self):
        scenes = {k[0] for k in self.rows}
        self.assertEqual(set(self.scenes), scenes)

    def test_values_shown_equal_the_csv_rows(self):
        checked = 0
        for scene, d in self.scenes.items():
            for c in d["configs"]:
                for target, shown in c["rows"].items():
                    r = self.rows[(scene, c["sampler"], c["spp"], c["filter"], float(c["radius"]), target)]
                    for col, v in shown.items():
                        if col == "mse_target_seeds":
                            self.assertEqual(v, [float(x) for x in r[col].split(";")])
                        elif v is None:
                            self.assertFalse(np.isfinite(float(r[col])), (scene, c["id"], col))
                        else:
                            self.assertEqual(v, float(r[col]), (scene, c["id"], target, col))
                        checked += 1
                self.assertEqual(set(c["rows"]), set(d["targets"]), c["id"])
        self.assertGreater(checked, 1000)

    def test_images_were_verified_against_the_csv(self):
        for scene, d in self.scenes.items():
            self.assertGreater(d["verified"]["comparisons"], 0, scene)
            self.assertLessEqual(d["verified"]["max_relative_difference"], export.TOLERANCE, scene)

    def test_images_decode_to_their_stated_range(self):
        for scene, d in self.scenes.items():
            n = d["crop"]["size"]
            for c in d["configs"][:5]:
                for k, key in c["crop"].items():
                    e = d["images"][key]
                    v = export.decode(e)
                    self.assertEqual(v.shape[:2], (n, n))
                    self.assertAlmostEqual(float(v.min()), e["lo"], places=9)
                    self.assertAlmostEqual(float(v.max()), e["hi"], places=9)
            self.assertTrue(0 <= d["crop"]["x"] <= d["width"] - n and 0 <= d["crop"]["y"] <= d["height"] - n)

    def test_flip_maps_stored_for_every_configuration_and_target(self):
        for scene, d in self.scenes.items():
            n = d["crop"]["size"]
            for c in d["configs"]:
                self.assertEqual(set(c["flipWhole"]), set(d["targets"]) if c["whole"] else set(), (scene, c["id"]))
                self.assertEqual(set(c["flip"]), set(d["targets"]), (scene, c["id"]))
                # the primary target's crop in the first file, the others' and every whole map in the second
                # (a map equal to one in the first file is stored once, there: the viewer looks there first)
                either = {**self.whole[scene], **d["images"]}
                maps = [(d["images"][c["flip"][d["primary"]]], (n, n, 1))] + \
                    [(either[c["flip"][t]], (n, n, 1)) for t in d["targets"] if t != d["primary"]] + \
                    [(self.whole[scene][k], (d["height"], d["width"], 1)) for k in c["flipWhole"].values()]
                for e, shape in maps:
                    self.assertEqual((e["bits"], e["lo"], e["hi"], e["c"]), (8, 0.0, 1.0, 1))
                    v = export.decode(e)
                    self.assertEqual(v.shape, shape)
                    self.assertTrue(0.0 <= v.min() and v.max() <= 1.0)
                if not c["whole"]:
                    continue
                crop = export.decode(self.whole[scene][c["flipWhole"][d["primary"]]])
                x, y = d["crop"]["x"], d["crop"]["y"]
                np.testing.assert_array_equal(crop[y:y + n, x:x + n], export.decode(d["images"][c["flip"][d["primary"]]]))

    def test_whole_images_of_every_configuration_in_the_second_file(self):
        for scene, d in self.scenes.items():
            w = self.whole[scene]
            self.assertFalse(any(k.startswith("w") for k in d["images"]), scene)
            self.assertTrue(any(c["whole"] for c in d["configs"]), scene)
            wanted = [c["whole"] for c in d["configs"] if c["whole"]] + [r["whole"] for r in d["refs"].values()] + \
                [t["whole"] for t in d["targetImages"].values()]
            for key in wanted:
                self.assertIn(key, w, scene)
                e = w[key]
                self.assertEqual((e["h"], e["w"], e["bits"]), (d["height"], d["width"], 8), (scene, key))
            self.assertEqual(self.index["scenes"][scene]["whole_bytes"],
                             os.path.getsize(os.path.join(VIEWER, d["wholeFile"])))

    def test_whole_image_equals_the_crop_where_they_overlap(self):
        # the 8-bit whole image over its own range against the crop (8 bits over the crop's range): both within
        # their half steps of the same render
        for scene, d in self.scenes.items():
            x, y, n = d["crop"]["x"], d["crop"]["y"], d["crop"]["size"]
            for c in [c for c in d["configs"] if c["whole"]][:4]:
                we, ce = self.whole[scene][c["whole"]], d["images"][c["crop"]["0"]]
                whole, crop = export.decode(we)[y:y + n, x:x + n], export.decode(ce)
                step = (we["hi"] - we["lo"]) / 255 / 2 + (ce["hi"] - ce["lo"]) / 255 / 2
                self.assertLessEqual(float(np.abs(whole - crop).max()), step + 1e-9, (scene, c["id"]))

    def test_size_budget(self):
        later = {v["whole_file"] for v in self.index["scenes"].values()}
        sizes = {f: os.path.getsize(os.path.join(VIEWER, f)) for f in os.listdir(VIEWER)}
        # the page loads the opening scene's file, the teaching strand and the viewer's script; every other
        # scene's file is loaded when that scene is opened
        scene_files = {f"{s}.js" for s in self.index["scenes"]}
        first = max(sizes[f] for f in scene_files) + \
            sum(b for f, b in sizes.items() if f not in later and f not in scene_files)
        self.assertLess(first, 1_700_000, "the viewer data loaded with the page (one scene, the teaching strand "
                        "and the viewer's script) within its share of the page's 5 MB budget")
        self.assertLess(sum(sizes[f] for f in later), WHOLE_BUDGET, "the whole images, loaded on demand")

    def test_the_committed_script_is_the_packages(self):
        for name in section.ASSETS:
            with open(os.path.join(VIEWER, name), encoding="utf-8") as f:
                self.assertEqual(f.read(), section.asset(name), f"results/viewer/{name}: regenerate the page")


class Encoding(unittest.TestCase):
    def test_round_trip_within_half_a_step(self):
        rng = np.random.default_rng(3)
        for bits in (8, 16):
            for c in (1, 3):
                a = rng.normal(0.5, 0.3, size=(13, 17, c))
                e = export.png_entry(a, bits)
                step = (a.max() - a.min()) / ((1 << bits) - 1)
                self.assertLessEqual(float(np.abs(export.decode(e) - a).max()), step / 2 + 1e-12, (bits, c))

    def test_fixed_scale_clips_and_states_it(self):
        a = np.array([[-0.1, 0.0, 0.5, 1.2]]).reshape(1, 4, 1)
        e = export.png_entry(a, 8, (0.0, 1.0))
        self.assertEqual((e["lo"], e["hi"]), (0.0, 1.0))
        self.assertEqual(export.decode(e).ravel().tolist(), [0.0, 0.0, 128 / 255, 1.0])

    @unittest.skipUnless(os.access(IMGDIFF, os.X_OK) and shutil.which("oiiotool"), "needs build/bin/imgdiff, oiiotool")
    def test_flip_map_decoded_equals_imgdiffs_within_the_step(self):
        """The exported FLIP map (flip.flip_maps, the viewer's 8-bit entry, decoded) against imgdiff's own map read
        from its EXR, on a 40 x 24 image (narrower than imgdiff's 200-pixel colour bar); the map's mean equals the
        flip imgdiff prints."""
        with tempfile.TemporaryDirectory() as tmp:
            a, b, m = (os.path.join(tmp, x) for x in ("a.exr", "b.exr", "m.exr"))
            subprocess.run(["oiiotool", "--pattern", "checker:width=4:height=4", "40x24", "3", "-d", "float", "-o", a],
                           check=True)
            subprocess.run(["oiiotool", "--pattern", "noise:type=uniform:min=0.2:max=0.8", "40x24", "3", "-d", "float",
                            "-o", b], check=True)
            run = subprocess.run([IMGDIFF, a, b, "--flip-output", m], check=True, capture_output=True, text=True)
            printed = float(next(x.split()[1] for x in run.stdout.splitlines() if x.startswith("flip ")))
            truth = read_exr(m)[:24, :40, 0]
            mine = flip.flip_maps(IMGDIFF, [(a, b, os.path.join(tmp, "a.flip.exr"))], (40, 24))[0]
            self.assertEqual(mine.shape, (24, 40))
            self.assertAlmostEqual(float(mine.mean()), printed, places=5)
            self.assertGreater(float(truth.max() - truth.min()), 0.1)  # not a constant map
            v = export.decode(export.png_entry(mine[..., None], 8, (0.0, 1.0)))[..., 0]
            self.assertLessEqual(float(np.abs(v - truth).max()), 0.5 / 255 + 1e-7)

    def test_channels(self):
        grey = np.repeat(np.arange(12.0).reshape(3, 4, 1), 3, axis=2)
        self.assertEqual(export.channels(grey).shape, (3, 4, 1))
        colour = grey.copy()
        colour[0, 0, 1] += 1
        self.assertEqual(export.channels(colour).shape, (3, 4, 3))


class Choices(unittest.TestCase):
    def test_crop_is_where_the_methods_differ(self):
        stack = np.zeros((4, 64, 64))
        stack[:, 40:50, 8:18] = np.arange(4)[:, None, None]  # the methods differ only there
        x, y = plan.crop_window(stack, 8)
        self.assertTrue(8 <= x <= 10 and 40 <= y <= 42, (x, y))

    def test_crop_is_structure_not_noise_when_the_noise_is_given(self):
        rng = np.random.default_rng(3)
        means = np.zeros((3, 64, 64))
        noise = np.full((3, 64, 64), 1e-4)
        means[:, 40:48, 8:16] = np.array([0.0, 0.1, 0.2])[:, None, None]  # a structural difference, quiet
        means[:, 0:8, 40:48] = rng.normal(0, 0.5, (3, 8, 8))  # larger differences, all of them noise
        noise[:, 0:8, 40:48] = 0.25
        self.assertEqual(plan.crop_window(means, 8, noise=noise), (8, 40))
        self.assertEqual(plan.crop_window(means, 8), (40, 0))  # by the variance alone: the noisy window


class ImageSizes(unittest.TestCase):
    def test_teaching_img_has_the_pngs_size(self):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from ..aliaslab_analysis.teaching import build
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "a.png")
            plt.imsave(path, np.zeros((7, 13)))  # 13 wide, 7 high
            tag = build.img(path, "cap")
            self.assertIn("width='13' height='7'", tag)

    def test_the_teaching_command_needs_the_viewers_renders(self):
        from . import synthetic
        from ..aliaslab_analysis.teaching import cli
        with tempfile.TemporaryDirectory() as tmp:
            study = os.path.join(tmp, "study.csv")
            synthetic.write(study)
            code, _, err = synthetic.run(cli.main, [tmp, "--study", study])
            self.assertEqual(code, 2)
            self.assertIn("run `python3 -m analysis viewer", err)
            self.assertFalse(os.path.exists(os.path.join(tmp, "viewer", "teaching.html")))


class Section(unittest.TestCase):
    def test_no_data_no_section(self):
        self.assertEqual(section.viewer_section(os.path.join(REPO, "docs")), "")

    def test_section_lists_the_scenes_and_loads_lazily(self):
        html = section.viewer_section(os.path.join(REPO, "results"), write=False)
        self.assertIn("id='alv'", html)
        self.assertIn("data-base='viewer/'", html)
        self.assertNotIn("ALIASLAB_VIEWER_ADD({", html)  # the data is in the per-scene files, not the page
        # the script and the style once, beside the data, not inline
        self.assertIn("<script src='viewer/viewer.js'></script>", html)
        self.assertIn("<link rel='stylesheet' href='viewer/viewer.css'>", html)
        self.assertNotIn("ALIASLAB_VIEWER_ADD = function", html)
        self.assertIn("only when you ask for the whole image", html)

    def test_assets_are_written_beside_the_data(self):
        with tempfile.TemporaryDirectory() as tmp:
            data = os.path.join(tmp, "viewer")
            os.makedirs(data)
            with open(os.path.join(data, "index.json"), "w", encoding="utf-8") as f:
                json.dump({"plan": "p", "scenes": {"s": {"file": "s.js", "bytes": 10, "whole_file": "s_whole.js",
                                                         "whole_bytes": 20, "verified": {
                                                             "comparisons": 1, "max_relative_difference": 0}}}}, f)
            open(os.path.join(data, "s.js"), "w").close()
            html = section.viewer_section(tmp)
            for name in section.ASSETS:
                with open(os.path.join(data, name), encoding="utf-8") as f:
                    self.assertEqual(f.read(), section.asset(name))
            self.assertIn("<script src='viewer/viewer.js'>", html)


if __name__ == "__main__":
    unittest.main()
