// The Gaussians' facts: gaussian's width follows the radius (sigma = r / 3
// unless sigma is given), gaussian-cut keeps a fixed sigma and only cuts, the
// edge term, the course's uncut variant, and the blur against the pixel-area
// target (box r = 0.5) growing with the radius. The contract every filter
// keeps (support, symmetry, batch, integral, sampling) is filter_test.cpp's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "filter/filter.h"

namespace aliaslab {
namespace {

/// The filter's normalised weights on an n x n midpoint grid over its support square, and the offsets.
struct Weights {
  std::vector<double> x, w;  ///< x offset and weight per grid point (y does not enter below)
};
Weights weights(const Filter& f, int n = 400) {
  Weights out;
  const double r = f.radius(), h = 2 * r / n;
  double sum = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -r + (i + 0.5) * h, y = -r + (j + 0.5) * h, v = f.eval(float(x), float(y));
      if (v != 0) out.x.push_back(x), out.w.push_back(v), sum += v;
    }
  for (double& v : out.w) v /= sum;
  return out;
}

/// The filter's frequency response at `cycles` per pixel along x: sum w cos(2 pi cycles x) (1 at 0).
double response(const Filter& f, double cycles) {
  const Weights g = weights(f);
  double s = 0;
  for (size_t k = 0; k < g.x.size(); ++k) s += g.w[k] * std::cos(2 * M_PI * cycles * g.x[k]);
  return s;
}

/// A vertical step edge (1 right of x = 8.3) over a row of 16 pixels, reconstructed by the filter from the
/// continuous image (the limit of many samples): pixel i's value is the weight right of the edge.
std::vector<double> stepEdge(const Filter& f) {
  const Weights g = weights(f);
  std::vector<double> row(16, 0.0);
  for (int i = 0; i < 16; ++i)
    for (size_t k = 0; k < g.x.size(); ++k) row[i] += i + 0.5 + g.x[k] >= 8.3 ? g.w[k] : 0;
  return row;
}

/// mean (G - A)^2 over the row: the blur against the pixel-area target A.
double stepBlur(const Filter& f) {
  const std::vector<double> g = stepEdge(f);
  double s = 0;
  for (int i = 0; i < 16; ++i) {
    const double area = std::clamp(i + 1 - 8.3, 0.0, 1.0);  // the pixel's covered fraction
    s += (g[i] - area) * (g[i] - area) / 16;
  }
  return s;
}

TEST(GaussianFacts, WidthFollowsTheRadius) {
  EXPECT_EQ(defaultFilterRadius("gaussian"), 1.5);
  EXPECT_EQ(defaultFilterRadius("gaussian", {{"sigma", 0.4}}), 3 * 0.4);  // a given sigma: 3 sigma
  EXPECT_EQ(defaultFilterRadius("gaussian-cut"), 1.5);
  const auto natural = makeFilter("gaussian", 1.5f);
  for (float r : {0.5f, 1.f, 2.f, 3.f}) {
    const auto g = makeFilter("gaussian", r);
    EXPECT_NEAR(g->params().at("sigma"), r / 3.0, 1e-12) << r;
    for (float x : {0.f, 0.2f, 0.7f, 1.1f, 1.45f})  // the natural profile stretched to r
      EXPECT_NEAR(g->profile(x * r / 1.5f), natural->profile(x), 1e-5) << r << " " << x;
    const double s = r / 3.0, er = std::exp(-4.5);  // cut at 3 sigma
    EXPECT_NEAR(g->integral(), 2 * M_PI * s * s * (1 - er), 1e-6 * s * s) << r;
  }
  EXPECT_EQ(makeFilter("gaussian", 1.f)->describe(), "gaussian r=1 sigma=0.3333 subtract_edge=0");
  EXPECT_EQ(makeFilter("gaussian", 2.f, {{"sigma", 0.4}})->describe(), "gaussian r=2 sigma=0.4 subtract_edge=0");
  EXPECT_EQ(makeFilter("gaussian-cut", 2.f)->describe(), "gaussian-cut r=2 sigma=0.5 subtract_edge=0");
  // at the natural radius the two are the same filter
  const auto cut = makeFilter("gaussian-cut", 1.5f);
  for (float x : {0.f, 0.3f, 0.9f, 1.4f}) EXPECT_EQ(cut->eval(x, 0.1f), natural->eval(x, 0.1f)) << x;
  // the course variant takes the sigma in use
  EXPECT_EQ(makeCourseVariant(*makeFilter("gaussian", 3.f))->describe(), "course-gaussian r=2.5 sigma=1");
  EXPECT_EQ(makeCourseVariant(*makeFilter("gaussian-cut", 3.f))->describe(), "course-gaussian r=1.5 sigma=0.5");
}

TEST(GaussianFacts, BlurAgainstThePixelAreaTargetGrowsWithTheRadius) {
  // From r = 1 on (at 0.5 the Gaussian is sharper than the pixel's box) the Gaussian blurs more than the target
  // as r grows: its response at a quarter of the sampling rate falls, the gap to the box's grows, and so does
  // the mean squared difference on a step edge. gaussian-cut hardly changes past r = 1.5: the radius only cuts.
  const auto box = makeFilter("box", 0.5f);
  const double target = response(*box, 0.25);
  EXPECT_NEAR(target, std::sin(M_PI / 4) / (M_PI / 4), 1e-4);  // sinc of the pixel's width
  EXPECT_LT(stepBlur(*box), 1e-5);
  double lastResponse = 2, lastGap = -1, lastStep = -1;
  for (float r : {1.f, 1.5f, 2.f, 3.f, 4.f}) {
    const auto g = makeFilter("gaussian", r);
    const double h = response(*g, 0.25), gap = (h - target) * (h - target), step = stepBlur(*g);
    EXPECT_NEAR(h, std::exp(-2 * M_PI * M_PI * (r / 3.0) * (r / 3.0) / 16), 0.02) << r;  // the uncut Gaussian's
    EXPECT_LT(h, target) << r;
    EXPECT_LT(h, lastResponse) << r;
    EXPECT_GT(gap, lastGap) << r;
    EXPECT_GT(step, lastStep) << r;
    lastResponse = h, lastGap = gap, lastStep = step;
  }
  EXPECT_GT(stepBlur(*makeFilter("gaussian", 4.f)), 10 * stepBlur(*makeFilter("gaussian", 1.5f)));
  const double cut15 = response(*makeFilter("gaussian-cut", 1.5f), 0.25);
  for (float r : {2.f, 3.f, 4.f}) {
    const auto c = makeFilter("gaussian-cut", r);
    EXPECT_NEAR(response(*c, 0.25), cut15, 0.02 * cut15) << r;
    EXPECT_NEAR(stepBlur(*c), stepBlur(*makeFilter("gaussian-cut", 1.5f)), 0.3 * stepBlur(*c)) << r;
  }
}

TEST(GaussianFacts, GaussianEdgeValueSubtractedOnlyWhenAsked) {
  auto plain = makeFilter("gaussian", 1.f, {{"sigma", 0.5}});
  auto sub = makeFilter("gaussian", 1.f, {{"sigma", 0.5}, {"subtract_edge", 1}});
  const double er = std::exp(-1.0 / (2 * 0.25));
  EXPECT_NEAR(plain->eval(0.99999f, 0), er, 1e-5);
  EXPECT_NEAR(sub->eval(0.99999f, 0), 0.0, 1e-5);
  EXPECT_NEAR(plain->integral(), 2 * M_PI * 0.25 * (1 - er), 1e-9);
  EXPECT_NEAR(sub->integral(), 2 * M_PI * 0.25 * (1 - er) - er * M_PI, 1e-9);
  EXPECT_EQ(plain->describe(), "gaussian r=1 sigma=0.5 subtract_edge=0");
  EXPECT_EQ(makeFilter("gaussian", 1.5f)->describe(), "gaussian r=1.5 sigma=0.5 subtract_edge=0");
  EXPECT_EQ(plain->eval(1.5f, 0), 0.f);
}

TEST(GaussianFacts, CourseGaussianIsTheUncutGaussianOverTheCoursesSquare) {
  // the classic gather's weight: exp(-d^2 / 2 sigma^2) uncut over pixels i-R..i+R, R = ceil(2 sigma - 0.5)
  const auto course = makeCourseVariant(*makeFilter("gaussian", 1.f, {{"sigma", 0.5}, {"subtract_edge", 1}}));
  ASSERT_NE(course, nullptr);
  EXPECT_EQ(course->describe(), "course-gaussian r=1.5 sigma=0.5");
  EXPECT_FLOAT_EQ(course->eval(1.5f, 0), std::exp(-2.f * (1.5f * 1.5f + 0.f)));
  EXPECT_FLOAT_EQ(course->eval(1.4f, -1.5f), std::exp(-2.f * (1.4f * 1.4f + 1.5f * 1.5f)));  // the corner too: uncut
  EXPECT_EQ(course->eval(1.5001f, 0), 0.f);
  for (double sigma : {0.1, 0.26, 0.5, 0.75, 1.0, 1.3, 4.0})
    EXPECT_EQ(defaultFilterRadius("course-gaussian", {{"sigma", sigma}}), std::ceil(2 * sigma - 0.5) + 0.5) << sigma;
  const double axis = 0.5 * std::sqrt(2 * M_PI) * std::erf(1.5 / (0.5 * M_SQRT2));
  EXPECT_NEAR(course->integral(), axis * axis, 1e-12);
  EXPECT_EQ(makeCourseVariant(*makeFilter("tent", 1.f)), nullptr);
}

}  // namespace
}  // namespace aliaslab
