"""`cmake --install BUILD --prefix P --component python` puts the module where Debian's python3 finds it under P
(P/<ALIASLAB_PYTHON_INSTALL_DIR>), and that copy imports and works without the build tree on the path."""
import os
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import support  # noqa: E402


class Install(support.TempCase):
    def test_the_installed_module_imports(self):
        subprocess.run([os.environ["CMAKE_COMMAND"], "--install", os.environ["ALIASLAB_BUILD"], "--prefix", self.tmp,
                        "--component", "python"], check=True, capture_output=True)
        site = os.path.join(self.tmp, os.environ["ALIASLAB_PYTHON_INSTALL_DIR"])
        env = dict(os.environ, PYTHONPATH=site)
        r = subprocess.run([sys.executable, "-c", "import aliaslab; print(aliaslab.__file__); "
                            "print(len(aliaslab.points('sobol', 8)))"], capture_output=True, text=True, env=env,
                           cwd=self.tmp)
        self.assertEqual(r.returncode, 0, r.stderr)
        where, count = r.stdout.split()
        self.assertTrue(os.path.realpath(where).startswith(os.path.realpath(site)), where)
        self.assertEqual(count, "8")


if __name__ == "__main__":
    unittest.main()
