// Issue 31: images 1 pixel wide or high (legal sizes: --size 1 64, --long-side 1) have spectra. Checked against a
// direct DFT computed here: P(u, v) = |sum_x,y f(x, y) e^{-2 pi i (u x / W + v y / H)}|^2 / (W H)^2, mean over the
// three channels, and against Parseval (the powers sum to the mean square).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "core/image.h"
#include "measure/spectrum.h"

using namespace aliaslab;

namespace {
Image ramp(int w, int h) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) im.set(x, y, Color(0.1f * x + 0.3f * y, std::sin(0.7f * (x + y)), (x * 7 + y * 3) % 5 * 0.2f));
  return im;
}

std::vector<double> directPower(const Image& im) {
  const int w = im.width(), h = im.height();
  std::vector<double> p(size_t(w) * h, 0.0);
  for (int c = 0; c < 3; ++c)
    for (int v = 0; v < h; ++v)
      for (int u = 0; u < w; ++u) {
        std::complex<double> s = 0;
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x)
            s += double(im.get(x, y)[c]) * std::polar(1.0, -2 * M_PI * (double(u) * x / w + double(v) * y / h));
        p[size_t(v) * w + u] += std::norm(s) / (double(w) * h * double(w) * h) / 3;
      }
  return p;
}
}  // namespace

TEST(SpectrumDegenerate, OnePixelWideHighOrBothMatchesTheDirectDft) {
  for (const auto& [w, h] : {std::pair{1, 64}, std::pair{64, 1}, std::pair{1, 1}, std::pair{1, 9}}) {
    const Image im = ramp(w, h);
    const auto p = powerSpectrum(im), q = directPower(im);
    ASSERT_EQ(p.size(), q.size());
    double sum = 0, meanSquare = 0;
    for (size_t i = 0; i < p.size(); ++i) {
      EXPECT_NEAR(p[i], q[i], 1e-9 * (1 + q[i])) << w << " x " << h << " frequency " << i;
      sum += p[i];
    }
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) meanSquare += double(im.get(x, y)[c]) * im.get(x, y)[c] / (3.0 * w * h);
    EXPECT_NEAR(sum, meanSquare, 1e-9) << w << " x " << h << " (Parseval)";
  }
}
