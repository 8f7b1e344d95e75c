// Sampler contract tests, instantiated over every registered name (a new
// sampler is covered the day it is added), plus the stratification /
// net / digit structure each pattern promises, checked by counting points
// in exact intervals (floor(x * k) on the float value, exact in double).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <complex>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/hash.h"
#include "sampling/bluenoise_mask.h"
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
  // the grids repeat one set in every pixel: uniform's for every seed, uniform-shifted's shifted per seed
  const bool deterministic = GetParam() == "uniform", samePerPixel = deterministic || GetParam() == "uniform-shifted";
  for (int spp : kCounts) {
    auto s = makeSampler(GetParam(), spp, 3);
    auto t = makeSampler(GetParam(), spp, 4);
    for (int p = 0; p < 16; ++p) {
      const auto here = pixel(*s, p, 5);
      EXPECT_EQ(here != pixel(*s, p + 1, 5), !samePerPixel) << "spp " << spp;
      EXPECT_EQ(here != pixel(*s, p, 6), !samePerPixel) << "spp " << spp;
      EXPECT_EQ(here != pixel(*t, p, 5), !deterministic) << "seed, spp " << spp;
    }
  }
}

TEST_P(SamplerContract, NeighbourPixelMeansUncorrelated) {
  // Pixel means of x (and y) in horizontally adjacent pixels: |r| < 5 / sqrt(pairs).
  if (GetParam() == "uniform") GTEST_SKIP() << "uniform is the same in every pixel by design";
  if (makeSampler(GetParam(), 1, 5)->correlatedAcrossPixels())
    GTEST_SKIP() << "correlated across pixels by design (SamplerCorrelation checks how)";
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
  // uniform-shifted's pixels of one seed are one set: its P pixels come from P seeds.
  const bool seedPerPixel = GetParam() == "uniform-shifted";
  for (int spp : kCounts) {
    auto s = makeSampler(GetParam(), spp, 9);
    const int pixels = 4000;
    std::vector<double> mx, my;
    for (int p = 0; p < pixels; ++p) {
      double sx = 0, sy = 0;
      if (seedPerPixel) s = makeSampler(GetParam(), spp, 9 + p);
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

INSTANTIATE_TEST_SUITE_P(AllSamplers, SamplerContract, ::testing::ValuesIn(allSamplerNames()),
                         [](const auto& info) {
                           std::string n = info.param;  // "bluenoise-dither:sobol" -> "bluenoise_dither_sobol"
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

// ---------------------------------------------------------------------------
TEST(SamplerFactory, NamesInDocumentedOrder) {
  const std::vector<std::string> expected = {"random", "uniform",    "uniform-shifted", "jittered", "nrooks",
                                             "multijittered", "cmj", "halton", "hammersley", "sobol", "pmj02",
                                             "bluenoise", "zsobol"};
  EXPECT_EQ(samplerNames(), expected);
  EXPECT_EQ(samplerWrapperNames(), std::vector<std::string>{"bluenoise-dither"});
  // every plain name, then the wrapper over every plain name
  ASSERT_EQ(allSamplerNames().size(), 2 * expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(allSamplerNames()[i], expected[i]);
    EXPECT_EQ(allSamplerNames()[expected.size() + i], "bluenoise-dither:" + expected[i]);
  }
}

TEST(SamplerFactory, WrapperNamesNeedOnePlainBase) {
  for (const char* bad : {"bluenoise-dither", "bluenoise-dither:", "bluenoise-dither:sobl",
                          "bluenoise-dither:bluenoise-dither:sobol", "dither:sobol", ":sobol"}) {
    try {
      makeSampler(bad, 4, 0);
      FAIL() << "accepted " << bad;
    } catch (const OptionError& e) {
      EXPECT_EQ(e.key(), "sampler") << bad;
      EXPECT_NE(std::string(e.what()).find("bluenoise-dither:BASE"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(makeSampler("bluenoise-dither:sobol", 0, 0), OptionError);
  EXPECT_EQ(makeSampler("bluenoise-dither:sobol", 4, 0)->name(), "bluenoise-dither:sobol");
}

TEST(SamplerFactory, UnknownNameListsEveryValidName) {
  try {
    makeSampler("jitterd", 4, 0);
    FAIL() << "no error";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.key(), "sampler");
    const std::string what = e.what();
    EXPECT_NE(what.find("'jitterd'"), std::string::npos);
    for (const std::string& n : samplerNames()) EXPECT_NE(what.find(n), std::string::npos) << n;
  }
}

TEST(SamplerFactory, NonPositiveSppThrows) {
  for (const std::string& n : allSamplerNames()) {
    for (int spp : {0, -3}) {
      try {
        makeSampler(n, spp, 0);
        FAIL() << n << " accepted spp " << spp;
      } catch (const OptionError& e) {
        EXPECT_EQ(e.key(), "spp");
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
    for (const char* grid : {"uniform", "uniform-shifted", "jittered", "multijittered", "cmj"})
      EXPECT_EQ(makeSampler(grid, spp, 0)->warning().empty(), square) << grid << " " << spp;
    for (const char* seq : {"sobol", "pmj02", "zsobol", "bluenoise-dither:sobol"}) {
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

TEST(SamplerStructure, UniformShiftedIsTheGridShiftedByOneOffsetPerSeed) {
  // In every pixel of a seed the m x n grid shifted by one offset (ox, oy) in [0, 1/m) x [0, 1/n); across seeds
  // the offsets differ and cover the cell (each of 4 x 4 sub-cells of the offset cell hit by 256 seeds).
  const auto byRow = [](const Vec2& a, const Vec2& b) { return a.y() < b.y() || (a.y() == b.y() && a.x() < b.x()); };
  for (int spp : {1, 4, 8, 9, 16}) {
    int m, n;
    gridShape(spp, m, n);
    std::vector<int> hits(16, 0);
    std::vector<Vec2> offsets;
    for (int seed = 0; seed < 256; ++seed) {
      auto s = makeSampler("uniform-shifted", spp, seed);
      const auto first = pixel(*s, 0, 0);
      auto pts = first;
      std::sort(pts.begin(), pts.end(), byRow);
      const double ox = pts[0].x(), oy = pts[0].y();
      ASSERT_GE(ox, 0.0);
      ASSERT_LT(ox, 1.0 / m);
      ASSERT_GE(oy, 0.0);
      ASSERT_LT(oy, 1.0 / n);
      for (int i = 0; i < spp; ++i) {
        EXPECT_NEAR(pts[i].x(), ox + double(i % m) / m, 1e-6) << "spp " << spp << " seed " << seed;
        EXPECT_NEAR(pts[i].y(), oy + double(i / m) / n, 1e-6) << "spp " << spp << " seed " << seed;
      }
      for (int p = 1; p < 6; ++p) ASSERT_EQ(pixel(*s, 7 * p - 11, 3 * p + 100), first) << "spp " << spp;
      ++hits[cellOf(float(oy * n), 4) * 4 + cellOf(float(ox * m), 4)];
      offsets.push_back(Vec2(float(ox), float(oy)));
    }
    for (int h : hits) EXPECT_GT(h, 0) << "spp " << spp;
    std::sort(offsets.begin(), offsets.end(), byRow);
    EXPECT_EQ(std::adjacent_find(offsets.begin(), offsets.end()), offsets.end()) << "spp " << spp;
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
  for (const char* name : {"sobol", "pmj02", "hammersley", "zsobol"})
    for (int n = 1; n <= 256; n *= 2) {
      auto s = makeSampler(name, n, 23);
      for (int p = 0; p < kPixels; ++p) {
        const auto pts = pixel(*s, p, 7);
        ASSERT_TRUE(isZeroTwoNet(pts, n)) << name << " N " << n << " pixel " << p;
        if (n < 256 || std::string(name) == "hammersley" || std::string(name) == "zsobol") continue;
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


// ---------------------------------------------------------------------------
// Samplers correlated across pixels (zsobol, bluenoise-dither).

/// All points of the `side` x `side` pixels from (x0, y0), overlaid (sub-pixel offsets only).
std::vector<Vec2> blockUnion(const Sampler& s, int x0, int y0, int side) {
  std::vector<Vec2> all;
  for (int y = y0; y < y0 + side; ++y)
    for (int x = x0; x < x0 + side; ++x)
      for (const Vec2& v : pixel(s, x, y)) all.push_back(v);
  return all;
}

TEST(SamplerCorrelation, ZSobolAlignedPixelBlocksFormNets) {
  // An aligned 2^j x 2^j block at spp = 2^k is an aligned block of 4^j 2^k Sobol' points: a
  // (0, 2j + k, 2)-net. Covers 2x2 blocks at 4 spp and 4x4 blocks at 16 spp (and 1 .. 16 spp generally).
  for (int spp : {1, 2, 4, 8, 16})
    for (int side : {2, 4})
      for (uint64_t seed : {1u, 2u}) {
        auto s = makeSampler("zsobol", spp, seed);
        for (int b = 0; b < 24; ++b) {
          const int x0 = side * (b % 6) + (b < 12 ? 0 : 64), y0 = side * (b / 6) + (b < 12 ? 0 : 1000 - 1000 % side);
          const auto pts = blockUnion(*s, x0, y0, side);
          ASSERT_TRUE(isZeroTwoNet(pts, static_cast<int>(pts.size())))
              << "spp " << spp << " block " << side << "x" << side << " at " << x0 << "," << y0;
        }
      }
}

TEST(SamplerCorrelation, IndependentSamplersDoNotFillNeighbourGaps) {
  // The block check can fail: sobol's per-pixel scrambles (and bluenoise-dither, whose pixels share one
  // set shifted by a mask) almost never make a 2x2 block at 4 spp a (0,4,2)-net.
  for (const char* name : {"sobol", "bluenoise-dither:sobol"}) {
    auto s = makeSampler(name, 4, 3);
    int nets = 0;
    for (int b = 0; b < 32; ++b) nets += isZeroTwoNet(blockUnion(*s, 2 * b, 6, 2), 16) ? 1 : 0;
    EXPECT_LE(nets, 3) << name;
  }
}

TEST(SamplerCorrelation, ZSobolNonPowerOfTwoTakesDistinctStrataOfItsBlock) {
  // spp = 3 uses 3 of the 4 points of a (0,2,2)-net: three different quadrants; spp = 6 (block of 8,
  // two aligned pairs and one more): the two pairs are (0,1,2)-nets, so no 1/8 column holds two points
  // of the 8-net subset.
  auto three = makeSampler("zsobol", 3, 4), six = makeSampler("zsobol", 6, 4);
  for (int p = 0; p < kPixels; ++p) {
    std::vector<int> quadrant(4, 0), column(8, 0);
    for (const Vec2& v : pixel(*three, p, 2 * p)) ++quadrant[cellOf(v.y(), 2) * 2 + cellOf(v.x(), 2)];
    for (int q : quadrant) ASSERT_LE(q, 1) << "pixel " << p;
    for (const Vec2& v : pixel(*six, p, 2 * p)) ++column[cellOf(v.x(), 8)];
    for (int c : column) ASSERT_LE(c, 1) << "pixel " << p;
  }
}

TEST(SamplerCorrelation, NeighbourMeansAntiCorrelate) {
  // At 1 spp the four pixels of an aligned 2x2 block hold a (0,2,2)-net (zsobol), or points shifted by
  // blue-noise ranks (bluenoise-dither): horizontally adjacent pixels' x anti-correlate, r < -0.2
  // (zsobol) and r < -0.1 (dither: a void-and-cluster mask's neighbours, reduced by the wrap-around of
  // the shift); independent pixels have sd 1 / sqrt(2048 pairs) = 0.022, so -0.1 is 4.5 sd away.
  for (const char* name : {"zsobol", "bluenoise-dither:random", "bluenoise-dither:jittered"}) {
    const double bound = std::string(name) == "zsobol" ? -0.2 : -0.1;
    auto s = makeSampler(name, 1, 5);
    ASSERT_TRUE(s->correlatedAcrossPixels());
    std::vector<double> a, b;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; x += 2) a.push_back(pixel(*s, x, y)[0].x()), b.push_back(pixel(*s, x + 1, y)[0].x());
    EXPECT_LT(correlation(a, b), bound) << name;
  }
  EXPECT_FALSE(makeSampler("sobol", 1, 5)->correlatedAcrossPixels());
}

TEST(SamplerCorrelation, DitherSharesOneSetShiftedPerPixel) {
  // Every pixel holds the same set up to one toroidal shift: point i minus point 0 (mod 1) is the same
  // in every pixel, to the 2^-24 resolution of the coordinates.
  auto s = makeSampler("bluenoise-dither:jittered", 16, 6);
  const auto first = pixel(*s, 0, 0);
  const auto wrapDiff = [](double a, double b) { return a - b - std::floor(a - b); };
  for (int p = 1; p < kPixels; ++p) {
    const auto pts = pixel(*s, 3 * p, p + 40);
    for (size_t i = 1; i < pts.size(); ++i) {
      for (int c : {0, 1}) {
        const double d = wrapDiff(pts[i][c], pts[0][c]) - wrapDiff(first[i][c], first[0][c]);
        ASSERT_LT(std::min(std::abs(d), 1 - std::abs(d)), 3e-7) << "pixel " << p << " point " << i;
      }
    }
  }
}

TEST(SamplerCorrelation, DitherShiftsAreTheMaskRanks) {
  // dither:uniform at 1 spp: x = frac(1/2 + ux + rank_x / 4096), so over one 64x64 tile the 1/4096
  // columns holding x are a permutation (one each), and the same for y; the next tile repeats them.
  auto s = makeSampler("bluenoise-dither:uniform", 1, 8);
  std::vector<int> cx(4096, 0), cy(4096, 0);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const Vec2 v = pixel(*s, x + 128, y - 64)[0];
      ++cx[cellOf(v.x(), 4096)], ++cy[cellOf(v.y(), 4096)];
      ASSERT_EQ(v, pixel(*s, x, y)[0]);
    }
  for (int i = 0; i < 4096; ++i) {
    ASSERT_EQ(cx[i], 1) << "x column " << i;
    ASSERT_EQ(cy[i], 1) << "y row " << i;
  }
}

/// Fraction of the power of a kMaskSize^2 mask (mean removed) at radial frequency below 1/8 cycle per
/// pixel (a quarter of Nyquist), by a direct 2-D DFT (an independent computation, not lib/measure).
double maskLowFrequencyFraction(const std::vector<double>& v) {
  const int n = sampling::kMaskSize;
  double mean = 0;
  for (double x : v) mean += x / v.size();
  std::vector<std::complex<double>> rows(v.size()), f(v.size());
  const double tau = 2 * std::acos(-1.0);
  for (int y = 0; y < n; ++y)
    for (int u = 0; u < n; ++u)
      for (int x = 0; x < n; ++x) rows[y * n + u] += (v[y * n + x] - mean) * std::polar(1.0, -tau * u * x / n);
  double low = 0, total = 0;
  for (int w = 0; w < n; ++w)
    for (int u = 0; u < n; ++u) {
      std::complex<double> sum = 0;
      for (int y = 0; y < n; ++y) sum += rows[y * n + u] * std::polar(1.0, -tau * w * y / n);
      const double fu = (u < n / 2 ? u : u - n) / static_cast<double>(n), fw = (w < n / 2 ? w : w - n) / static_cast<double>(n);
      total += std::norm(sum);
      if (std::hypot(fu, fw) < 0.125) low += std::norm(sum);
    }
  return low / total;
}

TEST(SamplerCorrelation, VoidAndClusterMaskIsABlueNoisePermutation) {
  // Every rank once per tile; the power below a quarter of Nyquist under 0.1 % of the total (measured 1.3e-5 to 1.5e-5). A white-noise
  // permutation puts about pi (1/8)^2 = 4.9 % there (the disc's share of the frequency square), and
  // must fail the bound (the check can fail).
  for (uint64_t seed : {0u, 1u, 2u})
    for (int channel : {0, 1}) {
      const auto mask = sampling::blueNoiseMask(seed, channel);
      ASSERT_EQ(mask->size(), 4096u);
      std::vector<int> seen(4096, 0);
      for (uint16_t r : *mask) ++seen.at(r);
      for (int c : seen) ASSERT_EQ(c, 1);
      const double low = maskLowFrequencyFraction(std::vector<double>(mask->begin(), mask->end()));
      EXPECT_LT(low, 0.001) << "seed " << seed << " channel " << channel;
      RecordProperty("low_fraction_" + std::to_string(seed) + "_" + std::to_string(channel), std::to_string(low));
      EXPECT_EQ(sampling::blueNoiseMask(seed, channel), mask) << "cached: built once";
    }
  EXPECT_NE(*sampling::blueNoiseMask(0, 0), *sampling::blueNoiseMask(1, 0));
  EXPECT_NE(*sampling::blueNoiseMask(0, 0), *sampling::blueNoiseMask(0, 1));
  std::vector<double> white(4096);
  for (int i = 0; i < 4096; ++i) white[i] = i;
  HashRng rng(99);
  for (int i = 4095; i > 0; --i) std::swap(white[i], white[rng.nextBelow(i + 1)]);
  const double whiteLow = maskLowFrequencyFraction(white);
  EXPECT_GT(whiteLow, 0.03);
  EXPECT_LT(whiteLow, 0.07);
}

}  // namespace
