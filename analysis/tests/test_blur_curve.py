"""The blur curve chart (charts/blur_curve.py): white noise's curve against the continuous value and an
independent spatial sum, one chart per scene from the committed positive-control CSV, nothing for a CSV
without the columns."""
import math
import os
import tempfile
import unittest

import numpy as np

from ..aliaslab_analysis.io import study_csv
from ..aliaslab_analysis.charts.blur_curve import SIGMAS, blur_curve, white_share

HERE = os.path.dirname(os.path.abspath(__file__))
CSV = os.path.join(os.path.dirname(os.path.dirname(HERE)), "results", "positive_control", "study.csv")


class BlurCurve(unittest.TestCase):
    def test_white_share_is_the_kernels_sum_of_squares(self):
        for sigma in SIGMAS:
            # the kernel itself: inverse DFT of the transfer function on a 32 x 32 grid, then sum w^2
            f = np.fft.fftfreq(32)
            h = np.exp(-2 * math.pi ** 2 * sigma ** 2 * (f[None, :] ** 2 + f[:, None] ** 2))
            w = np.real(np.fft.ifft2(h))
            self.assertAlmostEqual(w.sum(), 1.0, places=9)
            self.assertAlmostEqual(white_share(sigma, 32, 32), float((w ** 2).sum()), places=9)
        for sigma in (1.0, 2.0, 4.0):  # the continuous limit 1 / (4 pi sigma^2) once the Gaussian is well sampled
            self.assertAlmostEqual(white_share(sigma, 64, 64) * 4 * math.pi * sigma ** 2, 1.0, places=3)

    def test_one_chart_per_scene_and_none_without_the_columns(self):
        df, _ = study_csv.load_study(CSV)
        with tempfile.TemporaryDirectory() as out:
            paths = blur_curve(df, out)
            self.assertEqual(sorted(os.path.basename(p) for p in paths),
                             [f"blur_curve_{s}.png" for s in ("same_pixel", "same_pixel_x")])  # SVG: only with --svg
            self.assertTrue(all(os.path.getsize(p) > 1000 for p in paths))
            self.assertEqual(blur_curve(df.drop(columns=["blur_ratio_4"]), out), [])


if __name__ == "__main__":
    unittest.main()
