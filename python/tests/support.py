"""What the Python module's tests share: where the programs and scenes are, running a program, reading an EXR.

ctest runs each test as `/usr/bin/python3 python/tests/test_X.py` from the repository root with PYTHONPATH set to
the build's module folder and ALIASLAB_BIN to the build's bin folder (python/CMakeLists.txt)."""
import os
import subprocess
import tempfile
import unittest

import numpy as np

ROOT = os.environ.get("ALIASLAB_ROOT", os.getcwd())
BIN = os.environ.get("ALIASLAB_BIN", os.path.join(ROOT, "build", "bin"))


def scene(name):
    return os.path.join(ROOT, "scenes", name)


def run(program, *args):
    """Runs build/bin/PROGRAM with ARGS; returns its stdout; fails the test with its stderr on a non-zero exit."""
    r = subprocess.run([os.path.join(BIN, program), *map(str, args)], capture_output=True, text=True)
    if r.returncode != 0:
        raise AssertionError(f"{program} {' '.join(map(str, args))} exited {r.returncode}: {r.stderr}")
    return r.stdout


def read_exr(path):
    """An EXR as an (H, W, C) float32 array, read by OpenImageIO's own Python module (independent of aliaslab)."""
    import OpenImageIO as oiio
    inp = oiio.ImageInput.open(path)
    if inp is None:
        raise AssertionError(f"{path}: {oiio.geterror()}")
    try:
        return np.asarray(inp.read_image("float"), dtype=np.float32)
    finally:
        inp.close()


def same_bits(a, b):
    """True when two float32 arrays have the same shape and the same bits (NaN payloads and -0 included)."""
    a, b = np.ascontiguousarray(a, np.float32), np.ascontiguousarray(b, np.float32)
    return a.shape == b.shape and np.array_equal(a.view(np.uint32), b.view(np.uint32))


class TempCase(unittest.TestCase):
    """A test case with a temporary folder self.tmp, removed afterwards."""

    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="aliaslab-python-")
        self.tmp = self._tmp.name

    def tearDown(self):
        self._tmp.cleanup()
