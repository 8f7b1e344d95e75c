// The fast FLIP (measure/flip/flip.h) against its scalar definition (measure/flip/flip_definition.h, libm in double):
// the documented tolerance is 1e-6 per image mean (docs/flip.md), checked on renders of several scenes; the
// fast cube root, logarithm and power against libm on the ranges FLIP uses; the shared-image form meanFlips
// against one target at a time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "aliaslab_paths.h"
#include "core/cpu.h"
#include "film/film.h"
#include "filter/filter.h"
#include "measure/flip/flip.h"
#include "measure/flip/flip_definition.h"
#include "measure/flip/flip_fastmath.h"
#include "render/render.h"
#include "sampling/sampler.h"
#include "study/study_scene.h"

namespace aliaslab {
namespace {

using flipmath::Dv;

TEST(FlipFastMath, CubeRootLogarithmAndPowerAgreeWithLibm) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  double cbrtErr = 0, logErr = 0, expErr = 0;
  for (int i = 0; i < 200000; ++i) {
    // cube roots of CIELab's range (t in (0.0089, 1.0001]), and of a wider one
    const double t = i % 2 ? 0.0088 + 0.9913 * unit(rng) : std::exp2(-60 + 70 * unit(rng));
    cbrtErr = std::max(cbrtErr, std::abs(flipmath::cbrtPositive<1>(Dv<1>{t})[0] / std::cbrt(t) - 1));
    // logarithms of colour differences and of bases in (0, 1]
    const double x = std::exp2(-1000 + 1010 * unit(rng));
    logErr = std::max(logErr, std::abs(flipmath::log2Positive<1>(Dv<1>{x})[0] - std::log2(x)));
    const double z = -1000 + 1010 * unit(rng);
    expErr = std::max(expErr, std::abs(flipmath::exp2Of<1>(Dv<1>{z})[0] / std::exp2(z) - 1));
  }
  EXPECT_LT(cbrtErr, 1e-15);
  EXPECT_LT(logErr, 1e-12);
  EXPECT_LT(expErr, 1e-13);
  // exact points and the two vector widths against one lane
  EXPECT_EQ(flipmath::log2Positive<1>(Dv<1>{1.0})[0], 0.0);
  EXPECT_EQ(flipmath::exp2Of<1>(Dv<1>{0.0})[0], 1.0);
  EXPECT_EQ(flipmath::exp2Of<1>(Dv<1>{-3.0})[0], 0.125);
  EXPECT_EQ(flipmath::exp2Of<1>(Dv<1>{-2000.0})[0], std::exp2(-1022.0));
  const Dv<2> two = flipmath::cbrtPositive<2>(Dv<2>{0.3, 0.027});
  EXPECT_EQ(two[0], flipmath::cbrtPositive<1>(Dv<1>{0.3})[0]);
  EXPECT_NEAR(two[1], 0.3, 1e-16);
}

TEST(FlipFastMath, SinglePrecisionLogarithmAndPowerAgreeWithLibm) {
  // stage 3's float logarithm and power (flip_fastmath.h): log2 within 2e-7 absolute plus 2 ulp of the result,
  // 2^z within 3e-7 relative, on the ranges stage 3 uses (colour differences up to ~300, bases in (0, 1])
  using flipmath::Fv;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  double logExcess = 0, expErr = 0;
  for (int i = 0; i < 200000; ++i) {
    const float x = static_cast<float>(std::exp2(-125 + 134 * unit(rng)));  // normal floats up to 512
    const double exact = std::log2(static_cast<double>(x));
    const double got = flipmath::log2PositiveF<1>(Fv<1>{x})[0];
    logExcess = std::max(logExcess, std::abs(got - exact) - 2 * std::abs(exact) * 0x1p-24);
    const float z = static_cast<float>(-126 + 135 * unit(rng));
    expErr = std::max(expErr, std::abs(flipmath::exp2OfF<1>(Fv<1>{z})[0] / std::exp2(static_cast<double>(z)) - 1));
  }
  EXPECT_LT(logExcess, 2e-7);
  EXPECT_LT(expErr, 3e-7);
  EXPECT_EQ(flipmath::log2PositiveF<1>(Fv<1>{1.0f})[0], 0.0f);
  EXPECT_EQ(flipmath::exp2OfF<1>(Fv<1>{0.0f})[0], 1.0f);
  EXPECT_EQ(flipmath::exp2OfF<1>(Fv<1>{-3.0f})[0], 0.125f);
  EXPECT_EQ(flipmath::exp2OfF<1>(Fv<1>{-500.0f})[0], 0x1p-126f);  // clamped, not 0
  // the vector widths against one lane, bit for bit
  const Fv<8> xs = {0.3f, 7.0f, 1e-20f, 250.f, 0.999f, 1.5f, 3e-30f, 42.f};
  const Fv<8> logs = flipmath::log2PositiveF<8>(xs), pows = flipmath::exp2OfF<8>(xs * -0.7f);
  for (int l = 0; l < 8; ++l) {
    EXPECT_EQ(logs[l], flipmath::log2PositiveF<1>(Fv<1>{xs[l]})[0]) << l;
    EXPECT_EQ(pows[l], flipmath::exp2OfF<1>(Fv<1>{xs[l] * -0.7f})[0]) << l;
  }
}

// A render of a bundled scene at 48 px (larger side), jittered, `spp` samples per pixel, Mitchell r = 2.
Image render(const std::string& scene, int spp, uint64_t seed) {
  const auto s = loadStudyScene(std::string(ALIASLAB_SOURCE_DIR) + "/scenes/" + scene, 48, 48);
  const auto sampler = makeSampler("jittered", spp, seed);
  const SampleBuffer samples = traceSamples(*s->tracer, *sampler, s->width, s->height, 1);
  return reconstruct(samples, *makeFilter("mitchell", 2), ReconMode::WeightedAverage, 1).image;
}

TEST(Flip, FastMeanIsWithinTheToleranceOfTheDefinitionOnRenders) {
  // Test images (4 spp, two seeds) against a 64-spp reference of the same scene: noisy, aliased pairs with
  // every kind of FLIP value (flat regions, edges, texture). Tolerance: 1e-6 per image mean (docs/flip.md);
  // the fast path is in fact within 1e-9 per pixel.
  double worstPixel = 0, worstMean = 0;
  for (const char* scene : {"fence.txt", "siemens.txt", "zoneplate.txt", "vase.txt", "checker_horizon.txt"}) {
    const Image ref = render(scene, 64, 99);
    const FlipReference prepared(ref);
    for (uint64_t seed : {1, 2}) {
      const Image test = render(scene, 4, seed);
      const std::vector<float> fast = prepared.map(test), def = flipMapDefinition(test, ref);
      ASSERT_EQ(fast.size(), def.size());
      double maxPixel = 0;
      for (size_t i = 0; i < fast.size(); ++i) maxPixel = std::max(maxPixel, double(std::abs(fast[i] - def[i])));
      const double mean = meanFlipDefinition(test, ref);
      EXPECT_GT(mean, 0.005) << scene;  // a comparison with something in it
      EXPECT_NEAR(prepared.mean(test), mean, 1e-6) << scene;
      EXPECT_LT(maxPixel, 1e-6) << scene << " seed " << seed;
      worstPixel = std::max(worstPixel, maxPixel), worstMean = std::max(worstMean, std::abs(prepared.mean(test) - mean));
      EXPECT_EQ(meanFlip(test, ref), prepared.mean(test));
    }
  }
  std::printf("fast against definition: worst pixel %.3g, worst mean %.3g\n", worstPixel, worstMean);
}

TEST(Flip, SseAndAvxPathsGiveTheSameBits) {
  // ScopedCpuFeatures keeps every FLIP stage on SSE2 (on a CPU without AVX2 both runs take that path)
  const Image ref = render("vase.txt", 16, 7), test = render("vase.txt", 4, 8);
  const std::vector<float> wide = FlipReference(ref).map(test);
  std::vector<float> narrow;
  {
    const ScopedCpuFeatures sseOnly(CpuFeatures{});
    narrow = FlipReference(ref).map(test);
  }
  ASSERT_EQ(wide.size(), narrow.size());
  for (size_t i = 0; i < wide.size(); ++i) ASSERT_EQ(wide[i], narrow[i]) << "pixel " << i;
}

TEST(Flip, OneImageAgainstManyTargetsGivesEachTargetsNumber) {
  const Image a = render("siemens.txt", 4, 3), b = render("siemens.txt", 64, 4), c = render("siemens.txt", 16, 5);
  const FlipReference tb(b), tc(c), ta(a);
  const std::vector<double> m = meanFlips(a, {&tb, &tc, &ta});
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0], tb.mean(a));
  EXPECT_EQ(m[1], tc.mean(a));
  EXPECT_EQ(m[2], 0.0);
  EXPECT_NE(m[0], m[1]);
  EXPECT_TRUE(meanFlips(a, {}).empty());
  const FlipReference small(Image(8, 8));
  EXPECT_THROW(meanFlips(a, {&tb, &small}), std::invalid_argument);
}

}  // namespace
}  // namespace aliaslab
