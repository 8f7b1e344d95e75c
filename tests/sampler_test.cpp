// Sampler contract tests, instantiated over every registered name (a new
// sampler is covered the day it is added), plus the stratification /
// net / digit structure each pattern promises, checked by counting points
// in exact intervals (floor(x * k) on the float value, exact in double).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "sampling/sample_math.h"
#include "sampling/sampler.h"

using namespace aliaslab;

namespace {

const int kCounts[] = {1, 2, 3, 4, 7, 8, 9, 16, 64};
const Vec2 kSentinel(-7.f, -7.f);

std::vector<Vec2> pixel(const Sampler& s, int px, int py) {
  std::vector<Vec2> v(s.spp());
  s.generate(px, py, v.data());
  return v;
}

bool isPow2(int n) { return (n & (n - 1)) == 0; }

/// Index of the interval of width 1/k holding x (exact: x is a float, k small).
long cellOf(float x, long k) { return static_cast<long>(std::floor(static_cast<double>(x) * k)); }

/// Every 2^a x 2^b elementary interval with a + b = log2(n) holds exactly one of pts[0..n).
::testing::AssertionResult isZeroTwoNet(const std::vector<Vec2>& pts, int n) {
  int k = 0;
  while ((1 << k) < n) ++k;
  for (int a = 0; a <= k; ++a) {
    std::vector<int> count(n, 0);
    for (int i = 0; i < n; ++i) ++count[cellOf(pts[i].y(), 1L << (k - a)) * (1L << a) + cellOf(pts[i].x(), 1L << a)];
    for (int c = 0; c < n; ++c)
      if (count[c] != 1)
        return ::testing::AssertionFailure() << "interval " << c << " of shape " << (1 << a) << "x" << (1 << (k - a))
                                             << " holds " << count[c] << " of " << n << " points";
  }
  return ::testing::AssertionSuccess();
}

/// Each interval of width base^-j holds floor or ceil of n / base^j points (radical inverse property).
::testing::AssertionResult isRadicalInverseBalanced(const std::vector<float>& v, int base) {
  const long n = static_cast<long>(v.size());
  for (long width = base; width <= 4096; width *= base) {
    std::map<long, long> count;
    for (float x : v) ++count[cellOf(x, width)];
    for (long c = 0; c < width; ++c) {
      const long got = count.count(c) ? count[c] : 0;
      if (got != n / width && got != (n + width - 1) / width)
        return ::testing::AssertionFailure() << "1/" << width << " interval " << c << " holds " << got << " of " << n;
    }
  }
  return ::testing::AssertionSuccess();
}

/// Pearson correlation of two series.
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= n, mb /= n;
  double sab = 0, saa = 0, sbb = 0;
  for (size_t i = 0; i < a.size(); ++i)
    sab += (a[i] - ma) * (b[i] - mb), saa += (a[i] - ma) * (a[i] - ma), sbb += (b[i] - mb) * (b[i] - mb);
  return sab / std::sqrt(saa * sbb);
}

class SamplerContract : public ::testing::TestWithParam<std::string> {};

// ---------------------------------------------------------------------------
TEST_P(SamplerContract, WritesExactlySppPointsInsideUnitSquare) {
  for (int spp : kCounts) {
    auto s = makeSampler(GetParam(), spp, 7);
    ASSERT_EQ(s->spp(), spp);
    EXPECT_EQ(s->name(), GetParam());
    EXPECT_FALSE(s->describe().empty());
    for (int p = 0; p < 64; ++p) {
      std::vector<Vec2> buf(spp + 4, kSentinel);
      s->generate(p % 8 - 3, p / 8 + 1000, buf.data());
      for (int i = spp; i < spp + 4; ++i) ASSERT_EQ(buf[i], kSentinel) << "wrote past spp=" << spp;
      for (int i = 0; i < spp; ++i) {
        ASSERT_GE(buf[i].x(), 0.f);
        ASSERT_LT(buf[i].x(), 1.f);
        ASSERT_GE(buf[i].y(), 0.f);
        ASSERT_LT(buf[i].y(), 1.f);
      }
    }
  }
}

TEST_P(SamplerContract, PurePerPixelFunctionOfSeed) {
  // Pixels in raster order from one instance == reverse order from a fresh one.
  for (int spp : kCounts) {
    auto a = makeSampler(GetParam(), spp, 11);
    auto b = makeSampler(GetParam(), spp, 11);
    std::vector<std::vector<Vec2>> forward;
    for (int p = 0; p < 20; ++p) forward.push_back(pixel(*a, p % 5, p / 5));
    for (int p = 19; p >= 0; --p) ASSERT_EQ(pixel(*b, p % 5, p / 5), forward[p]) << "spp " << spp << " pixel " << p;
    ASSERT_EQ(pixel(*a, 3, 2), forward[13]);  // regenerating later changes nothing
  }
}

TEST_P(SamplerContract, NeighbouringPixelsAndSeedsGiveDifferentSets) {
  const bool deterministic = GetParam() == "uniform";
  for (int spp : kCounts) {
    auto s = makeSampler(GetParam(), spp, 3);
    auto t = makeSampler(GetParam(), spp, 4);
    for (int p = 0; p < 16; ++p) {
      const auto here = pixel(*s, p, 5);
      EXPECT_EQ(here != pixel(*s, p + 1, 5), !deterministic) << "spp " << spp;
      EXPECT_EQ(here != pixel(*s, p, 6), !deterministic) << "spp " << spp;
      EXPECT_EQ(here != pixel(*t, p, 5), !deterministic) << "seed, spp " << spp;
    }
  }
}

TEST_P(SamplerContract, NeighbourPixelMeansUncorrelated) {
  // Pixel means of x (and y) in horizontally adjacent pixels: |r| < 5 / sqrt(pairs).
  if (GetParam() == "uniform") GTEST_SKIP() << "uniform is the same in every pixel by design";
  for (int spp : {1, 7, 16}) {
    auto s = makeSampler(GetParam(), spp, 5);
    const int w = 100, h = 40;
    std::vector<double> mx(w * h), my(w * h);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        for (const Vec2& v : pixel(*s, i, j)) mx[j * w + i] += v.x() / spp, my[j * w + i] += v.y() / spp;
      }
    std::vector<double> ax, bx, ay, by;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i + 1 < w; i += 2)
        ax.push_back(mx[j * w + i]), bx.push_back(mx[j * w + i + 1]), ay.push_back(my[j * w + i]),
            by.push_back(my[j * w + i + 1]);
    const double bound = 5.0 / std::sqrt(static_cast<double>(ax.size()));
    EXPECT_LT(std::abs(correlation(ax, bx)), bound) << "x, spp " << spp;
    EXPECT_LT(std::abs(correlation(ay, by)), bound) << "y, spp " << spp;
  }
}

TEST_P(SamplerContract, CoordinateMeansAreOneHalf) {
  // Over P pixels the grand mean is within 5 standard errors (from the spread of pixel means) of 1/2.
  for (int spp : kCounts) {
    auto s = makeSampler(GetParam(), spp, 9);
    const int pixels = 4000;
    std::vector<double> mx, my;
    for (int p = 0; p < pixels; ++p) {
      double sx = 0, sy = 0;
      for (const Vec2& v : pixel(*s, p % 80, p / 80)) sx += v.x(), sy += v.y();
      mx.push_back(sx / spp), my.push_back(sy / spp);
    }
    for (const auto* m : {&mx, &my}) {
      double mean = 0, var = 0;
      for (double v : *m) mean += v / pixels;
      for (double v : *m) var += (v - mean) * (v - mean) / (pixels - 1);
      EXPECT_NEAR(mean, 0.5, 5 * std::sqrt(var / pixels) + 1e-6) << "spp " << spp;
      // A pixel mean can never be more spread than one uniform point (variance 1/12).
      EXPECT_LT(var, 1.0 / 12 * 1.2) << "spp " << spp;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllSamplers, SamplerContract, ::testing::ValuesIn(samplerNames()),
                         [](const auto& info) { return info.param; });

// ---------------------------------------------------------------------------
TEST(SamplerFactory, NamesInDocumentedOrder) {
  const std::vector<std::string> expected = {"random", "uniform",    "jittered", "nrooks", "multijittered", "cmj",
                                             "halton", "hammersley", "sobol",    "pmj02",  "bluenoise"};
  EXPECT_EQ(samplerNames(), expected);
}

TEST(SamplerFactory, UnknownNameListsEveryValidName) {
  try {
    makeSampler("jitterd", 4, 0);
    FAIL() << "no error";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "--sampler");
    const std::string what = e.what();
    EXPECT_NE(what.find("'jitterd'"), std::string::npos);
    for (const std::string& n : samplerNames()) EXPECT_NE(what.find(n), std::string::npos) << n;
  }
}

TEST(SamplerFactory, NonPositiveSppThrows) {
  for (const std::string& n : samplerNames()) {
    for (int spp : {0, -3}) {
      try {
        makeSampler(n, spp, 0);
        FAIL() << n << " accepted spp " << spp;
      } catch (const OptionError& e) {
        EXPECT_EQ(e.option(), "--spp");
      }
    }
  }
}

TEST(SamplerFactory, GridShapeIsMostSquareFactorisation) {
  const int expect[][3] = {{1, 1, 1}, {2, 1, 2}, {3, 1, 3}, {4, 2, 2}, {7, 1, 7}, {8, 2, 4},
                           {9, 3, 3}, {12, 3, 4}, {16, 4, 4}, {18, 3, 6}, {64, 8, 8}, {97, 1, 97}};
  for (const auto& e : expect) {
    int m, n;
    gridShape(e[0], m, n);
    EXPECT_EQ(m, e[1]) << e[0];
    EXPECT_EQ(n, e[2]) << e[0];
  }
}

TEST(SamplerFactory, WarningsExactlyForUnnaturalCounts) {
  for (int spp : kCounts) {
    const bool square = static_cast<int>(std::lround(std::sqrt(spp))) * static_cast<int>(std::lround(std::sqrt(spp))) == spp;
    for (const char* grid : {"uniform", "jittered", "multijittered", "cmj"})
      EXPECT_EQ(makeSampler(grid, spp, 0)->warning().empty(), square) << grid << " " << spp;
    for (const char* seq : {"sobol", "pmj02"}) {
      const std::string w = makeSampler(seq, spp, 0)->warning();
      EXPECT_EQ(w.empty(), isPow2(spp)) << seq << " " << spp;
      if (!w.empty()) {
        EXPECT_NE(w.find("power of two"), std::string::npos);
      }
    }
    for (const char* any : {"random", "nrooks", "halton", "hammersley", "bluenoise"})
      EXPECT_TRUE(makeSampler(any, spp, 0)->warning().empty()) << any;
  }
  EXPECT_NE(makeSampler("jittered", 8, 0)->describe().find("2x4"), std::string::npos);
}

// ---------------------------------------------------------------------------
// Structure of particular patterns, over many pixels.
constexpr int kPixels = 64;

TEST(SamplerStructure, UniformIsTheGridOfCellCentres) {
  const auto byRow = [](const Vec2& a, const Vec2& b) { return a.y() < b.y() || (a.y() == b.y() && a.x() < b.x()); };
  for (int spp : kCounts) {
    int m, n;
    gridShape(spp, m, n);
    auto s = makeSampler("uniform", spp, 1);
    for (int p = 0; p < 4; ++p) {
      auto pts = pixel(*s, p, 3 * p);
      std::sort(pts.begin(), pts.end(), byRow);
      for (int i = 0; i < spp; ++i) {
        EXPECT_NEAR(pts[i].x(), (i % m + 0.5) / m, 1e-6) << "spp " << spp;
        EXPECT_NEAR(pts[i].y(), (i / m + 0.5) / n, 1e-6) << "spp " << spp;
      }
    }
  }
}

TEST(SamplerStructure, OnePointPerGridCell) {
  for (const char* name : {"jittered", "multijittered", "cmj"})
    for (int spp : kCounts) {
      int m, n;
      gridShape(spp, m, n);
      auto s = makeSampler(name, spp, 21);
      for (int p = 0; p < kPixels; ++p) {
        std::vector<int> count(spp, 0);
        for (const Vec2& v : pixel(*s, p, -p)) ++count[cellOf(v.y(), n) * m + cellOf(v.x(), m)];
        for (int c : count) ASSERT_EQ(c, 1) << name << " spp " << spp << " pixel " << p;
      }
    }
}

TEST(SamplerStructure, LatinHypercubeOnePointPerRowAndColumn) {
  for (const char* name : {"nrooks", "multijittered", "cmj"})
    for (int spp : kCounts) {
      auto s = makeSampler(name, spp, 22);
      for (int p = 0; p < kPixels; ++p) {
        std::vector<int> cols(spp, 0), rows(spp, 0);
        for (const Vec2& v : pixel(*s, 2 * p, p)) ++cols[cellOf(v.x(), spp)], ++rows[cellOf(v.y(), spp)];
        for (int i = 0; i < spp; ++i) {
          ASSERT_EQ(cols[i], 1) << name << " spp " << spp << " column " << i;
          ASSERT_EQ(rows[i], 1) << name << " spp " << spp << " row " << i;
        }
      }
    }
}

TEST(SamplerStructure, ElementaryIntervalsAtPowersOfTwo) {
  // Every elementary interval of area 1/N holds one point, N = 1 .. 256; and
  // for spp 256 every power-of-two prefix is a net too (the sequences are progressive).
  for (const char* name : {"sobol", "pmj02", "hammersley"})
    for (int n = 1; n <= 256; n *= 2) {
      auto s = makeSampler(name, n, 23);
      for (int p = 0; p < kPixels; ++p) {
        const auto pts = pixel(*s, p, 7);
        ASSERT_TRUE(isZeroTwoNet(pts, n)) << name << " N " << n << " pixel " << p;
        if (n < 256 || std::string(name) == "hammersley") continue;
        for (int prefix = 1; prefix < n; prefix *= 2) ASSERT_TRUE(isZeroTwoNet(pts, prefix)) << name << " prefix " << prefix;
      }
    }
}

TEST(SamplerStructure, RandomPointsAreNotANet) {
  // The net check can fail: independent points almost never form a (0,4,2)-net.
  auto s = makeSampler("random", 16, 1);
  int nets = 0;
  for (int p = 0; p < kPixels; ++p) nets += isZeroTwoNet(pixel(*s, p, 0), 16) ? 1 : 0;
  EXPECT_EQ(nets, 0);
}

TEST(SamplerStructure, RadicalInverseDigitBalance) {
  // x (base 2) of halton, sobol, y (base 2) of hammersley and sobol, y (base 3) of halton:
  // the first N indices fill each b^-j interval with floor or ceil of N / b^j points.
  for (int spp : {1, 2, 3, 7, 9, 16, 27, 64, 100}) {
    auto halton = makeSampler("halton", spp, 24), hammersley = makeSampler("hammersley", spp, 24),
         sobol = makeSampler("sobol", spp, 24);
    for (int p = 0; p < kPixels; ++p) {
      std::vector<float> hx, hy, mx, my, sx, sy;
      for (const Vec2& v : pixel(*halton, p, 1)) hx.push_back(v.x()), hy.push_back(v.y());
      for (const Vec2& v : pixel(*hammersley, p, 1)) mx.push_back(v.x()), my.push_back(v.y());
      for (const Vec2& v : pixel(*sobol, p, 1)) sx.push_back(v.x()), sy.push_back(v.y());
      ASSERT_TRUE(isRadicalInverseBalanced(hx, 2)) << "halton x spp " << spp;
      ASSERT_TRUE(isRadicalInverseBalanced(hy, 3)) << "halton y spp " << spp;
      ASSERT_TRUE(isRadicalInverseBalanced(my, 2)) << "hammersley y spp " << spp;
      ASSERT_TRUE(isRadicalInverseBalanced(sx, 2)) << "sobol x spp " << spp;
      ASSERT_TRUE(isRadicalInverseBalanced(sy, 2)) << "sobol y spp " << spp;
      // Hammersley x = (i + u) / N: one point in each 1/N column.
      std::vector<int> cols(spp, 0);
      for (float x : mx) ++cols[cellOf(x, spp)];
      for (int c : cols) ASSERT_EQ(c, 1) << "hammersley spp " << spp;
    }
  }
}

TEST(SamplerStructure, HaltonBoxesOfSize2aBy3b) {
  // N = 2^a 3^b points: every 2^-a x 3^-b box holds exactly one (Chinese remainder theorem).
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{{1, 1}, {2, 1}, {1, 2}, {2, 2}, {3, 2}, {4, 2}, {2, 3}}) {
    const int ca = 1 << a, cb = static_cast<int>(std::lround(std::pow(3, b))), n = ca * cb;
    auto s = makeSampler("halton", n, 25);
    for (int p = 0; p < kPixels; ++p) {
      std::vector<int> count(n, 0);
      for (const Vec2& v : pixel(*s, p, p)) ++count[cellOf(v.y(), cb) * ca + cellOf(v.x(), ca)];
      for (int c : count) ASSERT_EQ(c, 1) << "N " << n << " pixel " << p;
    }
  }
}

/// Mean over pixels of the smallest toroidal distance between two points of a pixel.
double meanMinTorusDistance(const Sampler& s, int pixels) {
  double sum = 0;
  for (int p = 0; p < pixels; ++p) {
    const auto pts = pixel(s, p, 2);
    double best = 2;
    for (size_t i = 0; i < pts.size(); ++i)
      for (size_t j = i + 1; j < pts.size(); ++j) {
        const double dx = std::abs(pts[i].x() - pts[j].x()), dy = std::abs(pts[i].y() - pts[j].y());
        best = std::min(best, std::hypot(std::min(dx, 1 - dx), std::min(dy, 1 - dy)));
      }
    sum += best;
  }
  return sum / pixels;
}

TEST(SamplerStructure, BlueNoiseKeepsPointsApart) {
  // N uniform points have a closest pair at distance O(1/N) (mean about 0.71/N on the torus);
  // a well-spread set keeps it Theta(1/sqrt N): require 0.3/sqrt(N), and check random fails it.
  for (int spp : {16, 64, 256}) {
    const double bound = 0.3 / std::sqrt(spp);
    EXPECT_GT(meanMinTorusDistance(*makeSampler("bluenoise", spp, 26), kPixels), bound) << spp;
    EXPECT_LT(meanMinTorusDistance(*makeSampler("random", spp, 26), kPixels), bound) << spp;
  }
}

TEST(SamplerMath, KenslerPermuteIsABijectionAndDivisorIsExact) {
  for (uint32_t n = 1; n <= 300; ++n) {
    const sampling::Divisor d(n);
    for (uint32_t a : {0u, 1u, n - 1, n, 12345u, 0x7fffffffu, 0xfffffffeu, 0xffffffffu}) {
      ASSERT_EQ(d.div(a), a / n) << a << " / " << n;
      ASSERT_EQ(d.mod(a), a % n) << a << " % " << n;
    }
    for (uint32_t p : {0u, 0x9e3779b9u, 0xdeadbeefu}) {
      std::vector<int> hit(n, 0);
      for (uint32_t i = 0; i < n; ++i) {
        const uint32_t v = sampling::kenslerPermute(i, n, p);
        ASSERT_LT(v, n);
        ASSERT_EQ(v, sampling::kenslerPermute(i, d, p));
        ++hit[v];
      }
      for (int h : hit) ASSERT_EQ(h, 1) << "n " << n;
    }
  }
}

TEST(SamplerStructure, Pmj02RefusesHugeCounts) {
  EXPECT_THROW(makeSampler("pmj02", (1 << 16) + 1, 0), OptionError);
}

}  // namespace
