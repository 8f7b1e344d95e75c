// Reconstruction: every mode against the mathematics of docs/science.md, and the fast weighted average
// against the film's definition (film/film_definition.h).
#include <gtest/gtest.h>

#include <cstdint>

#include <chrono>
#include <cmath>
#include <limits>

#include "core/cpu.h"
#include "core/error.h"
#include "core/hash.h"
#include "film/film.h"
#include "film/film_definition.h"
#include "film/film_impl.h"
#include "filter/filter_sampler.h"
#include "support/film_samples.h"

namespace aliaslab {
namespace {

using testing::constant;
using testing::kConst;
using testing::makeSamples;
using testing::maxDiff;
using testing::noisy;

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

TEST(Film, OneAccumulatorPassEqualsEachReconstructionBitForBit) {
  // filters of equal radius share one pass (footprints once, then each filter's weights): the result must be
  // exactly each filter's own reconstruct(), including a unit-weight box, a radius wider than a block
  // (sample by sample) and a radius no other filter has; every filter at each radius the study uses, so
  // that weighted filters go two at a time through the pair kernels (n = 2 .. 6) where the CPU has them
  const SampleBuffer b = makeSamples(37, 29, 6, 21, noisy);
  std::vector<std::unique_ptr<Filter>> owned;
  for (float r : {1.f, 1.5f, 2.f, 2.3f, 3.f})
    for (const auto& name : allFilterNames()) owned.push_back(makeFilter(name, r));
  owned.push_back(makeFilter("box", 0.5f)), owned.push_back(makeFilter("tent", 9.f)), owned.push_back(makeFilter("lanczos", 9.f));
  owned.push_back(makeFilter("mitchell", 2.7f));
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

TEST(Film, PairKernelsSumBitForBitLikeTheSseKernels) {
  // with AVX2 + FMA, weighted filters of one radius accumulate two at a time (film/splat_kernels.cpp, pairAvx2);
  // without, one at a time in SSE: the same sums, for every block size the study uses (n = 1 .. 6) and an odd
  // number of weighted filters (the last one alone), in two bands and with two threads
  const SampleBuffer b = makeSamples(31, 45, 7, 5, noisy);
  std::vector<std::unique_ptr<Filter>> owned;
  for (float r : {0.5f, 1.f, 1.5f, 2.f, 2.3f, 3.f})
    for (const auto& name : filterNames()) owned.push_back(makeFilter(name, r));
  std::vector<const Filter*> filters;
  for (const auto& f : owned) filters.push_back(f.get());
  Accumulator fast(31, 45, filters), sse(31, 45, filters);
  fast.add(b, 2);
  {
    const ScopedCpuFeatures sseOnly(CpuFeatures{});
    sse.add(b, 2);
  }
  for (size_t k = 0; k < filters.size(); ++k)
    EXPECT_EQ(maxDiff(fast.resolve(k).image, sse.resolve(k).image), 0.0) << filters[k]->describe();
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

}  // namespace
}  // namespace aliaslab
