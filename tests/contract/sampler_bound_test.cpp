// Every registered sampler's claimed variance bound (Sampler::varianceBound, docs/science.md "What the samplers
// guarantee") on integrands chosen to reach it, with the pixels of one seed as independent replicates (every
// bounded pattern is independent across pixels): Var(mean over the N points) <= c sigma^2 / N within 3 standard
// errors. The integrands: the Walsh functions w_ab(x, y) = (-1)^(x_a + y_b) (x_a the a-th binary digit of x; a = 0:
// no x factor), each a single gain coefficient of a base-2 scrambled net (Owen 1997: for nested uniform scrambling
// Var = Gamma_ab / N with every Gamma <= 2 for a (0,m,2)-net; this is where a hash-based scramble would show a gain
// above 2); the negative control's grating with sqrt(N) cycles per pixel (jittered exactly at its bound); a disc.
// Sobol's gains one by one against nested uniform scrambling's. And the progressive samplers (Sampler::progressive): the pattern at n is the first n points of the pattern at
// any larger count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "sampling/sampler.h"

namespace aliaslab {
namespace {

struct Integrand {
  std::string name;
  std::function<double(double, double)> f;
  double mean, variance;  ///< over the unit square
};

int digit(double x, int a) { return a == 0 ? 0 : static_cast<int>(std::floor(x * std::ldexp(1.0, a))) & 1; }

std::vector<Integrand> integrands(int n) {
  std::vector<Integrand> out;
  for (int a = 0; a <= 8; ++a)
    for (int b = 0; b <= 8; ++b)
      if (a + b > 0)
        out.push_back({"walsh(" + std::to_string(a) + "," + std::to_string(b) + ")",
                       [a, b](double x, double y) { return (digit(x, a) ^ digit(y, b)) ? -1.0 : 1.0; }, 0, 1});
  const double k = std::sqrt(double(n));
  if (k == std::floor(k))
    out.push_back({"grating", [k](double x, double) { return 0.5 + 0.5 * std::cos(2 * M_PI * k * x); }, 0.5, 0.125});
  out.push_back({"disc", [](double x, double y) { return x * x + y * y < 2 / M_PI ? 1.0 : 0.0; }, 0.5, 0.25});
  return out;
}

TEST(SamplerBound, EveryClaimedBoundHoldsOnItsHardestIntegrands) {
  const int side = 96;  // 9216 pixels: independent replicates of the pixel's estimate
  int checked = 0;
  for (const std::string& name : allSamplerNames())
    for (int n : {4, 8, 16, 32, 64}) {
      const auto s = makeSampler(name, n, 7);
      const double c = s->varianceBound();
      if (!(c > 0)) continue;
      std::vector<Vec2> pts(n);
      const auto fs = integrands(n);
      std::vector<double> sum(fs.size(), 0), sum2(fs.size(), 0);
      for (int py = 0; py < side; ++py)
        for (int px = 0; px < side; ++px) {
          s->generate(px, py, pts.data());
          for (size_t i = 0; i < fs.size(); ++i) {
            double m = 0;
            for (const Vec2& p : pts) m += fs[i].f(p.x(), p.y());
            const double e = m / n - fs[i].mean, e2 = e * e;
            sum[i] += e2, sum2[i] += e2 * e2;
          }
        }
      const double P = double(side) * side;
      double worst = 0;
      std::string at;
      for (size_t i = 0; i < fs.size(); ++i) {
        const double var = sum[i] / P, se = std::sqrt(std::max(0.0, sum2[i] / P - var * var) / P);
        const double gain = var * n / fs[i].variance;  // Var as a multiple of sigma^2 / N
        if (gain > worst) worst = gain, at = fs[i].name;
        EXPECT_LE(var, c * fs[i].variance / n + 3 * se) << name << " at " << n << " on " << fs[i].name
                                                         << ": gain " << gain << ", bound " << c;
      }
      std::printf("%s at %d: largest Var / (sigma^2/N) = %.3f (%s), bound %.4g\n", name.c_str(), n, worst,
                  at.c_str(), c);
      ++checked;
    }
  EXPECT_GE(checked, 3 * 3);  // random, jittered, nrooks at every count; sobol at the powers of two
}

// The hash-based Owen scramble against the theory of nested uniform scrambling, gain by gain: for a (0,m,2)-net in
// base 2 the Walsh function w_ab has gain 0 when a + b <= m (the net integrates it exactly), 2 on a + b = m + 1 with
// a, b >= 1, and 1 beyond (and 1 for a one-dimensional w at m + 1): Var = gain sigma^2 / N, sigma^2 = 1.
TEST(SamplerBound, SobolGainsAreThoseOfNestedUniformScrambling) {
  const int side = 96;
  for (int m : {4, 6}) {
    const int n = 1 << m;
    const auto s = makeSampler("sobol", n, 11);
    std::vector<Vec2> pts(n);
    std::vector<double> sum(81, 0), sum2(81, 0);
    for (int py = 0; py < side; ++py)
      for (int px = 0; px < side; ++px) {
        s->generate(px, py, pts.data());
        for (int a = 0; a <= 8; ++a)
          for (int b = 0; b <= 8; ++b) {
            double mean = 0;
            for (const Vec2& p : pts) mean += (digit(p.x(), a) ^ digit(p.y(), b)) ? -1.0 : 1.0;
            const double g = mean * mean / n;  // (mean / n)^2 * n: one replicate of the gain
            sum[a * 9 + b] += g, sum2[a * 9 + b] += g * g;
          }
      }
    const double P = double(side) * side;
    for (int a = 0; a <= 8; ++a)
      for (int b = 0; b <= 8; ++b) {
        if (a + b == 0) continue;
        const double expected = a + b <= m ? 0.0 : (a + b == m + 1 && a > 0 && b > 0) ? 2.0 : 1.0;
        const double gain = sum[a * 9 + b] / P, se = std::sqrt(std::max(0.0, sum2[a * 9 + b] / P - gain * gain) / P);
        EXPECT_NEAR(gain, expected, 3 * se + 1e-9) << "N = " << n << ", w(" << a << "," << b << ")";
      }
  }
}

TEST(SamplerBound, ProgressivePatternsArePrefixes) {
  int progressive = 0;
  for (const std::string& name : samplerNames()) {
    const auto big = makeSampler(name, 64, 3);
    if (!big->progressive()) continue;
    ++progressive;
    std::vector<Vec2> all(64), some(16);
    for (int p = 0; p < 4; ++p) {
      big->generate(p, 2 * p, all.data());
      for (int n : {1, 4, 5, 16}) {
        makeSampler(name, n, 3)->generate(p, 2 * p, some.data());
        for (int i = 0; i < n; ++i) ASSERT_TRUE((some[i] == all[i])) << name << " point " << i << " of " << n;
      }
    }
  }
  EXPECT_GE(progressive, 4);  // random, halton, sobol, pmj02
}

}  // namespace
}  // namespace aliaslab
