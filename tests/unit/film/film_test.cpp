// Reconstruction: every mode against the mathematics of docs/science.md and an
// independent brute-force weighted average written here.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include <chrono>
#include <cmath>
#include <limits>

#include "core/cpu.h"
#include "core/error.h"
#include "core/hash.h"
#include "film/film.h"
#include "film/film_impl.h"
#include "film/visualize.h"
#include "filter/filter_sampler.h"

namespace aliaslab {
namespace {

/// Random positions inside each pixel (or filter-importance offsets around
/// its centre when `importance` is given) with radiance field(x, y).
template <class Field>
SampleBuffer makeSamples(int w, int h, int spp, uint64_t seed, Field&& field, const Filter* importance = nullptr) {
  SampleBuffer b(w, h, spp);
  const std::unique_ptr<FilterSampler> table = importance ? std::make_unique<FilterSampler>(*importance) : nullptr;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int k = 0; k < spp; ++k) {
        FilmSample& s = b.pixel(i, j)[k];
        const Vec2 u(toUnitFloat(hashWords(seed, i, j, k, 0)), toUnitFloat(hashWords(seed, i, j, k, 1)));
        if (importance) {
          const Vec2 o = table->sample(u, s.weight);
          s.x = i + 0.5f + o.x(), s.y = j + 0.5f + o.y();
        } else {
          s.x = i + u.x(), s.y = j + u.y();
        }
        s.L = field(s.x, s.y, hashWords(seed, i, j, k, 2));
      }
  return b;
}

const Color kConst(0.3f, 0.6f, 0.9f);
auto constant = [](float, float, uint64_t) { return kConst; };
auto noisy = [](float x, float y, uint64_t h) {
  return Color(toUnitFloat(h), 0.5f + 0.1f * std::sin(x), toUnitFloat(mix64(h)) * y);
};

/// The definition, in double: sum f(x_k - p) L_k / sum f over every sample, fallback to the own mean.
Image naiveWeighted(const SampleBuffer& b, const Filter& f) {
  Image img(b.width(), b.height());
  for (int j = 0; j < b.height(); ++j)
    for (int i = 0; i < b.width(); ++i) {
      Eigen::Array3d num = Eigen::Array3d::Zero();
      double den = 0;
      for (const FilmSample& s : b.samples()) {
        const double w = f.eval(s.x - (i + 0.5f), s.y - (j + 0.5f));
        num += w * s.L.cast<double>(), den += w;
      }
      img.set(i, j, (num / den).cast<float>());
    }
  return img;
}

double maxDiff(const Image& a, const Image& b) {
  double m = 0;
  for (int j = 0; j < a.height(); ++j)
    for (int i = 0; i < a.width(); ++i) m = std::max(m, double((a.get(i, j) - b.get(i, j)).abs().maxCoeff()));
  return m;
}

const ReconMode kModes[] = {ReconMode::WeightedAverage, ReconMode::Classic, ReconMode::ImportanceSampled,
                            ReconMode::Supersample};

TEST(Film, ConstantFieldReconstructsExactlyEveryFilterModeRadius) {
  for (const auto& name : allFilterNames())
    for (float r : {0.05f, 0.5f, 1.5f, 2.3f, 20.f})
      for (int spp : {4, 9, 5}) {
        auto f = makeFilter(name, r);
        for (ReconMode mode : kModes) {
          const SampleBuffer b =
              makeSamples(11, 7, spp, 5, constant, mode == ReconMode::ImportanceSampled ? f.get() : nullptr);
          if (mode == ReconMode::Supersample && spp == 5) {
            EXPECT_THROW(reconstruct(b, *f, mode, 1), OptionError);
            continue;
          }
          const Reconstruction rec = reconstruct(b, *f, mode, 2);
          for (int j = 0; j < 7; ++j)
            for (int i = 0; i < 11; ++i)
              ASSERT_LT((rec.image.get(i, j) - kConst).abs().maxCoeff(), 1e-6)
                  << f->describe() << " " << toString(mode) << " spp " << spp << " pixel " << i << "," << j;
          EXPECT_EQ(rec.stats.nanPixels, 0u);
          EXPECT_EQ(rec.stats.negativePixels, 0u);
        }
      }
}

TEST(Film, FastWeightedAverageEqualsBruteForceDefinition) {
  for (const auto& name : allFilterNames())
    for (float r : {0.5f, 1.5f, 2.3f}) {
      auto f = makeFilter(name, r);
      const SampleBuffer b = makeSamples(13, 9, 8, 7, noisy);
      const Reconstruction rec = reconstruct(b, *f, ReconMode::WeightedAverage, 2);
      ASSERT_EQ(rec.stats.undefinedPixels, 0u) << f->describe();
      EXPECT_LT(maxDiff(rec.image, naiveWeighted(b, *f)), 1e-5) << f->describe();
    }
}

TEST(Film, SingleSampleReachesExactlyThePixelsWithinItsSupport) {
  // one finite sample, all others NaN: a reached pixel is f(d) L / f(d) = L,
  // every other pixel is undefined and falls back to its own (absent) samples: 0
  for (const char* name : {"tent", "box", "gaussian"}) {
    auto f = makeFilter(name, 1.7f);
    SampleBuffer b(9, 9, 1);
    for (auto& s : b.samples()) s.x = s.y = NAN;
    FilmSample& one = b.pixel(4, 4)[0];
    one.x = 4.3f, one.y = 4.7f, one.L = Color(2, 3, 4);
    const Reconstruction rec = reconstruct(b, *f, ReconMode::WeightedAverage, 1);
    size_t reached = 0;
    for (int j = 0; j < 9; ++j)
      for (int i = 0; i < 9; ++i) {
        const float dx = 4.3f - (i + 0.5f), dy = 4.7f - (j + 0.5f);
        const bool inside = f->radial() ? std::hypot(dx, dy) < 1.7f && 1 - std::hypot(dx, dy) / 1.7f > 1e-6
                                        : std::abs(dx) <= 1.7f && std::abs(dy) <= 1.7f;
        reached += inside;
        const Color want = inside || (i == 4 && j == 4) ? Color(2, 3, 4) : Color::Zero();
        EXPECT_LT((rec.image.get(i, j) - want).abs().maxCoeff(), 1e-6) << name << " " << i << "," << j;
      }
    EXPECT_EQ(rec.stats.nonFiniteSamples, 80u);
    EXPECT_EQ(rec.stats.undefinedPixels, 81u - reached) << name;
  }
}

TEST(Film, TwoSamplesGiveTheFilterWeightedMean) {
  // tent r = 2 at pixel (1, 0): samples at distances 0.5 and 1 -> weights 0.75 and 0.5
  auto f = makeFilter("tent", 2.f);
  SampleBuffer b(3, 1, 1);
  b.pixel(0, 0)[0] = {1.5f, 1.0f, Color(1, 1, 1), 1};   // d = 0.5 from (1.5, 0.5)
  b.pixel(1, 0)[0] = {1.5f, -0.5f, Color(0, 0, 0), 1};  // d = 1
  b.pixel(2, 0)[0] = {NAN, 0, Color(9, 9, 9), 1};
  const Reconstruction rec = reconstruct(b, *f, ReconMode::WeightedAverage, 1);
  EXPECT_NEAR(rec.image.get(1, 0)[0], 0.75 / 1.25, 1e-6);
  // border pixel 2 (centre 2.5, 0.5): distances sqrt(1.25) and sqrt(2): clipped support still normalises
  const double w1 = 1 - std::sqrt(1.25) / 2, w2 = 1 - std::sqrt(2.0) / 2;
  EXPECT_NEAR(rec.image.get(2, 0)[0], w1 / (w1 + w2), 1e-6);
}

TEST(Film, NegativeLobeMakesNegativePixelKeptAndCounted) {
  // lanczos r = 1.5 (tau 3): dx = 0.75 -> x' = 1.5, weight sinc(1.5) sinc(0.5) = (-2/3pi)(2/pi)
  auto f = makeFilter("lanczos", 1.5f);
  SampleBuffer b(2, 1, 1);
  b.pixel(0, 0)[0] = {0.5f, 0.5f, Color::Zero(), 1};
  b.pixel(1, 0)[0] = {1.25f, 0.5f, Color::Ones(), 1};
  const Reconstruction rec = reconstruct(b, *f, ReconMode::WeightedAverage, 1);
  const double wn = (-2 / (3 * M_PI)) * (2 / M_PI);
  EXPECT_NEAR(rec.image.get(0, 0)[0], wn / (1 + wn), 1e-5);
  EXPECT_GE(rec.stats.negativePixels, 1u);
  EXPECT_EQ(rec.stats.nanPixels, 0u);
}

TEST(Film, TinyRadiusLeavesPixelsUndefinedWithOwnMean) {
  auto f = makeFilter("tent", 0.05f);
  const SampleBuffer b = makeSamples(10, 10, 2, 11, noisy);
  const Reconstruction rec = reconstruct(b, *f, ReconMode::WeightedAverage, 1);
  size_t undefined = 0;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i) {
      const FilmSample* s = b.pixel(i, j);
      bool any = false;
      for (int k = 0; k < 2; ++k) any |= std::hypot(s[k].x - i - 0.5f, s[k].y - j - 0.5f) < 0.05f;
      if (any) continue;
      ++undefined;
      EXPECT_LT((rec.image.get(i, j) - (s[0].L + s[1].L) / 2).abs().maxCoeff(), 1e-6);
    }
  EXPECT_GT(undefined, 90u);
  EXPECT_EQ(rec.stats.undefinedPixels, undefined);
}

TEST(Film, ImportanceWeightsSummingToZeroFallBackToMean) {
  auto f = makeFilter("lanczos", 1.5f);
  SampleBuffer b(1, 1, 3);
  b.pixel(0, 0)[0] = {0.5f, 0.5f, Color(1, 2, 3), 1.f};
  b.pixel(0, 0)[1] = {0.6f, 0.5f, Color(3, 2, 1), -1.f};
  b.pixel(0, 0)[2] = {0.6f, 0.5f, Color(NAN, 0, 0), 5.f};
  const Reconstruction rec = reconstruct(b, *f, ReconMode::ImportanceSampled, 1);
  EXPECT_LT((rec.image.get(0, 0) - Color(2, 2, 2)).abs().maxCoeff(), 1e-6);
  EXPECT_EQ(rec.stats.undefinedPixels, 1u);
  EXPECT_EQ(rec.stats.nonFiniteSamples, 1u);
}

TEST(Film, OverflowingResultFallsBackAndCountsNan) {
  // (3e38 - 0.99 * -3e38) / (1 - 0.99) = 6e40 overflows float: fallback mean (3e38 - 3e38) / 2 = 0
  auto f = makeFilter("box", 0.5f);
  SampleBuffer b(1, 1, 2);
  b.pixel(0, 0)[0] = {0.5f, 0.5f, Color(3e38f, 1, 1), 1.f};
  b.pixel(0, 0)[1] = {0.5f, 0.5f, Color(-3e38f, 1, 1), -0.99f};
  const Reconstruction rec = reconstruct(b, *f, ReconMode::ImportanceSampled, 1);
  EXPECT_TRUE((rec.image.get(0, 0) == Color(0, 1, 1)).all()) << rec.image.get(0, 0);
  EXPECT_EQ(rec.stats.nanPixels, 1u);
  EXPECT_EQ(rec.stats.undefinedPixels, 0u);
}

TEST(Film, AccumulatorOverBatchesEqualsReconstructionOfUnion) {
  auto tent = makeFilter("tent", 1.5f), lanczos = makeFilter("lanczos", 2.3f);
  Accumulator acc(12, 8, {tent.get(), lanczos.get()});
  SampleBuffer all(12, 8, 12);
  for (int batch = 0; batch < 3; ++batch) {
    const SampleBuffer b = makeSamples(12, 8, 4, 100 + batch, noisy);
    acc.add(b, batch + 1);
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 12; ++i)
        for (int k = 0; k < 4; ++k) all.pixel(i, j)[4 * batch + k] = b.pixel(i, j)[k];
  }
  EXPECT_EQ(acc.samplesAdded(), 12u * 8 * 12);
  EXPECT_EQ(acc.bytes(), 3u * 12 * 8 * 4 * sizeof(double));
  EXPECT_LT(maxDiff(acc.resolve(0).image, reconstruct(all, *tent, ReconMode::WeightedAverage).image), 1e-6);
  EXPECT_LT(maxDiff(acc.resolve(1).image, reconstruct(all, *lanczos, ReconMode::WeightedAverage).image), 1e-6);
}

TEST(Film, BandAfterBandAndBatchAfterBatchMatchTheDefinition) {
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
    EXPECT_LT(maxDiff(acc.resolve(0).image, naiveWeighted(first, *mitchell)), 1e-5) << "threads " << threads;
    EXPECT_LT(maxDiff(acc.resolve(1).image, naiveWeighted(first, *tent)), 1e-5) << "threads " << threads;
    acc.add(second, threads);
    EXPECT_LT(maxDiff(acc.resolve(0).image, naiveWeighted(both, *mitchell)), 1e-5) << "threads " << threads;
    EXPECT_LT(maxDiff(acc.resolve(1).image, naiveWeighted(both, *tent)), 1e-5) << "threads " << threads;
  }
  // nothing added: every pixel undefined with the mean of no samples, 0
  Accumulator empty(w, h, {tent.get()});
  const Reconstruction none = empty.resolve(0);
  EXPECT_EQ(none.stats.undefinedPixels, static_cast<size_t>(w) * h);
  EXPECT_EQ(maxDiff(none.image, Image(w, h)), 0.0);
}

TEST(Film, OneAccumulatorPassEqualsEachReconstructionBitForBit) {
  // filters of equal radius share one pass (footprints once, then each filter's weights): the result must be
  // exactly each filter's own reconstruct(), including a unit-weight box, a radius wider than a block
  // (sample by sample) and a radius no other filter has
  const SampleBuffer b = makeSamples(37, 29, 6, 21, noisy);
  std::vector<std::unique_ptr<Filter>> owned;
  for (const auto& name : allFilterNames()) owned.push_back(makeFilter(name, 1.5f));
  owned.push_back(makeFilter("box", 0.5f)), owned.push_back(makeFilter("tent", 9.f)), owned.push_back(makeFilter("lanczos", 9.f));
  owned.push_back(makeFilter("mitchell", 2.3f));
  std::vector<const Filter*> filters;
  for (const auto& f : owned) filters.push_back(f.get());
  for (int threads : {1, 3}) {
    Accumulator acc(37, 29, filters);
    acc.measureShares();
    const auto t0 = std::chrono::steady_clock::now();
    acc.add(b, threads);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::vector<double>& seconds = acc.filterSeconds();
    const double shared = acc.sharedSeconds();
    ASSERT_EQ(seconds.size(), filters.size());
    // the shares add up to the call's wall time: each filter's own part plus 1/K of the shared rest
    double total = 0;
    for (double s : seconds) total += s;
    EXPECT_GE(shared, 0.0);
    EXPECT_LE(shared, total * (1 + 1e-9));
    EXPECT_LE(total, wall * (1 + 1e-9));
    for (double s : seconds) EXPECT_GE(s, shared / static_cast<double>(filters.size()) * (1 - 1e-9));
    for (size_t k = 0; k < filters.size(); ++k) {
      const Reconstruction own = reconstruct(b, *filters[k], ReconMode::WeightedAverage, 1), fused = acc.resolve(k);
      EXPECT_EQ(maxDiff(own.image, fused.image), 0.0) << filters[k]->describe() << " threads " << threads;
      EXPECT_EQ(own.stats.undefinedPixels, fused.stats.undefinedPixels);
      EXPECT_EQ(own.stats.negativePixels, fused.stats.negativePixels);
      EXPECT_EQ(own.stats.nonFiniteSamples, fused.stats.nonFiniteSamples);
      EXPECT_GE(seconds[k], 0.0);
    }
  }
}

TEST(Film, IdenticalForAnyThreadCount) {
  auto f = makeFilter("mitchell", 2.3f);
  const SampleBuffer b = makeSamples(40, 37, 4, 3, noisy);
  const SampleBuffer bi = makeSamples(40, 37, 4, 3, noisy, f.get());
  for (ReconMode mode : kModes) {
    const SampleBuffer& in = mode == ReconMode::ImportanceSampled ? bi : b;
    const Image one = reconstruct(in, *f, mode, 1).image;
    for (int t : {2, 3, 8}) EXPECT_EQ(maxDiff(one, reconstruct(in, *f, mode, t).image), 0.0) << toString(mode) << t;
  }
}

TEST(Film, Avx2AndSseKernelsSumBitForBitAlike) {
  // the fast path's AVX2 + FMA kernel (where the CPU has it) against the SSE one: exact products, same sums
  const SampleBuffer b = makeSamples(23, 19, 5, 13, noisy);
  for (const auto& name : allFilterNames())
    for (float r : {0.5f, 1.5f, 2.3f, 20.f}) {
      auto f = makeFilter(name, r);
      std::vector<double> fast(4 * 23 * 19, 0.0), sse(fast);
      filmimpl::splatWeighted(b, *f, fast.data(), 1);
      const ScopedCpuFeatures sseOnly(CpuFeatures{});
      filmimpl::splatWeighted(b, *f, sse.data(), 1);
      EXPECT_TRUE(fast == sse) << f->describe();
    }
}

TEST(Film, EightSampleSetUpMatchesOneByOneOnAwkwardSamples) {
  // The AVX2 set-up (8 samples at once, where the CPU has it) falls back to one by one for any group with
  // a sample it does not handle; both must give the same sums. Samples here: inside their pixel, exactly on
  // pixel edges and centres (footprints wider than a block), next to the image's first rows and columns
  // (centresWithin's float branch), far outside, in a neighbour's pixel, with NaN or inf positions or
  // radiance; 9 per pixel so groups of 8 straddle pixels; 45 rows = two bands.
  const int w = 70, h = 45, spp = 9;
  SampleBuffer b(w, h, spp);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int k = 0; k < spp; ++k) {
        FilmSample& s = b.pixel(i, j)[k];
        const uint64_t key = hashWords(77, i, j, k);
        s.x = i + toUnitFloat(hashWords(key, 0)), s.y = j + toUnitFloat(hashWords(key, 1));
        s.L = noisy(s.x, s.y, hashWords(key, 2));
        switch (hashWords(key, 3) % 40) {
          case 0: s.x = static_cast<float>(i); break;
          case 1: s.y = static_cast<float>(j); break;
          case 2: s.x = i + 0.5f, s.y = j + 0.5f; break;
          case 3: s.x = nan; break;
          case 4: s.y = -inf; break;
          case 5: s.L[1] = inf; break;
          case 6: s.L[2] = nan; break;
          case 7: s.x = -30.f; break;
          case 8: s.y = h + 40.f; break;
          case 9: s.x += 1.5f, s.y -= 2.25f; break;
          case 10: s.weight = nan; break;  // not read by the weighted average
          default: break;
        }
      }
  for (const char* name : {"box", "tent", "mitchell", "lanczos", "gaussian"})
    for (float r : {0.5f, 1.f, 1.5f, 2.f, 2.3f, 3.7f}) {
      auto f = makeFilter(name, r);
      std::vector<double> fast(4 * static_cast<size_t>(w) * h, 0.0), plain(fast);
      filmimpl::splatWeighted(b, *f, fast.data(), 1);
      const ScopedCpuFeatures sseOnly(CpuFeatures{});
      filmimpl::splatWeighted(b, *f, plain.data(), 1);
      EXPECT_TRUE(fast == plain) << f->describe();
    }
}

TEST(Film, ClassicBoxHalfIsOwnMeanAndTentGathersSquareSupport) {
  const SampleBuffer b = makeSamples(6, 5, 4, 9, noisy);
  auto box = makeFilter("box", 0.5f);
  EXPECT_EQ(classicSupport(*box), 0);
  const Image img = reconstruct(b, *box, ReconMode::Classic, 1).image;
  const FilmSample* s = b.pixel(2, 3);
  EXPECT_LT((img.get(2, 3) - (s[0].L + s[1].L + s[2].L + s[3].L) / 4).abs().maxCoeff(), 1e-6);
  // tent 1.7: R = 2, weights of samples within the 5x5 pixel block only
  auto tent = makeFilter("tent", 1.7f);
  EXPECT_EQ(classicSupport(*tent), 2);
  EXPECT_EQ(classicSupport(*makeFilter("gaussian", 5.f, {{"sigma", 1.0}})), 2);  // its course variant's
  EXPECT_EQ(classicSupport(*makeFilter("course-gaussian", 2.5f, {{"sigma", 1.0}})), 2);
  Eigen::Array3d num = Eigen::Array3d::Zero();
  double den = 0;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 2; ++i)
      for (int k = 0; k < 4; ++k) {
        const FilmSample& q = b.pixel(i, j)[k];
        const double w = std::max(0.0, 1 - std::hypot(q.x - 0.5, q.y - 2.5) / 1.7);
        num += w * q.L.cast<double>(), den += w;
      }
  const Image ct = reconstruct(b, *tent, ReconMode::Classic, 1).image;
  EXPECT_LT((ct.get(0, 2).cast<double>() - num / den).abs().maxCoeff(), 1e-5);
}

TEST(Film, SupersampleIsBinomialBlurThenBlockAverage) {
  // 2 x 1 pixels, spp 4 at the 2x2 sub-pixel centres, fine image 4 x 2 with values v(x, y) = x + 10 y
  SampleBuffer b(2, 1, 4);
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 4; ++k) {
      const int fx = 2 * i + k % 2, fy = k / 2;
      b.pixel(i, 0)[k] = {(fx + 0.5f) / 2, (fy + 0.5f) / 2, Color::Constant(float(fx + 10 * fy)), 1};
    }
  // blur of a linear field is the identity inside; at the edges the renormalised taps are
  // x: (2v0 + v1)/3 at 0, (v2 + 2v3)/3 at 3 -> 1/3, 1, 2, 8/3; y: rows (2 r0 + r1)/3, (r0 + 2 r1)/3 -> 10/3, 20/3
  const double bx[4] = {1.0 / 3, 1, 2, 8.0 / 3}, by[2] = {10.0 / 3, 20.0 / 3};
  const Image img = reconstruct(b, *makeFilter("box", 0.5f), ReconMode::Supersample, 1).image;
  for (int i = 0; i < 2; ++i) {
    const double want = (bx[2 * i] + bx[2 * i + 1]) / 2 + (by[0] + by[1]) / 2;
    EXPECT_NEAR(img.get(i, 0)[0], want, 1e-5);
  }
}

TEST(Film, ModeNamesRoundTrip) {
  for (ReconMode m : kModes) EXPECT_EQ(parseReconMode(toString(m)), m);
  EXPECT_THROW(parseReconMode("gather"), OptionError);
}

TEST(Visualize, RenderFilterReproducesClassicTentPicture) {
  auto f = makeFilter("tent", 1.7f);
  const Image img = renderFilter(*f, 9, 9, 20);
  ASSERT_EQ(img.width(), 181);
  ASSERT_EQ(img.height(), 181);
  // corner (5.05, 5.05) of image pixel (101, 101), offset (0.55, 0.55) from (4.5, 4.5)
  EXPECT_NEAR(img.get(101, 101)[0], 1 - std::hypot(0.55, 0.55) / 1.7, 1e-6);
  EXPECT_NEAR(img.get(90, 95)[1], 1 - std::hypot(0.0, 0.25) / 1.7, 1e-6);
  EXPECT_EQ(img.get(90, 95)[0], img.get(90, 95)[2]);  // grey
  EXPECT_TRUE((img.get(41, 101) == Color(0, 0, 0)).all());   // in the support square, weight 0
  EXPECT_TRUE((img.get(21, 21) == Color(0, 0, 0.5f)).all()); // outside the support cells
  EXPECT_TRUE((img.get(100, 57) == Color(0, 0, 1)).all());   // grid column
  EXPECT_TRUE((img.get(57, 180) == Color(0, 0, 1)).all());   // last grid row
}

TEST(Visualize, RenderFilterSignedDrawsEvalCutAtTheRadiusAboveAColourBar) {
  auto f = makeFilter("gaussian", 1.f, {{"sigma", 1.0}});
  const Image img = renderFilterSigned(*f, 9, 9, 20);
  ASSERT_EQ(img.width(), std::max(181, kColorBarMinWidth));
  ASSERT_EQ(img.height(), 181 + kColorBarHeight);
  const int b = kColorBarHeight;
  // offset (0.55, 0.55) from (4.5, 4.5): d = 0.78 inside, weight exp(-d^2 / 2), shown as sqrt of it
  const float w = std::exp(-0.5f * (0.55f * 0.55f * 2));
  EXPECT_NEAR(img.get(101, b + 101)[1], 1 - std::sqrt(w), 1e-5);
  EXPECT_NEAR(img.get(101, b + 101)[0], 1, 1e-6);
  EXPECT_TRUE((img.get(112, b + 101) == Color(1, 1, 1)).all());  // offset (1.1, 0.55): beyond r = 1, white
  EXPECT_TRUE((img.get(100, b + 57) == Color::Constant(0.55f)).all());  // grid column
  // the bar runs blue (left) through white to red (right)
  const int barRow = kColorBarHeight - 1 - 8;
  EXPECT_TRUE((img.get(4, barRow) == Color(0, 0, 1)).all());
  EXPECT_TRUE((img.get(img.width() - 5, barRow) == Color(1, 0, 0)).all());
}

TEST(Visualize, RenderSamplesPutsEachSampleInItsPixel) {
  const SampleBuffer b = makeSamples(3, 2, 2, 4, noisy);
  const Image img = renderSamples(b, 10);
  ASSERT_EQ(img.width(), 30);
  ASSERT_EQ(img.height(), 20);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const FilmSample& s = b.pixel(i, j)[1];
      const int x = int(std::floor(s.x * 10)), y = int(std::floor(s.y * 10));
      EXPECT_EQ(x / 10, i);
      EXPECT_EQ(y / 10, j);
      EXPECT_TRUE((img.get(x, y) == s.L).all());
    }
  EXPECT_FLOAT_EQ(renderSamples(SampleBuffer(2, 2, 0), 4).get(1, 1)[0], 0.2f);  // (0,0) even: grey
  EXPECT_FLOAT_EQ(renderSamples(SampleBuffer(2, 2, 0), 4).get(5, 1)[0], 0.f);   // (1,0) odd: black
}

TEST(Visualize, RenderSamplesShowsTheBlockNeighboursOffsets) {
  // 2x2 film, 1 spp: pixel (i, j)'s sample at offset (0.1 + 0.4 i, 0.1 + 0.4 j). At zoom 10 every cell
  // shows its own sample in its colour and the three others' offsets as ghosts; a ghost never covers
  // a sample, and zoom < 4 draws the classic picture only.
  SampleBuffer b(2, 2, 1);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      FilmSample& s = b.pixel(i, j)[0];
      s.x = i + 0.15f + 0.4f * i, s.y = j + 0.15f + 0.4f * j;
      s.L = Color(1.f, 0.5f * i, 0.5f * j);
    }
  const Image img = renderSamples(b, 10);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      for (int nj = 0; nj < 2; ++nj)
        for (int ni = 0; ni < 2; ++ni) {
          const int x = 10 * i + 1 + 4 * ni, y = 10 * j + 1 + 4 * nj;  // floor((i + 0.15 + 0.4 ni) * 10)
          const Color expect = (ni == i && nj == j) ? b.pixel(i, j)[0].L : Color(0.75f, 0.55f, 0.15f);
          EXPECT_TRUE((img.get(x, y) == expect).all()) << "cell " << i << "," << j << " offset of " << ni << "," << nj;
        }
  const Image small = renderSamples(b, 3);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 6; ++x) {
      const Color c = small.get(x, y);
      EXPECT_FALSE(c[0] == 0.75f && c[1] == 0.55f) << x << "," << y;
    }
}

TEST(Visualize, RenderSamplesMarkedOutlinesStrataAndRingsDarkSamples) {
  SampleBuffer b = makeSamples(2, 2, 1, 1, noisy);
  const Image plain = renderSamplesMarked(SampleBuffer(2, 2, 0), 20, 2, 2);  // 2 x 2 strata per 20-pixel cell
  const Color line(0.1f, 0.2f, 0.45f);
  EXPECT_TRUE((plain.get(9, 3) == line).all());   // x = 9..10 crosses the stratum boundary at 10
  EXPECT_TRUE((plain.get(3, 19) == line).all());  // the pixel boundary at 20 as well
  // a black sample far from the lines gets a white ring
  b.samples()[0].L = Color::Zero(), b.samples()[0].x = 0.26f, b.samples()[0].y = 0.26f;
  const Image marked = renderSamplesMarked(b, 20, 0, 0);
  EXPECT_TRUE((marked.get(5, 5) == Color::Zero()).all());
  EXPECT_TRUE((marked.get(6, 5) == Color::Ones()).all());
  EXPECT_TRUE((marked.get(4, 4) == Color::Ones()).all());
}

TEST(Visualize, ColourMapsKeepSignAndOrder) {
  Image e(3, 1);
  e.set(0, 0, Color::Constant(-1)), e.set(1, 0, Color::Zero()), e.set(2, 0, Color::Constant(0.5f));
  const Image fc = falseColor(e, 1.f);
  EXPECT_TRUE((fc.get(0, 0) == Color(0, 0, 1)).all());
  EXPECT_TRUE((fc.get(1, 0) == Color(1, 1, 1)).all());
  EXPECT_TRUE((fc.get(2, 0) == Color(1, 0.5f, 0.5f)).all());
  const Image hc = heatColor(e, 1.f);
  EXPECT_LT(hc.get(1, 0).sum(), hc.get(2, 0).sum());
  EXPECT_EQ(plotFilter(*makeFilter("lanczos", 2.f), 64).height(), 96);
}

}  // namespace
}  // namespace aliaslab

// Large sample buffers and sums come from core/huge_pages.h: 2 MB-aligned, and a freed block is handed out
// again for the same size (not under AddressSanitizer, which must see every free).
TEST(LargeBuffers, AlignedAndReusedForTheSameSize) {
  const size_t bytes = (size_t(5) << 20) + 123;  // rounds up to 6 MB
  void* a = aliaslab::allocateLarge(bytes);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(a) % (size_t(2) << 20), 0u);
  std::memset(a, 0x5a, bytes);  // the whole block is usable
  aliaslab::freeLarge(a, bytes);
  void* b = aliaslab::allocateLarge((size_t(6) << 20) - 7);  // same rounded size
#if defined(__SANITIZE_ADDRESS__)
  (void)b;
#else
  EXPECT_EQ(b, a);
#endif
  aliaslab::freeLarge(b, (size_t(6) << 20) - 7);
  // small blocks are plain malloc; a SampleBuffer's vector still starts value-initialised when reused
  void* s = aliaslab::allocateLarge(100);
  ASSERT_NE(s, nullptr);
  aliaslab::freeLarge(s, 100);
  for (int round = 0; round < 2; ++round) {
    aliaslab::SampleBuffer buf(512, 256, 16);  // 50 MB
    for (const aliaslab::FilmSample& f : buf.samples()) ASSERT_TRUE(f.x == 0 && f.y == 0 && f.weight == 1.f);
    for (aliaslab::FilmSample& f : buf.samples()) f.x = f.y = 7.f, f.weight = 3.f;
  }
}

// The variable-count buffer without the fill (SampleBuffer::Unwritten, for a caller that writes every sample:
// the adaptive gather) has the same layout as the filled one: counts, row counts and each pixel's first sample
// at the same offset (the prefix sums of the counts, summed here), and refuses the same bad counts. The filled
// one still starts as FilmSample{} in large memory that a previous buffer of the same size left dirty.
TEST(LargeBuffers, VariableCountUnwrittenHasTheFilledLayout) {
  using aliaslab::SampleBuffer;
  const int w = 300, h = 200;
  std::vector<int> counts(w * h);
  for (int p = 0; p < w * h; ++p) counts[p] = (p * 7919) % 23;  // 0 .. 22, zeros included
  for (int round = 0; round < 2; ++round) {
    SampleBuffer filled(w, h, counts), bare(w, h, counts, SampleBuffer::Unwritten{});
    ASSERT_EQ(bare.samples().size(), filled.samples().size());
    EXPECT_TRUE(bare.variable());
    size_t offset = 0;
    for (int j = 0; j < h; ++j) {
      size_t row = 0;
      for (int i = 0; i < w; ++i) {
        const int n = counts[size_t(j) * w + i];
        ASSERT_EQ(bare.count(i, j), n);
        ASSERT_EQ(bare.pixel(i, j) - bare.samples().data(), std::ptrdiff_t(offset));
        ASSERT_EQ(filled.pixel(i, j) - filled.samples().data(), std::ptrdiff_t(offset));
        offset += n, row += n;
      }
      ASSERT_EQ(bare.rowCount(j), row);
    }
    EXPECT_EQ(offset, bare.samples().size());
    for (const aliaslab::FilmSample& f : filled.samples()) ASSERT_TRUE(f.x == 0 && f.y == 0 && f.weight == 1.f);
    for (aliaslab::FilmSample& f : filled.samples()) f.x = f.y = 7.f, f.weight = 3.f;
    for (aliaslab::FilmSample& f : bare.samples()) f.x = f.y = 5.f, f.weight = 2.f;
  }
  EXPECT_THROW(SampleBuffer(2, 2, std::vector<int>(3, 1), SampleBuffer::Unwritten{}), std::invalid_argument);
  EXPECT_THROW(SampleBuffer(1, 2, std::vector<int>{1, -1}, SampleBuffer::Unwritten{}), std::invalid_argument);
}
