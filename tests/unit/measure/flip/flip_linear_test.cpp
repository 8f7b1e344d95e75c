// Stage 1 of LDR-FLIP (measure/flip/flip_planes.h flipLinear) bit for bit against the textbook: one pixel at a
// time, every clamped-index sum taken over all its taps (zero ones too) in order from 0, the colour formulas of
// flip_colour.h on scalars, the library's kernels (flipCsfKernels, flipFeatureKernels). The stage's vector
// loops, their AVX2 twins, the skipped zero taps and the row-by-row passes must not change a single bit of any
// output, on images with odd sizes (vector tails), negative, NaN and infinite colours, at two viewing
// distances (two sets of kernel radii), on the SSE2 and the AVX2 path.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>

#include "core/cpu.h"
#include "measure/flip/flip.h"
#include "measure/flip/flip_colour.h"
#include "measure/flip/flip_planes.h"

namespace aliaslab {
namespace {

using namespace flipcolour;
using Plane = std::vector<double>;

// The textbook separable sum: every tap, in order of k, indices clamped at the edges.
Plane textbook(const Plane& in, int w, int h, const Plane& kx, const Plane& ky) {
  const int rx = static_cast<int>(kx.size()) / 2, ry = static_cast<int>(ky.size()) / 2;
  Plane mid(in.size()), out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int k = -rx; k <= rx; ++k) s += kx[k + rx] * in[static_cast<size_t>(y) * w + std::clamp(x + k, 0, w - 1)];
      mid[static_cast<size_t>(y) * w + x] = s;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int k = -ry; k <= ry; ++k) s += ky[k + ry] * mid[static_cast<size_t>(std::clamp(y + k, 0, h - 1)) * w + x];
      out[static_cast<size_t>(y) * w + x] = s;
    }
  return out;
}
Plane delta(int r) {
  Plane d(2 * r + 1, 0.0);
  d[r] = 1;
  return d;
}

FlipLinear textbookLinear(const Image& img, double ppd) {
  const int w = img.width(), h = img.height();
  const size_t n = static_cast<size_t>(w) * h;
  FlipLinear out;
  out.width = w, out.height = h;
  std::array<Plane, 3> ycc;
  Plane lum(n);
  for (auto& p : ycc) p.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const float* c = img.data() + 3 * i;
    const V3 xyz = rgbToXyz(V3{std::clamp<double>(c[0], 0, 1), std::clamp<double>(c[1], 0, 1),
                               std::clamp<double>(c[2], 0, 1)});
    const V3 v = xyzToYcc(xyz);
    for (int k = 0; k < 3; ++k) ycc[k][i] = std::isfinite(v[k]) ? v[k] : 0.0;
    lum[i] = std::isfinite(xyz[1]) ? xyz[1] : 0.0;
  }
  std::array<Plane, 3> f;
  const std::array<FlipCsfKernel, 3> csf = flipCsfKernels(ppd);
  for (int c = 0; c < 3; ++c) {
    const auto& [e1, e2, A1, A2, total] = csf[c];
    const Plane one = textbook(ycc[c], w, h, e1, e1), two = A2 > 0 ? textbook(ycc[c], w, h, e2, e2) : Plane(n);
    f[c].resize(n);
    for (size_t i = 0; i < n; ++i) f[c][i] = (A2 > 0 ? A1 * one[i] + A2 * two[i] : A1 * one[i]) / total;
  }
  for (auto& p : out.rgb) p.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const V3 rgb = xyzToRgb(yccToXyz({f[0][i], f[1][i], f[2][i]}));
    for (int k = 0; k < 3; ++k) out.rgb[k][i] = std::clamp(rgb[k], 0.0, 1.0);
  }
  const auto [g, d1, d2p, d2n, edge, pos, neg] = flipFeatureKernels(ppd);
  // The y-derivative planes as the library defines them: the x pass with g, then the derivative along y.
  const Plane smooth = textbook(lum, w, h, g, delta(0));
  const Plane ex = textbook(lum, w, h, d1, g), ey = textbook(smooth, w, h, delta(0), d1);
  const Plane pxp = textbook(lum, w, h, d2p, g), pxn = textbook(lum, w, h, d2n, g);
  const Plane pyp = textbook(smooth, w, h, delta(0), d2p), pyn = textbook(smooth, w, h, delta(0), d2n);
  out.gx.resize(n), out.gy.resize(n), out.px.resize(n), out.py.resize(n);
  for (size_t i = 0; i < n; ++i) {
    out.gx[i] = ex[i] / edge, out.gy[i] = ey[i] / edge;
    out.px[i] = pxp[i] / pos + pxn[i] / neg, out.py[i] = pyp[i] / pos + pyn[i] / neg;
  }
  return out;
}

Image randomImage(int w, int h, unsigned seed) {
  Image img(w, h);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.5f, 1.5f);
  const float odd[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                       -std::numeric_limits<float>::infinity(), -0.0f, -2.0f, 1e30f};
  for (size_t i = 0; i < static_cast<size_t>(3) * w * h; ++i)
    img.data()[i] = rng() % 17 == 0 ? odd[rng() % 6] : u(rng);
  return img;
}

void expectSameBits(const Plane& got, const Plane& want, const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (size_t i = 0; i < got.size(); ++i)
    ASSERT_EQ(std::bit_cast<uint64_t>(got[i]), std::bit_cast<uint64_t>(want[i]))
        << what << " pixel " << i << ": " << got[i] << " vs " << want[i];
}

void expectTextbook(const Image& img, double ppd) {
  const FlipLinear want = textbookLinear(img, ppd);
  for (const bool sseOnly : {false, true}) {
    SCOPED_TRACE(sseOnly ? "SSE2 path" : "the CPU's widest path");
    std::optional<ScopedCpuFeatures> scope;
    if (sseOnly) scope.emplace(CpuFeatures{});
    const FlipLinear got = flipLinear(img, ppd);
    for (int k = 0; k < 3; ++k) expectSameBits(got.rgb[k], want.rgb[k], "rgb");
    expectSameBits(got.gx, want.gx, "gx"), expectSameBits(got.gy, want.gy, "gy");
    expectSameBits(got.px, want.px, "px"), expectSameBits(got.py, want.py, "py");
  }
}

TEST(FlipLinear, EqualsTheTextbookBitForBitOnOddSizesAndBadColours) {
  expectTextbook(randomImage(37, 23, 1), kFlipDefaultPixelsPerDegree);
  expectTextbook(randomImage(21, 40, 2), 25.0);
  expectTextbook(randomImage(1, 9, 3), kFlipDefaultPixelsPerDegree);
}

TEST(FlipLinear, SeparablePassesSkipZeroTapsWithoutChangingABit) {
  // Kernels with zeros at the ends, in the middle and in runs, on a plane with negative values and exact zeros.
  const int w = 29, h = 17;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3, 3);
  Plane in(static_cast<size_t>(w) * h);
  for (double& v : in) v = rng() % 5 == 0 ? 0.0 : u(rng);
  const Plane kernels[] = {{0, 0.25, 0, -0.5, 0, 0, 0.125}, {0, 0, 0, 1.5, 0, 0, 0}, {0.3, -0.7, 0}, {0, 0, 0}};
  for (const Plane& kx : kernels) {
    for (const Plane& ky : kernels)
      expectSameBits(convolveClamped(in, w, h, kx, ky), textbook(in, w, h, kx, ky), "plane");
    // all four y passes from one x pass, row by row
    std::vector<Plane> rows(4, Plane(in.size()));
    convolveClampedRows(in, w, h, kx, {&kernels[0], &kernels[1], &kernels[2], &kernels[3]},
                        [&](int y, const double* const* r) {
                          for (int j = 0; j < 4; ++j) std::copy(r[j], r[j] + w, rows[j].begin() + y * w);
                        });
    for (int j = 0; j < 4; ++j) expectSameBits(rows[j], textbook(in, w, h, kx, kernels[j]), "rows");
  }
}

}  // namespace
}  // namespace aliaslab
