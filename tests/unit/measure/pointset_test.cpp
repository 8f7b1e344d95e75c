// Point-set measures against independent computations on the same points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/hash.h"
#include "measure/pointset.h"

namespace aliaslab {
namespace {

std::vector<Vec2> uniformPoints(int n, uint64_t seed) {
  HashRng rng(seed);
  std::vector<Vec2> pts(n);
  for (Vec2& p : pts) p = Vec2(rng.nextFloat(), rng.nextFloat());
  return pts;
}

// m x m points at the cell centres ((i + 0.5) / m, (j + 0.5) / m).
std::vector<Vec2> regularGrid(int m) {
  std::vector<Vec2> pts;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) pts.emplace_back((i + 0.5f) / m, (j + 0.5f) / m);
  return pts;
}

// Exact integral over anchors a in [0,1]^2 of (#{x_i < a} / N - a_x a_y)^2:
// the count is constant on the cells of the grid of sorted coordinates, and
// each cell's integral of the polynomial is exact.
double discrepancySquaredByCells(const std::vector<Vec2>& pts) {
  std::vector<double> xs = {0.0, 1.0}, ys = {0.0, 1.0};
  for (const Vec2& p : pts) xs.push_back(p.x()), ys.push_back(p.y());
  std::sort(xs.begin(), xs.end());
  std::sort(ys.begin(), ys.end());
  const double n = static_cast<double>(pts.size());
  double total = 0.0;
  for (size_t a = 0; a + 1 < xs.size(); ++a)
    for (size_t b = 0; b + 1 < ys.size(); ++b) {
      const double u0 = xs[a], u1 = xs[a + 1], v0 = ys[b], v1 = ys[b + 1];
      if (u1 <= u0 || v1 <= v0) continue;
      int count = 0;
      for (const Vec2& p : pts) count += (p.x() <= u0 && p.y() <= v0);
      const double c = count / n;
      total += c * c * (u1 - u0) * (v1 - v0) - 2.0 * c * (u1 * u1 - u0 * u0) / 2.0 * (v1 * v1 - v0 * v0) / 2.0 +
               (u1 * u1 * u1 - u0 * u0 * u0) / 3.0 * (v1 * v1 * v1 - v0 * v0 * v0) / 3.0;
    }
  return total;
}

TEST(L2StarDiscrepancy, WarnockEqualsExactIntegralOverAnchorBoxes) {
  for (int n : {1, 2, 7, 64}) {
    const auto pts = uniformPoints(n, 17 + n);
    const double warnock = l2StarDiscrepancySquared(pts);
    EXPECT_NEAR(warnock, discrepancySquaredByCells(pts), 1e-12 + 1e-9 * warnock) << "N = " << n;
  }
}

// Warnock's formula in exact integer arithmetic for dyadic points x = X / 2^k
// (k <= 24, N <= 1024): 18 N^2 2^(4k) D^2 = 2 N^2 2^(4k) - 9 N sum_i A_i
// + 18 2^(2k) sum_ij B_ij with A_i = (2^2k - X_i^2)(2^2k - Y_i^2) and
// B_ij = (2^k - max X)(2^k - max Y); every quantity fits in 128 bits.
double discrepancySquaredExact(const std::vector<Vec2>& pts, int k) {
  using I = __int128;
  const I one = I(1) << k, n = static_cast<I>(pts.size());
  std::vector<I> X, Y;
  for (const Vec2& p : pts) X.push_back(static_cast<I>(std::ldexp(double(p.x()), k))), Y.push_back(static_cast<I>(std::ldexp(double(p.y()), k)));
  for (size_t i = 0; i < pts.size(); ++i) {  // the points really are dyadic with k bits
    EXPECT_EQ(std::ldexp(double(X[i]), -k), double(pts[i].x()));
    EXPECT_EQ(std::ldexp(double(Y[i]), -k), double(pts[i].y()));
  }
  I sumA = 0, sumB = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    sumA += (one * one - X[i] * X[i]) * (one * one - Y[i] * Y[i]);
    for (size_t j = 0; j < pts.size(); ++j) sumB += (one - std::max(X[i], X[j])) * (one - std::max(Y[i], Y[j]));
  }
  const I one4 = one * one * one * one;
  const I num = 2 * n * n * one4 - 9 * n * sumA + 18 * one * one * sumB;
  // num >= 0 and < 2^113: split into two doubles to keep 106 bits before dividing
  const I hiPart = (num >> 60) << 60;
  const long double value = (static_cast<long double>(hiPart) + static_cast<long double>(num - hiPart)) /
                            (18.0L * static_cast<long double>(n * n) * static_cast<long double>(one4));
  return static_cast<double>(value);
}

// Hammersley points (i / N, radical inverse of i): dyadic with log2 N bits, and
// of low discrepancy, so Warnock's three terms cancel to ~1e-6 of 1/9.
std::vector<Vec2> hammersley(int n) {
  std::vector<Vec2> pts;
  for (int i = 0; i < n; ++i) {
    unsigned r = 0;
    for (int b = 1, v = i; b < n; b <<= 1, v >>= 1) r = (r << 1) | (v & 1);
    pts.emplace_back(float(i) / n, float(r) / n);
  }
  return pts;
}

TEST(L2StarDiscrepancy, AgreesWithExactRationalArithmeticTo1e9) {
  // Issue 16: the plain double sums were off by up to 2e-6 relative at N = 1024.
  for (int n : {16, 256, 1024}) {
    const auto pts = hammersley(n);
    const int k = static_cast<int>(std::lround(std::log2(n)));
    const double exact = discrepancySquaredExact(pts, k);
    EXPECT_NEAR(l2StarDiscrepancySquared(pts), exact, 1e-9 * exact) << "Hammersley N = " << n;
  }
  // Stratified points with 24-bit coordinates (jittered m x m, and Hammersley
  // jittered inside its cells): the plain double sums were off by 1e-8 to 3e-8 relative.
  for (int m : {4, 16, 32}) {
    const int n = m * m;
    auto pts = uniformPoints(2 * n, 90 + n);
    std::vector<Vec2> jittered, shifted;
    const auto ham = hammersley(n);
    for (int i = 0; i < n; ++i) {
      const float u = pts[2 * i].x(), v = pts[2 * i].y(), s = pts[2 * i + 1].x(), t = pts[2 * i + 1].y();
      auto bits24 = [](double x) { return static_cast<float>(std::floor(x * 16777216.0) / 16777216.0); };
      jittered.emplace_back(bits24((i % m + u) / m), bits24((i / m + v) / m));
      shifted.emplace_back(bits24(ham[i].x() + double(s) / n), bits24(ham[i].y() + double(t) / n));
    }
    for (const auto* set : {&jittered, &shifted}) {
      const double exact = discrepancySquaredExact(*set, 24);
      EXPECT_NEAR(l2StarDiscrepancySquared(*set), exact, 1e-9 * exact)
          << (set == &jittered ? "jittered" : "jittered Hammersley") << " N = " << n;
    }
  }
}

TEST(L2StarDiscrepancy, SinglePointAtOriginHasClosedForm) {
  // One point at 0: the count is 1 everywhere, D^2 = int (1 - a b)^2 = 1 - 1/2 + 1/9.
  EXPECT_NEAR(l2StarDiscrepancySquared({Vec2(0.f, 0.f)}), 1.0 - 0.5 + 1.0 / 9.0, 1e-12);
}

TEST(L2StarDiscrepancy, RandomPointsHaveExpectedSquare5Over36N) {
  // For N independent uniform points E D^2 = (2^-d - 3^-d) / N = 5 / (36 N) in 2-D.
  const int n = 32, sets = 400;
  double mean = 0.0;
  for (int s = 0; s < sets; ++s) mean += l2StarDiscrepancySquared(uniformPoints(n, 500 + s)) / sets;
  EXPECT_NEAR(mean, 5.0 / (36.0 * n), 0.1 * 5.0 / (36.0 * n));
}

TEST(MinToroidalDistance, RegularGridIsOneOverM) {
  for (int m : {2, 5, 8, 16}) EXPECT_NEAR(minToroidalDistance(regularGrid(m)), 1.0 / m, 1e-6) << "m = " << m;
}

TEST(MinToroidalDistance, WrapsAroundTheEdges) {
  // 0.05 and 0.95 are 0.1 apart across the edge, not 0.9.
  EXPECT_NEAR(minToroidalDistance({Vec2(0.05f, 0.5f), Vec2(0.95f, 0.5f), Vec2(0.5f, 0.05f)}), 0.1, 1e-6);
  EXPECT_NEAR(idealPackingDistance(1), std::sqrt(2.0 / std::sqrt(3.0)), 1e-12);
}

TEST(Periodogram, RegularGridPeaksAtMultiplesOfSqrtN) {
  // sum_j exp(-2 pi i k . x_j) over an m x m grid is +-N when m divides kx and ky, else 0.
  const int m = 8, n = m * m;
  Periodogram p(3 * m);
  p.add(regularGrid(m));
  for (int ky = -3 * m; ky <= 3 * m; ++ky)
    for (int kx = -3 * m; kx <= 3 * m; ++kx) {
      const bool peak = kx % m == 0 && ky % m == 0;
      EXPECT_NEAR(p.at(kx, ky), peak ? n : 0.0, 1e-6 * n) << "k = (" << kx << ", " << ky << ")";
    }
}

TEST(Periodogram, UniformRandomPointsHaveFlatUnitSpectrum) {
  // E P(k) = 1 for k != 0; the mean of 256 sets has a standard error of ~1/16 per frequency.
  Periodogram p(8);
  for (int s = 0; s < 256; ++s) p.add(uniformPoints(32, 1000 + s));
  EXPECT_NEAR(p.at(0, 0), 32.0, 1e-9);
  const auto radial = radialSpectrum(p);
  for (size_t r = 1; r < radial.size(); ++r) EXPECT_NEAR(radial[r], 1.0, 0.15) << "r = " << r;
}

TEST(Periodogram, RadialSpectrumOfGridCountsPeaksInTheirAnnulus) {
  // Ring r = m holds the 4 axis peaks (power N) among the frequencies with |k| rounding to m.
  const int m = 4;
  Periodogram p(2 * m);
  p.add(regularGrid(m));
  const auto radial = radialSpectrum(p);
  int ring = 0;
  for (int ky = -2 * m; ky <= 2 * m; ++ky)
    for (int kx = -2 * m; kx <= 2 * m; ++kx)
      ring += static_cast<int>(std::floor(std::sqrt(double(kx * kx + ky * ky)) + 0.5)) == m;
  EXPECT_NEAR(radial[m], 4.0 * m * m / ring, 1e-6);
  EXPECT_NEAR(radial[1], 0.0, 1e-6);
}

}  // namespace
}  // namespace aliaslab
