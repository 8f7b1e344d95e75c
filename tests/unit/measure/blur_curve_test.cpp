// The blur curve (measure/spectrum.h, docs/science.md "The blur curve"): for white noise of per-pixel variance v,
// a blur by the normalised kernel w leaves variance v sum w^2. Here w is the blur the accumulator applies (the
// Gaussian transfer function exp(-2 pi^2 s^2 rho^2) on the W x H DFT grid, a circular convolution); its
// spatial weights are computed independently by a direct inverse DFT, and sum w^2 from them. The random sampler
// on the positive-control scene (every pixel the same function, so the same variance; errors independent between
// pixels) must give blurred/unblurred ratios equal to sum w^2 within three standard errors, at sigma 0.5 to 4.
#include <gtest/gtest.h>

#include <cmath>

#include "accel/aggregate.h"
#include "aliaslab_paths.h"
#include "measure/spectrum.h"
#include "render/render.h"
#include "scene/scene.h"

namespace aliaslab {
namespace {

/// sum of w(x, y)^2 with w the inverse DFT of exp(-2 pi^2 s^2 rho^2) on an n x n grid (rho of the wrapped index).
double kernelSquares(double sigma, int n) {
  const double pi = std::acos(-1.0);
  auto h = [&](int u) {  // separable: exp(-2 pi^2 s^2 (fu^2 + fv^2)) = H(fu) H(fv)
    const double f = (u < (n + 1) / 2 ? u : u - n) / static_cast<double>(n);
    return std::exp(-2 * pi * pi * sigma * sigma * f * f);
  };
  double line = 0;  // sum over x of w1(x)^2, w1 the 1-D kernel; the 2-D kernel is w1(x) w1(y)
  for (int x = 0; x < n; ++x) {
    double re = 0;
    for (int u = 0; u < n; ++u) re += h(u) * std::cos(2 * pi * u * x / n) / n;
    line += re * re;
  }
  return line * line;
}

TEST(BlurCurve, KernelOfTheTransferFunction) {
  // the independent sums against known values: sum w = H(0) = 1, and sum w^2 near 1 / (4 pi s^2) for s >= 1
  for (double s : {1.0, 2.0, 4.0}) EXPECT_NEAR(kernelSquares(s, 64) * 4 * std::acos(-1.0) * s * s, 1.0, 0.01) << s;
  // at 0.5 the transfer function is cut at Nyquist (|f| <= 1/2), which removes a little of the continuous value
  EXPECT_LT(kernelSquares(0.5, 64), 1 / (4 * std::acos(-1.0) * 0.25));
  EXPECT_GT(kernelSquares(0.5, 64), 0.9 / (4 * std::acos(-1.0) * 0.25));
}

TEST(BlurCurve, WhiteNoiseMatchesTheKernelsSquares) {
  Scene scene = parseScene(std::string(ALIASLAB_SOURCE_DIR) + "/scenes/controls/same_pixel.txt");
  const auto aggregate = makeBruteForce(*scene.root);
  const Tracer tracer(scene, *aggregate, TraceOptions{});
  const int size = 32, spp = 4, seeds = 64;
  const Image exact(size, size, Color::Constant(0.5f));
  SpectrumAccumulator acc({&exact, nullptr}, {{&exact, nullptr}});
  const auto box = makeFilter("box", 0.5f);
  for (int k = 0; k < seeds; ++k)
    acc.add(reconstruct(traceSamples(tracer, *makeSampler("random", spp, 40 + k), size, size, 2), *box,
                        ReconMode::WeightedAverage, 1).image);
  const SpectrumTargetMetrics m = acc.result().targets[0];
  for (size_t s = 0; s < kBlurCurve.size(); ++s) {
    const double want = kernelSquares(kBlurCurve[s], size);
    std::printf("sigma %.1f: ratio %.5f +- %.5f, sum w^2 %.5f\n", kBlurCurve[s], m.blurRatio[s], m.blurRatioSe[s], want);
    EXPECT_GT(m.blurRatioSe[s], 0);
    EXPECT_NEAR(m.blurRatio[s], want, 3 * m.blurRatioSe[s]) << "sigma " << kBlurCurve[s];
  }
}

}  // namespace
}  // namespace aliaslab
