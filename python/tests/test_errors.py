"""Bad arguments raise a Python exception naming the argument, and the interpreter goes on working."""
import math
import os
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import support  # noqa: E402
import aliaslab  # noqa: E402

SCENE = support.scene("sphere_triangle.txt")


class BadArguments(unittest.TestCase):
    def raises(self, kind, word, call, *args, **kwargs):
        with self.assertRaises(kind) as c:
            call(*args, **kwargs)
        self.assertIn(word, str(c.exception))
        return str(c.exception)

    def test_each_bad_argument_is_named(self):
        message = self.raises(ValueError, "sampler", aliaslab.points, "nosuch", 4)
        self.assertIn("sobol", message)  # the valid names are listed
        self.raises(ValueError, "spp", aliaslab.points, "jittered", 0)
        self.raises(ValueError, "spp", aliaslab.render, SCENE, spp=0)
        self.raises(ValueError, "sampler", aliaslab.render, SCENE, sampler="nosuch")
        self.raises(FileNotFoundError, "scene_file", aliaslab.render, "no/such/scene.txt")
        self.raises(FileNotFoundError, "scene_file", aliaslab.reference, "no/such/scene.txt")
        self.raises(ValueError, "radius", aliaslab.filter_eval, "tent", math.nan, 0.0, 0.0)
        self.raises(ValueError, "radius", aliaslab.render, SCENE, filter="tent", radius=math.nan)
        self.raises(ValueError, "radius", aliaslab.reference, SCENE, radius=math.nan)
        self.raises(ValueError, "filter", aliaslab.filter_eval, "nosuch", 1.0, 0.0, 0.0)
        self.raises(ValueError, "params", aliaslab.filter_eval, "gaussian", 1.0, 0.0, 0.0, {"sigmaa": 1.0})
        self.raises(ValueError, "size", aliaslab.render, SCENE, size=(0, 9))
        self.raises(ValueError, "spp", aliaslab.reference, SCENE, spp=3)
        self.raises(ValueError, "reconstruction", aliaslab.render, SCENE, reconstruction="nosuch")
        self.raises(TypeError, "type", aliaslab.filter_eval, "tent", "wide", 0.0, 0.0)

    def test_the_interpreter_survives(self):
        script = ("import aliaslab\n"
                  "for call in (lambda: aliaslab.points('nosuch', 4), lambda: aliaslab.render('missing.txt'),\n"
                  "             lambda: aliaslab.filter_eval('tent', float('nan'), 0, 0)):\n"
                  "    try:\n        call()\n    except Exception as e:\n        print(type(e).__name__)\n"
                  "print(aliaslab.points('jittered', 4).shape)\n")
        r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=os.environ)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout.split(), ["ValueError", "FileNotFoundError", "ValueError", "(4,", "2)"])


if __name__ == "__main__":
    unittest.main()
