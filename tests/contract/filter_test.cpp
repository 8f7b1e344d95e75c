// Filter contract tests over every registered filter (allFilterNames(): the
// study's filters, gaussian-cut and the course variants) and a range of radii, with the
// batch evaluator and the importance sampler built beside each, plus the
// published facts about the classic profiles (the Gaussians':
// filter_gaussian_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>
#include <vector>

#include "core/cpu.h"
#include "core/error.h"
#include "core/hash.h"
#include "filter/filter.h"
#include "filter/filter_batch.h"
#include "filter/filter_sampler.h"
#include "filter/filter_simd.h"

namespace aliaslab {
namespace {

// 5-point Gauss-Legendre on [-1, 1]
constexpr double kX[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
constexpr double kW[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                          0.2369268850561891};

/// Composite 5-point Gauss-Legendre of f over [a, b] in `cells` cells.
template <class F>
double gl1(F&& f, double a, double b, int cells) {
  double s = 0, h = (b - a) / cells;
  for (int c = 0; c < cells; ++c)
    for (int k = 0; k < 5; ++k) s += kW[k] * f(a + (c + 0.5) * h + 0.5 * h * kX[k]);
  return s * 0.5 * h;
}

/// 2-D integral of g(f(dx, dy)) over the support: Cartesian product rule on
/// the square, or polar (radius x angle) on the disc; independent of Filter::integral().
/// `cells` per axis: kinks of |f| at sign changes need many.
template <class G>
double quad2(const Filter& f, G&& g, int cells) {
  const double r = f.radius();
  if (f.radial())
    return gl1([&](double rho) {
      return rho * gl1([&](double phi) { return g(f.eval(float(rho * std::cos(phi)), float(rho * std::sin(phi)))); },
                       0, 2 * M_PI, 8);
    }, 0, r, cells);
  return gl1([&](double y) { return gl1([&](double x) { return g(f.eval(float(x), float(y))); }, -r, r, cells); },
             -r, r, cells);
}

using Param = std::tuple<std::string, float>;
class FilterContract : public ::testing::TestWithParam<Param> {
 protected:
  void SetUp() override { filter = makeFilter(std::get<0>(GetParam()), std::get<1>(GetParam())); }
  std::unique_ptr<Filter> filter;
};

TEST_P(FilterContract, ZeroPastRadius) {
  const float r = filter->radius();
  HashRng rng(hashWords(1, r * 1000));
  for (int k = 0; k < 4000; ++k) {
    const float dx = (2 * rng.nextFloat() - 1) * 2 * r, dy = (2 * rng.nextFloat() - 1) * 2 * r;
    const bool outside = filter->radial() ? std::sqrt(dx * dx + dy * dy) > r : (std::abs(dx) > r || std::abs(dy) > r);
    if (outside) {
      EXPECT_EQ(filter->eval(dx, dy), 0.f) << dx << " " << dy;
    }
  }
  EXPECT_EQ(filter->eval(r * 1.0001f, 0), 0.f);
  EXPECT_EQ(filter->eval(0, -r * 1.0001f), 0.f);
}

TEST_P(FilterContract, SymmetricUnderReflectionAndSwap) {
  const float r = filter->radius();
  HashRng rng(hashWords(2, r * 1000));
  for (int k = 0; k < 2000; ++k) {
    const float dx = (2 * rng.nextFloat() - 1) * r, dy = (2 * rng.nextFloat() - 1) * r;
    const float f = filter->eval(dx, dy), tol = 1e-6f;
    EXPECT_NEAR(filter->eval(-dx, dy), f, tol);
    EXPECT_NEAR(filter->eval(dx, -dy), f, tol);
    EXPECT_NEAR(filter->eval(dy, dx), f, tol);
  }
}

TEST_P(FilterContract, EvalBatchEqualsEval) {
  // the film's fast path: n x n centres from one before the first within r (so some lie beyond it)
  // 12 samples: 8 in 8 lanes where the CPU has AVX2, 4 in 4 lanes; 37: padded to 40
  const float r = filter->radius();
  const FilterBatch batch(*filter);
  for (const int count : {12, 37}) {
    const int n = int(std::ceil(2 * r)) + 2, stride = FilterBatch::stride(count);
    std::vector<float> x(stride), y(stride), cx(stride), cy(stride), out(size_t(n) * n * stride);
    HashRng rng(hashWords(4, r * 1000, count));
    for (int s = 0; s < stride; ++s) {
      x[s] = 30 * rng.nextFloat() - 5, y[s] = 30 * rng.nextFloat() - 5;
      cx[s] = std::floor(x[s] - r) - 0.5f, cy[s] = std::floor(y[s] - r) - 0.5f;
    }
    batch.eval(count, x.data(), y.data(), cx.data(), cy.data(), n, out.data());
    for (int s = 0; s < count; ++s)
      for (int b = 0; b < n; ++b)
        for (int a = 0; a < n; ++a) {
          const float e = filter->eval(x[s] - (cx[s] + a), y[s] - (cy[s] + b)), w = out[size_t(b * n + a) * stride + s];
          if (filter->name() == "gaussian" || filter->name() == "gaussian-cut") {
            // per-axis exponentials: a few ulps per unit of the exponent
            EXPECT_NEAR(w, e, e > 0 ? 2.5e-7f * (4 - std::log(e)) * e : 0.f) << s << " " << a << " " << b;
          } else if (filter->name() == "blackmanharris") {
            EXPECT_NEAR(w, e, 1e-6f) << s << " " << a << " " << b;  // Eigen's vectorised cos
          } else {
            EXPECT_EQ(w, e) << s << " " << a << " " << b;  // bit for bit
          }
        }
  }
}

TEST_P(FilterContract, EightLanesGiveTheFourLaneBits) {
  // FilterBatch's 8-lane path (CPUs with AVX2) and its 4-lane path give the same weights, bit for bit, so a
  // study's numbers do not depend on the CPU (the Gaussian included, whose weights are not eval()'s bits)
  if (!cpuFeatures().avx2) GTEST_SKIP() << "no AVX2 on this CPU: only the 4-lane path runs";
  const float r = filter->radius();
  const int n = int(std::ceil(2 * r)) + 2, count = 64, stride = FilterBatch::stride(count);
  const FilterBatch batch(*filter);
  std::vector<float> x(stride), y(stride), cx(stride), cy(stride), eight(size_t(n) * n * stride), four(eight.size());
  HashRng rng(hashWords(5, r * 1000));
  for (int s = 0; s < stride; ++s) {
    x[s] = 30 * rng.nextFloat() - 5, y[s] = 30 * rng.nextFloat() - 5;
    cx[s] = std::floor(x[s] - r) - 0.5f, cy[s] = std::floor(y[s] - r) - 0.5f;
  }
  batch.eval(count, x.data(), y.data(), cx.data(), cy.data(), n, eight.data());
  {
    const ScopedCpuFeatures sseOnly(CpuFeatures{});
    batch.eval(count, x.data(), y.data(), cx.data(), cy.data(), n, four.data());
  }
  size_t differ = 0, nonzero = 0;
  for (size_t k = 0; k < eight.size(); ++k)
    differ += std::memcmp(&eight[k], &four[k], sizeof(float)) != 0, nonzero += four[k] != 0;
  EXPECT_EQ(differ, 0u) << "of " << eight.size();
  EXPECT_GT(nonzero, size_t(count) / 8);  // not all cut to 0 (about (2r)^2 per sample for r < 0.5: 23 at r = 0.3)
}

TEST_P(FilterContract, IntegralMatchesQuadrature) {
  const double q = quad2(*filter, [](double v) { return v; }, 64);
  EXPECT_NEAR(filter->integral(), q, 1e-4 * std::abs(q));
  const double qa = quad2(*filter, [](double v) { return std::abs(v); }, 256);
  EXPECT_NEAR(FilterSampler(*filter).absIntegral(), qa, 1e-4 * qa);
}

TEST_P(FilterContract, UnitWeightsOnlyWhereEvalIsOneOnTheSupport) {
  // the film skips the weights of a unit-weight filter: eval() must be 1 wherever it is not 0
  if (!FilterBatch(*filter).unitWeights()) return;
  const float r = filter->radius();
  HashRng rng(hashWords(6, r * 1000));
  for (int k = 0; k < 2000; ++k) {
    const float dx = (2 * rng.nextFloat() - 1) * r, dy = (2 * rng.nextFloat() - 1) * r, f = filter->eval(dx, dy);
    EXPECT_TRUE(f == 1.f || f == 0.f) << dx << " " << dy;
  }
}

TEST_P(FilterContract, CourseVariantIsARegisteredFilterOfItsOwn) {
  // the classic gather's variant (if any) is made by the registry and has no variant of its own
  const std::unique_ptr<Filter> course = makeCourseVariant(*filter);
  if (!course) return;
  EXPECT_NE(std::find(allFilterNames().begin(), allFilterNames().end(), course->name()), allFilterNames().end());
  EXPECT_EQ(makeCourseVariant(*course), nullptr);
  for (const auto& [key, value] : course->params()) EXPECT_EQ(value, filter->params().at(key)) << key;
}

TEST_P(FilterContract, SampleDensityIsAbsFOverAbsIntegral) {
  // stratified u (300 x 300), 8 x 8 bins over the support square
  const float r = filter->radius();
  const int n = 300, bins = 8;
  const FilterSampler sampler(*filter);
  std::vector<double> hist(bins * bins, 0.0);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      HashRng rng(hashWords(3, a, b));
      const Vec2 u((a + rng.nextFloat()) / n, (b + rng.nextFloat()) / n);
      float w;
      const Vec2 p = sampler.sample(u, w);
      const float f = filter->eval(p.x(), p.y());
      ASSERT_LE(std::abs(p.x()), r);
      ASSERT_LE(std::abs(p.y()), r);
      EXPECT_FLOAT_EQ(std::abs(w), float(sampler.absIntegral()));
      if (f != 0) {
        EXPECT_EQ(w > 0, f > 0) << p.transpose();
      }
      const int bx = std::min(bins - 1, int((p.x() + r) / (2 * r) * bins));
      const int by = std::min(bins - 1, int((p.y() + r) / (2 * r) * bins));
      hist[by * bins + bx] += 1.0 / (n * n);
    }
  // expected bin masses by a 40 x 40 midpoint rule of |f|
  double l1 = 0, total = 0;
  const double cell = 2.0 * r / bins, m = 40;
  std::vector<double> expect(bins * bins);
  for (int by = 0; by < bins; ++by)
    for (int bx = 0; bx < bins; ++bx) {
      double s = 0;
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
          s += std::abs(filter->eval(float(-r + (bx + (i + 0.5) / m) * cell), float(-r + (by + (j + 0.5) / m) * cell)));
      total += expect[by * bins + bx] = s;
    }
  for (int k = 0; k < bins * bins; ++k) l1 += std::abs(hist[k] - expect[k] / total);
  EXPECT_LT(l1, 0.01);
}

TEST_P(FilterContract, DescribeNamesRadiusAndParams) {
  const std::string d = filter->describe();
  EXPECT_EQ(d.rfind(filter->name() + " r=", 0), 0u) << d;
  for (const auto& [key, value] : defaultFilterParams(filter->name())) EXPECT_NE(d.find(" " + key + "="), std::string::npos) << d;
}

INSTANTIATE_TEST_SUITE_P(AllFilters, FilterContract,
                         ::testing::Combine(::testing::ValuesIn(allFilterNames()),
                                            ::testing::Values(0.3f, 0.5f, 1.f, 1.5f, 2.3f, 4.f)),
                         [](const auto& info) {
                           std::string name = std::get<0>(info.param);
                           std::replace(name.begin(), name.end(), '-', '_');  // (test names take no '-')
                           return name + "_r" +
                                  std::to_string(int(std::lround(std::get<1>(info.param) * 10)));
                         });

// 1-D profile facts at the natural support
double minimumOf(const Filter& f, double lo, double hi, double& at) {
  double best = 1e30;
  for (int k = 0; k <= 200000; ++k) {
    const double x = lo + (hi - lo) * k / 200000;
    if (f.profile(float(x)) < best) best = f.profile(float(x)), at = x;
  }
  return best;
}

TEST(FilterFacts, MitchellOneThirdPeakMinimumAndUnitIntegral) {
  auto f = makeFilter("mitchell", 2.f);
  EXPECT_NEAR(f->profile(0), 8.0 / 9.0, 1e-6);
  double at;
  EXPECT_NEAR(minimumOf(*f, 0, 2, at), -0.03628, 5e-5);
  EXPECT_NEAR(at, 10.0 / 7.0, 1e-3);
  EXPECT_NEAR(gl1([&](double x) { return f->profile(float(x)); }, -2, 2, 64), 1.0, 1e-6);
  EXPECT_NEAR(f->integral(), 1.0, 1e-9);
}

TEST(FilterFacts, CatmullRomMinimumIsMinusTwoTwentySevenths) {
  auto f = makeFilter("catmullrom", 2.f);
  double at;
  EXPECT_NEAR(minimumOf(*f, 0, 2, at), -2.0 / 27.0, 1e-5);
  EXPECT_NEAR(at, 4.0 / 3.0, 1e-3);
  EXPECT_NEAR(f->profile(0), 1.0, 1e-6);
}

TEST(FilterFacts, LanczosThreeLobesMinimumAndIntegral) {
  auto f = makeFilter("lanczos", 3.f);
  double at;
  EXPECT_NEAR(minimumOf(*f, 0, 3, at), -0.1473, 1e-4);
  EXPECT_NEAR(gl1([&](double x) { return f->profile(float(x)); }, -3, 3, 64), 0.99706, 1e-5);
  EXPECT_NEAR(std::sqrt(f->integral()), 0.99706, 1e-5);
}

TEST(FilterFacts, MitchellStretchesToRadius) {
  auto f2 = makeFilter("mitchell", 2.f), f5 = makeFilter("mitchell", 5.f);
  for (float x : {0.1f, 0.7f, 1.3f, 1.9f}) EXPECT_NEAR(f5->profile(x * 2.5f), f2->profile(x), 1e-6);
  EXPECT_NEAR(f5->integral(), 6.25, 1e-9);
}

TEST(FilterFacts, BoxTentAndBlackmanHarrisClosedForms) {
  auto box = makeFilter("box", 0.5f), tent = makeFilter("tent", 2.f), bh = makeFilter("blackmanharris", 2.f);
  EXPECT_EQ(box->eval(0.5f, -0.5f), 1.f);  // closed square support
  EXPECT_NEAR(box->integral(), 1.0, 1e-12);
  EXPECT_NEAR(tent->eval(0.6f, 0.8f), 0.5, 1e-6);  // radial cone: d = 1
  EXPECT_NEAR(tent->integral(), M_PI * 4 / 3, 1e-9);
  EXPECT_NEAR(bh->profile(0), 1.0, 1e-6);
  EXPECT_NEAR(bh->profile(2), 0.00006, 1e-6);
}

// Factory errors
std::string optionOf(const std::function<void()>& fn, std::string* message = nullptr) {
  try {
    fn();
  } catch (const OptionError& e) {
    if (message) *message = e.what();
    return e.key();
  }
  return "";
}

namespace {
[[gnu::target("avx2")]] void exp8(const float* in, float* out) { filterimpl::store8(out, filterimpl::exp8(filterimpl::load8(in))); }
[[gnu::target("avx2")]] void cos8(const float* in, float* out) { filterimpl::store8(out, filterimpl::cos8(filterimpl::load8(in))); }

/// How many of `in` (padded with `pad` to a multiple of 8) `eight` maps to other bits than Eigen's 4-lane `four`.
template <class Four>
size_t differFromFourLanes(std::vector<float> in, float pad, void (*eight)(const float*, float*), Four four) {
  while (in.size() % 8) in.push_back(pad);
  std::vector<float> fast(in.size());
  for (size_t k = 0; k < in.size(); k += 8) eight(&in[k], &fast[k]);
  size_t differ = 0;
  for (size_t k = 0; k < in.size(); k += 4) {
    const filterimpl::Lanes ref = four(filterimpl::lanes(&in[k]));
    for (int l = 0; l < 4; ++l) differ += std::memcmp(&ref[l], &fast[k + l], sizeof(float)) != 0;
  }
  return differ;
}
}  // namespace

TEST(FilterFacts, EightLaneCosIsEigensFourLaneCosBitForBit) {
  // the Blackman-Harris batch (FilterBatch) must give the same bits with and without AVX2: inputs from -200 to 200 in
  // steps of about 1e-4 (every octant and both polynomials, the multiples of pi/2), random floats of every
  // exponent up to 1e38, both sides of Eigen's huge threshold (18838) in one group of 8 and apart, and
  // zeros, infinities and NaN
  if (!cpuFeatures().avx2) GTEST_SKIP() << "no AVX2 on this CPU: the 8-lane path is not used";
  std::vector<float> in;
  for (double v = -200; v < 200; v += 1.03e-4) in.push_back(float(v));
  HashRng rng(77);
  for (int k = 0; k < 400000; ++k)
    in.push_back((rng.nextFloat() < 0.5f ? -1.f : 1.f) * std::ldexp(1.f + rng.nextFloat(), int(rng.nextFloat() * 250) - 124));
  for (float v : {0.f, -0.f, 18837.998f, 18838.f, 18838.002f, -18838.f, 1e-30f, 2.5e5f, 1.5707964f, 3.1415927f, 4.712389f,
                  INFINITY, -INFINITY, NAN, 1e38f, -1e38f})
    in.push_back(v);
  EXPECT_EQ(differFromFourLanes(in, 0.5f, cos8, [](const filterimpl::Lanes& v) { return filterimpl::Lanes(v.cos()); }), 0u)
      << "of " << in.size();
}

TEST(FilterFacts, EightLaneExpIsEigensFourLaneExpBitForBit) {
  // the Gaussian's batch (FilterBatch) must give the same bits with and without AVX2: every input from -110 (results
  // below float's normal range, the 2^m split of pldexp) to 100 in steps of about 1e-4, and the clamps
  if (!cpuFeatures().avx2) GTEST_SKIP() << "no AVX2 on this CPU: the 8-lane path is not used";
  std::vector<float> in;
  for (double v = -110; v < 100; v += 1.01e-4) in.push_back(float(v));
  for (float v : {0.f, -0.f, 88.723f, -88.723f, 89.f, -89.f, -87.33654f, 1e-30f, -1e-30f, 1e30f, -1e30f}) in.push_back(v);
  EXPECT_EQ(differFromFourLanes(in, 0.f, exp8, [](const filterimpl::Lanes& v) { return filterimpl::Lanes(v.exp()); }), 0u)
      << "of " << in.size();
}

TEST(FilterFactory, UnknownNameListsValidNames) {
  std::string msg;
  EXPECT_EQ(optionOf([] { makeFilter("gauss", 1); }, &msg), "filter");
  for (const auto& n : filterNames()) EXPECT_NE(msg.find(n), std::string::npos) << msg;
}

TEST(FilterFactory, RadiusMustBeFiniteAndPositive) {
  for (float r : {0.f, -1.f, NAN, INFINITY}) EXPECT_EQ(optionOf([r] { makeFilter("tent", r); }), "radius") << r;
}

TEST(FilterFactory, MisspeltParameterIsNamed) {
  std::string msg;
  EXPECT_EQ(optionOf([] { makeFilter("gaussian", 1.5f, {{"sigmaa", 0.4}}); }, &msg), "filter-param");
  EXPECT_NE(msg.find("'sigmaa' is not a parameter of gaussian (valid: sigma, subtract_edge)"), std::string::npos) << msg;
  EXPECT_EQ(optionOf([] { makeFilter("box", 1, {{"tau", 3}}); }, &msg), "filter-param");
  EXPECT_NE(msg.find("valid: none"), std::string::npos) << msg;
}

TEST(FilterFactory, OutOfRangeParametersRejected) {
  EXPECT_EQ(optionOf([] { makeFilter("gaussian", 1, {{"sigma", -0.5}}); }), "filter-param");
  EXPECT_EQ(optionOf([] { makeFilter("gaussian", 1, {{"sigma", 0}}); }), "");  // 0: r / 3
  EXPECT_EQ(optionOf([] { makeFilter("gaussian-cut", 1, {{"sigma", 0}}); }), "filter-param");
  EXPECT_EQ(optionOf([] { makeFilter("gaussian-cut", 1, {{"subtract_edge", 2}}); }), "filter-param");
  EXPECT_EQ(optionOf([] { makeFilter("gaussian", 1, {{"sigma", NAN}}); }), "filter-param");
  EXPECT_EQ(optionOf([] { makeFilter("gaussian", 1, {{"subtract_edge", 0.5}}); }), "filter-param");
  EXPECT_EQ(optionOf([] { makeFilter("lanczos", 1, {{"tau", 0.5}}); }), "filter-param");
  EXPECT_EQ(optionOf([] { makeFilter("hann", 1, {{"tau", 0.99}}); }), "filter-param");
  EXPECT_EQ(optionOf([] { makeFilter("lanczos", 2, {{"tau", 2}}); }), "");
}

TEST(FilterFactory, NamesInDocumentedOrder) {
  const std::vector<std::string> expected = {"box", "tent", "gaussian", "mitchell", "catmullrom", "lanczos", "hann", "blackmanharris"};
  EXPECT_EQ(filterNames(), expected);
  std::vector<std::string> all = expected;
  all.push_back("gaussian-cut");  // not one of the study's filters
  all.push_back("course-gaussian");
  EXPECT_EQ(allFilterNames(), all);
  for (const auto& n : allFilterNames()) EXPECT_EQ(makeFilter(n, 1)->name(), n);
}

}  // namespace
}  // namespace aliaslab
