"""points() against the programs: the pointsets program's --dump of every point it measured, and the raytracer's
-render_samples picture of the samples it traced (classic flags: a 1 x 1 image, each sample drawn at
floor(64 x position) in its own colour on the pixel's grey; film y points up, the picture's rows run down)."""
import csv
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import support  # noqa: E402
import aliaslab  # noqa: E402

GREY = np.float32(0.2)  # the checker grey of pixel (0, 0) behind the samples


class PointsetsDump(support.TempCase):
    def test_points_equal_the_dump_bit_for_bit(self):
        names = [s for s in aliaslab.samplers() if ":" not in s] + ["bluenoise-dither:sobol"]
        dump = os.path.join(self.tmp, "points.csv")
        support.run("pointsets", "--samplers", ",".join(names), "--counts", "16,25", "--sets", "3", "--seed", "7",
                    "--dump", dump, "--out", self.tmp)
        with open(dump) as f:
            rows = list(csv.DictReader(f))
        seen = set()
        groups = {}
        for r in rows:
            groups.setdefault((r["sampler"], int(r["n"]), int(r["px"]), int(r["py"])), []).append(r)
        for (name, n, px, py), g in groups.items():
            p = aliaslab.points(name, n, pixel=(px, py), seed=7)
            self.assertEqual(p.shape, (n, 2))
            self.assertEqual(p.dtype, np.float64)
            want = np.array([[float(r["x"]), float(r["y"])] for r in sorted(g, key=lambda r: int(r["k"]))])
            # %.9g gives a float32 back exactly; the module's float64 holds that float32 exactly
            self.assertTrue(np.array_equal(p, want.astype(np.float32).astype(np.float64)), (name, n, px, py))
            self.assertTrue(np.array_equal(p, p.astype(np.float32)), "points are the renderer's floats")
            seen.add(name)
        self.assertEqual(seen, set(names))
        self.assertEqual(len(groups), len(names) * 2 * 3)

    def test_another_seed_or_pixel_gives_other_points(self):  # the comparison above can tell them apart
        a = aliaslab.points("sobol", 16, (0, 0), 7)
        self.assertFalse(np.array_equal(a, aliaslab.points("sobol", 16, (0, 0), 8)))
        self.assertFalse(np.array_equal(a, aliaslab.points("sobol", 16, (1, 0), 7)))


class RenderSamples(support.TempCase):
    def marked(self, *flags):
        out = os.path.join(self.tmp, "samples.exr")
        support.run("raytracer", "-input", support.scene("sphere_triangle.txt"), "-size", 1, 1, *flags,
                    "-render_samples", out, 64)
        img = support.read_exr(out)[:, :, :3]
        ys, xs = np.nonzero(np.any(img != GREY, axis=2))
        return set(zip(xs.tolist(), ys.tolist()))

    def expected(self, sampler, spp, seed=0):
        p = aliaslab.points(sampler, spp, (0, 0), seed).astype(np.float32)
        cells = np.floor(p * np.float32(64)).astype(int)  # film position (0 + u) x zoom, as the picture draws it
        return {(x, 63 - y) for x, y in cells.tolist()}  # film y points up; the file's rows run top-down

    def test_jittered_samples_sit_where_points_says(self):
        self.assertEqual(self.marked("-jittered_samples", 16), self.expected("jittered", 16))

    def test_random_samples_sit_where_points_says(self):
        got = self.marked("-random_samples", 25)
        self.assertEqual(got, self.expected("random", 25))
        self.assertNotEqual(got, self.expected("random", 25, seed=1))


if __name__ == "__main__":
    unittest.main()
