"""render() and reference() against the programs, to the bit: the raytracer's EXR (with the tracing flags of the
scene's # render: line) and the reference program's EXR and manifest, read by OpenImageIO's Python module."""
import json
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import support  # noqa: E402
import aliaslab  # noqa: E402


class Render(support.TempCase):
    def raytracer(self, name, size, *flags):
        out = os.path.join(self.tmp, "out.exr")
        support.run("raytracer", "-input", support.scene(name), "-size", *size, *flags, "-output", out)
        return support.read_exr(out)[:, :, :3]

    def test_a_filtered_render_equals_the_raytracers_exr(self):
        want = self.raytracer("sphere_triangle.txt", (9, 9), "--sampler", "sobol", "--spp", 16, "--filter", "mitchell",
                              "--radius", 2, "--seed", 3)
        got = aliaslab.render(support.scene("sphere_triangle.txt"), sampler="sobol", spp=16, filter="mitchell",
                              radius=2, seed=3)
        self.assertEqual(got.shape, (9, 9, 3))
        self.assertEqual(got.dtype, np.float32)
        self.assertTrue(support.same_bits(got, want))
        other = aliaslab.render(support.scene("sphere_triangle.txt"), sampler="sobol", spp=16, filter="mitchell",
                                radius=2, seed=4)
        self.assertFalse(support.same_bits(other, want), "another seed must be told apart")

    def test_the_render_lines_tracing_flags_and_the_default_filter(self):
        # glass_sphere's render line: -shadows -bounces 5 -weight 0.01 -shade_back; spp > 1 without a filter: box 0.5
        want = self.raytracer("glass_sphere.txt", (24, 20), "-shadows", "-bounces", 5, "-weight", 0.01,
                              "-shade_back", "--sampler", "jittered", "--spp", 4)
        got = aliaslab.render(support.scene("glass_sphere.txt"), sampler="jittered", spp=4, size=(24, 20))
        self.assertEqual(got.shape, (20, 24, 3))
        self.assertTrue(support.same_bits(got, want))
        flat = self.raytracer("glass_sphere.txt", (24, 20), "--sampler", "jittered", "--spp", 4)
        self.assertFalse(support.same_bits(got, flat), "the tracing flags must change this scene")

    def test_importance_reconstruction_and_a_mesh_scene(self):
        # a mesh scene is traced with the BVH whatever its render line's -grid (as the sweep; the raytracer's own
        # -grid would force a grid), so the raytracer is run without it
        want = self.raytracer("fence.txt", (32, 32), "--sampler", "pmj02", "--spp", 8,
                              "--filter", "gaussian", "--radius", 1.5, "--reconstruction", "importance")
        got = aliaslab.render(support.scene("fence.txt"), sampler="pmj02", spp=8, filter="gaussian", radius=1.5,
                              reconstruction="importance", size=(32, 32), threads=1)
        self.assertTrue(support.same_bits(got, want))


class Reference(support.TempCase):
    def test_reference_equals_the_reference_programs_image_and_error(self):
        support.run("reference", "--scene", support.scene("sphere_triangle.txt"), "--filters", "tent", "--radii", 1,
                    "--spp", 64, "--batch", 16, "--out", self.tmp)
        want = support.read_exr(os.path.join(self.tmp, "sphere_triangle-tent-r1.exr"))[:, :, :3]
        with open(os.path.join(self.tmp, "manifest.json")) as f:
            manifest = json.load(f)
        entry = [f for f in manifest["filters"] if f["filter"] == "tent"][0]
        got = aliaslab.reference(support.scene("sphere_triangle.txt"), filter="tent", radius=1, spp=64, batch=16)
        self.assertTrue(support.same_bits(got["image"], want))
        self.assertEqual(got["spp"], 64)
        d = got["half_diff"].astype(np.float64)
        self.assertAlmostEqual(got["error"], float(np.mean(d * d)), delta=1e-9 * max(got["error"], 1e-30))
        self.assertAlmostEqual(got["error"], float(entry["ref_error"]), delta=1e-5 * got["error"])
        self.assertEqual(got["describe"], entry["describe"])


if __name__ == "__main__":
    unittest.main()
