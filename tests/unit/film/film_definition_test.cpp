// The film's definition (film/film_definition.h) against values worked out by hand, and every fast path of the
// weighted average (reconstruct's splat band after band, the Accumulator batch after batch) against it: images
// within float rounding of the double sums, and the same degenerate outcomes counted.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/hash.h"
#include "film/film.h"
#include "film/film_definition.h"
#include "support/film_samples.h"

namespace aliaslab {
namespace {

using testing::makeSamples;
using testing::maxDiff;
using testing::noisy;

void expectSameStats(const ReconStats& a, const ReconStats& b, const std::string& what) {
  EXPECT_EQ(a.undefinedPixels, b.undefinedPixels) << what;
  EXPECT_EQ(a.negativePixels, b.negativePixels) << what;
  EXPECT_EQ(a.nanPixels, b.nanPixels) << what;
  EXPECT_EQ(a.nonFiniteSamples, b.nonFiniteSamples) << what;
}

/// The definition and the fast reconstruction, to be checked against the same worked values.
std::vector<Reconstruction> bothWays(const SampleBuffer& b, const Filter& f) {
  return {reconstructDefinition(b, f), reconstruct(b, f, ReconMode::WeightedAverage, 1)};
}

TEST(FilmDefinition, TwoSamplesGiveTheFilterWeightedMean) {
  // tent r = 2: pixel (1, 0), centre (1.5, 0.5), sees samples at distances 0.5 and 1 (weights 0.75 and 0.5) and
  // not the NaN one; border pixel (2, 0), centre (2.5, 0.5), at sqrt(1.25) and sqrt(2): the clipped support
  // still normalises
  auto f = makeFilter("tent", 2.f);
  SampleBuffer b(3, 1, 1);
  b.pixel(0, 0)[0] = {1.5f, 1.0f, Color(1, 2, 4), 1};   // d = 0.5 from (1.5, 0.5)
  b.pixel(1, 0)[0] = {1.5f, -0.5f, Color(0, 0, 0), 1};  // d = 1
  b.pixel(2, 0)[0] = {NAN, 0, Color(9, 9, 9), 1};
  const double w1 = 1 - std::sqrt(1.25) / 2, w2 = 1 - std::sqrt(2.0) / 2;
  for (const Reconstruction& rec : bothWays(b, *f)) {
    EXPECT_NEAR(rec.image.get(1, 0)[0], 0.75 / 1.25, 1e-6);
    EXPECT_NEAR(rec.image.get(1, 0)[2], 4 * 0.75 / 1.25, 1e-6);
    EXPECT_NEAR(rec.image.get(2, 0)[1], 2 * w1 / (w1 + w2), 1e-6);
    EXPECT_EQ(rec.stats.nonFiniteSamples, 1u);
    EXPECT_EQ(rec.stats.undefinedPixels, 0u);
  }
  // area weights: the same buffer marked areaWeighted with weights 3 and 1 gives (3 w L) / (3 w + 1 w')
  b.setAreaWeighted(true);
  b.pixel(0, 0)[0].weight = 3;
  for (const Reconstruction& rec : bothWays(b, *f))
    EXPECT_NEAR(rec.image.get(1, 0)[0], 3 * 0.75 / (3 * 0.75 + 0.5), 1e-6);
  // a radius that reaches no pixel centre: every pixel takes its own mean (the NaN pixel has none: 0)
  for (const Reconstruction& tiny : bothWays(b, *makeFilter("box", 0.1f))) {
    EXPECT_EQ(tiny.stats.undefinedPixels, 3u);
    EXPECT_TRUE((tiny.image.get(0, 0) == Color(1, 2, 4)).all());
    EXPECT_TRUE((tiny.image.get(2, 0) == Color::Zero()).all());
  }
}

TEST(FilmDefinition, NegativeLobeMakesNegativePixelKeptAndCounted) {
  // lanczos r = 1.5 (tau 3): dx = 0.75 -> x' = 1.5, weight sinc(1.5) sinc(0.5) = (-2/3pi)(2/pi)
  auto f = makeFilter("lanczos", 1.5f);
  SampleBuffer b(2, 1, 1);
  b.pixel(0, 0)[0] = {0.5f, 0.5f, Color::Zero(), 1};
  b.pixel(1, 0)[0] = {1.25f, 0.5f, Color::Ones(), 1};
  const double wn = (-2 / (3 * M_PI)) * (2 / M_PI);
  for (const Reconstruction& rec : bothWays(b, *f)) {
    EXPECT_NEAR(rec.image.get(0, 0)[0], wn / (1 + wn), 1e-5);
    EXPECT_GE(rec.stats.negativePixels, 1u);
    EXPECT_EQ(rec.stats.nanPixels, 0u);
  }
}

TEST(FilmDefinition, FastWeightedAverageEqualsTheDefinition) {
  for (const auto& name : allFilterNames())
    for (float r : {0.5f, 1.f, 1.5f, 2.f, 2.3f, 3.f}) {  // the study's radii (0.5, 1, 2, natural 1.5 and 3), and 2.3
      auto f = makeFilter(name, r);
      const SampleBuffer b = makeSamples(13, 9, 8, 7, noisy);
      const Reconstruction rec = reconstruct(b, *f, ReconMode::WeightedAverage, 2);
      ASSERT_EQ(rec.stats.undefinedPixels, 0u) << f->describe();
      EXPECT_LT(maxDiff(rec.image, reconstructDefinition(b, *f).image), 1e-5) << f->describe();
    }
}

TEST(FilmDefinition, BandAfterBandAndBatchAfterBatchMatchTheDefinition) {
  // A tall film is splatted band by band (32 rows each, the last one short); one thread reuses one band buffer
  // for all of them, so each band must hand its buffer back cleared, padding included (a radius of 2.3 reaches
  // 5 rows and columns past a band). The Accumulator's first batch overwrites sums it never zeroed; the second
  // adds to them. Both against the definition, in double.
  auto mitchell = makeFilter("mitchell", 2.3f), tent = makeFilter("tent", 1.5f);
  const int w = 9, h = 101;
  const SampleBuffer first = makeSamples(w, h, 3, 41, noisy), second = makeSamples(w, h, 3, 42, noisy);
  SampleBuffer both(w, h, 6);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int k = 0; k < 3; ++k) both.pixel(i, j)[k] = first.pixel(i, j)[k], both.pixel(i, j)[3 + k] = second.pixel(i, j)[k];
  for (int threads : {1, 3}) {
    Accumulator acc(w, h, {mitchell.get(), tent.get()});
    acc.add(first, threads);
    EXPECT_LT(maxDiff(acc.resolve(0).image, reconstructDefinition(first, *mitchell).image), 1e-5) << "threads " << threads;
    EXPECT_LT(maxDiff(acc.resolve(1).image, reconstructDefinition(first, *tent).image), 1e-5) << "threads " << threads;
    acc.add(second, threads);
    EXPECT_LT(maxDiff(acc.resolve(0).image, reconstructDefinition(both, *mitchell).image), 1e-5) << "threads " << threads;
    EXPECT_LT(maxDiff(acc.resolve(1).image, reconstructDefinition(both, *tent).image), 1e-5) << "threads " << threads;
  }
  // nothing added: every pixel undefined with the mean of no samples, 0
  Accumulator empty(w, h, {tent.get()});
  const Reconstruction none = empty.resolve(0);
  EXPECT_EQ(none.stats.undefinedPixels, static_cast<size_t>(w) * h);
  EXPECT_EQ(maxDiff(none.image, Image(w, h)), 0.0);
}

TEST(FilmDefinition, FastPathsCountTheSameDegenerateOutcomes) {
  // Variable counts (zeros included) with area weights, as adaptive sampling makes them, some NaN and inf
  // samples, radiance large enough to overflow float where a negative lobe nearly cancels the weights, and radii
  // from one that reaches few pixel centres to one with negative lobes: reconstruct() and the Accumulator give
  // the definition's image and the definition's counts.
  const int w = 12, h = 9;
  std::vector<int> counts(w * h);
  for (int p = 0; p < w * h; ++p) counts[p] = p % 5;
  SampleBuffer b(w, h, counts);
  b.setAreaWeighted(true);
  const float inf = std::numeric_limits<float>::infinity();
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int k = 0; k < b.count(i, j); ++k) {
        FilmSample& s = b.pixel(i, j)[k];
        const uint64_t key = hashWords(5, i, j, k);
        s.x = i + toUnitFloat(hashWords(key, 0)), s.y = j + toUnitFloat(hashWords(key, 1));
        s.L = noisy(s.x, s.y, hashWords(key, 2));
        s.weight = 1.f / b.count(i, j);
        switch (hashWords(key, 3) % 17) {
          case 0: s.x = NAN; break;
          case 1: s.L[0] = inf; break;
          case 2: s.L = Color(3e38f, -3e38f, 1); break;
          default: break;
        }
      }
  for (const char* name : {"box", "tent", "lanczos", "mitchell"})
    for (float r : {0.3f, 1.f, 2.3f}) {
      auto f = makeFilter(name, r);
      const Reconstruction want = reconstructDefinition(b, *f);
      const Reconstruction fast = reconstruct(b, *f, ReconMode::WeightedAverage, 2);
      Accumulator acc(w, h, {f.get()});
      acc.add(b, 2);
      const Reconstruction streamed = acc.resolve(0);
      for (const Reconstruction* got : {&fast, &streamed}) {
        const std::string what = f->describe() + (got == &fast ? " reconstruct" : " accumulator");
        expectSameStats(got->stats, want.stats, what);
        for (int j = 0; j < h; ++j)
          for (int i = 0; i < w; ++i) {
            const Color a = got->image.get(i, j), d = want.image.get(i, j);
            EXPECT_LE((a - d).abs().maxCoeff(), 1e-5f * std::max(1.f, d.abs().maxCoeff())) << what << " " << i << "," << j;
          }
      }
    }
}

}  // namespace
}  // namespace aliaslab
