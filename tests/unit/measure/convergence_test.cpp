// Analytic integrands, the RMSE estimator and the log-log slope fitter.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/hash.h"
#include "sampling/sampler.h"
#include "measure/convergence.h"

namespace aliaslab {
namespace {

// Midpoint rule on a k x k grid: mean of f and of f^2.
void midpointMoments(const Integrand& f, int k, double& mean, double& meanSquare) {
  mean = meanSquare = 0.0;
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const double v = f.f((i + 0.5) / k, (j + 0.5) / k);
      mean += v, meanSquare += v * v;
    }
  mean /= double(k) * k, meanSquare /= double(k) * k;
}

TEST(Integrands, ExactValuesMatchQuadratureAndScience) {
  // Values as printed in docs/science.md, then checked by independent quadrature.
  const std::vector<std::pair<double, double>> science = {
      {0.5, 0.5}, {0.5, 0.5}, {0.318310, 0.4658}, {0.557746, 0.2161}, {0.25, 0.2205}};
  ASSERT_EQ(integrands().size(), science.size());
  for (size_t i = 0; i < science.size(); ++i) {
    const Integrand& f = integrands()[i];
    double mean, meanSquare;
    midpointMoments(f, 3000, mean, meanSquare);
    const double tol = f.discontinuous ? 2e-4 : 1e-7;
    EXPECT_NEAR(f.exact, mean, tol) << f.name;
    EXPECT_NEAR(f.sigma, std::sqrt(meanSquare - mean * mean), 5 * tol) << f.name;
    EXPECT_NEAR(f.exact, science[i].first, 5e-7) << f.name;
    EXPECT_NEAR(f.sigma, science[i].second, 5e-5) << f.name;
  }
}

TEST(ConvergenceRmse, RandomSamplingAtNEqualsOneHasRmseSigma) {
  // RMSE of one uniform point is sigma; with R realisations its relative standard error is below 1/sqrt(R).
  const int r = 20000;
  for (int n : {1, 16}) {
    auto sampler = makeSampler("random", n, 7);
    const auto rmse = convergenceRmse(*sampler, integrands(), r, 2);
    for (size_t i = 0; i < rmse.size(); ++i) {
      const double expected = integrands()[i].sigma / std::sqrt(double(n));
      EXPECT_NEAR(rmse[i], expected, 3.0 * expected / std::sqrt(double(r)))
          << integrands()[i].name << " N = " << n;
    }
  }
}

TEST(ConvergenceRmse, IndependentOfThreadCount) {
  auto sampler = makeSampler("random", 8, 3);
  EXPECT_EQ(convergenceRmse(*sampler, integrands(), 300, 1), convergenceRmse(*sampler, integrands(), 300, 2));
}

// Approximately Gaussian noise from the sum of 12 uniforms (mean 0, variance 1).
double gaussianNoise(HashRng& rng) {
  double s = -6.0;
  for (int i = 0; i < 12; ++i) s += rng.nextDouble();
  return s;
}

TEST(SlopeFit, ExactPowerLawGivesItsExponent) {
  std::vector<double> n, y;
  for (int k = 0; k <= 12; ++k) n.push_back(std::ldexp(1.0, k)), y.push_back(0.3 * std::pow(n.back(), -0.75));
  const SlopeFit fit = fitLogLogSlope(n, y, 1, 4096);
  EXPECT_NEAR(fit.slope, -0.75, 1e-12);
  EXPECT_NEAR(std::exp(fit.intercept), 0.3, 1e-12);
  EXPECT_NEAR(fit.slopeError, 0.0, 1e-12);
  EXPECT_EQ(fit.points, 13);
}

TEST(SlopeFit, RecoversKnownSlopesFromNoisyData) {
  // 10 % multiplicative noise; the slope error over 13 points spanning 2^12 is ~0.008.
  HashRng rng(42);
  for (double slope : {-0.5, -0.75, -1.0, -1.5}) {
    std::vector<double> n, y;
    for (int k = 0; k <= 12; ++k) {
      n.push_back(std::ldexp(1.0, k));
      y.push_back(2.0 * std::pow(n.back(), slope) * std::exp(0.1 * gaussianNoise(rng)));
    }
    const SlopeFit fit = fitLogLogSlope(n, y, 1, 4096);
    EXPECT_NEAR(fit.slope, slope, 0.04) << slope;
    EXPECT_GT(fit.slopeError, 0.002);
    EXPECT_LT(std::abs(fit.slope - slope), 5 * fit.slopeError + 1e-3) << slope;
  }
}

TEST(SlopeFit, UsesOnlyTheStatedRangeAndPowersOfTwo) {
  // Slope -1 inside [16, 1024] at powers of two; a different law outside and at non-powers.
  std::vector<double> n = {1, 2, 4, 16, 32, 48, 64, 100, 256, 1024, 4096};
  std::vector<double> y;
  for (double v : n) {
    const bool inside = v >= 16 && v <= 1024 && (v == 16 || v == 32 || v == 64 || v == 256 || v == 1024);
    y.push_back(inside ? 1.0 / v : 5.0 * std::pow(v, -0.2));
  }
  EXPECT_NEAR(fitLogLogSlope(n, y, 16, 1024, true).slope, -1.0, 1e-12);
  EXPECT_THROW(fitLogLogSlope({4, 4}, {1, 2}, 1, 10), std::invalid_argument);
  EXPECT_THROW(fitLogLogSlope({4}, {1}, 1, 10), std::invalid_argument);
}

TEST(ExpectedSlope, FollowsScience) {
  const auto& fs = integrands();
  EXPECT_EQ(*expectedSlope("random", fs[3]).slope, -0.5);
  EXPECT_EQ(*expectedSlope("jittered", fs[0]).slope, -0.75);
  EXPECT_EQ(*expectedSlope("jittered", fs[4]).slope, -1.0);
  EXPECT_EQ(*expectedSlope("sobol", fs[3]).slope, -1.5);
  EXPECT_EQ(*expectedSlope("pmj02", fs[2]).slope, -0.75);
  EXPECT_FALSE(expectedSlope("no-such-sampler", fs[0]).slope.has_value());
}

}  // namespace
}  // namespace aliaslab
