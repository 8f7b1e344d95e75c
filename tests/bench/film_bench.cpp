// Reconstruction throughput in sample-pixel contributions per second (one
// thread): the film's fast weighted average against the straightforward
// per-pixel gather the course writes (for each pixel, each neighbour pixel
// within ceil(r), each sample: a virtual eval()). The gather's output is
// checked against the fast path before it is timed.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>

#include "core/hash.h"
#include "film/film.h"

#include "bench_samples.h"

namespace aliaslab {
namespace {

constexpr int kSize = 256, kSpp = 64;

/// Hashed positions in each pixel.
const SampleBuffer& samples() {
  static const SampleBuffer b = benchSamples(kSize, kSpp, [](int i, int j, Vec2* u) {
    for (int k = 0; k < kSpp; ++k)
      u[k] = Vec2(toUnitFloat(hashWords(1, i, j, k, 0)), toUnitFloat(hashWords(1, i, j, k, 1)));
  });
  return b;
}

/// Sample-pixel pairs with the pixel centre inside the support, counted once per (shape, radius).
size_t contributions(const Filter& f) {
  static std::map<std::pair<bool, float>, size_t> cache;
  const auto key = std::make_pair(f.radial(), f.radius());
  if (cache.count(key)) return cache[key];
  const float r = f.radius();
  size_t n = 0;
  for (const FilmSample& s : samples().samples())
    for (int j = std::max(0, int(s.y - r - 1)); j <= std::min(kSize - 1, int(s.y + r + 1)); ++j)
      for (int i = std::max(0, int(s.x - r - 1)); i <= std::min(kSize - 1, int(s.x + r + 1)); ++i) {
        const float dx = s.x - (i + 0.5f), dy = s.y - (j + 0.5f);
        n += f.radial() ? dx * dx + dy * dy <= r * r : std::abs(dx) <= r && std::abs(dy) <= r;
      }
  return cache[key] = n;
}

/// The course's gather: every sample of every neighbour pixel within ceil(r), virtual eval.
Image naiveGather(const SampleBuffer& b, const Filter& f) {
  const int R = static_cast<int>(std::ceil(f.radius()));
  Image img(b.width(), b.height());
  for (int j = 0; j < b.height(); ++j)
    for (int i = 0; i < b.width(); ++i) {
      double num[3] = {0, 0, 0}, den = 0;
      for (int nj = std::max(0, j - R); nj <= std::min(b.height() - 1, j + R); ++nj)
        for (int ni = std::max(0, i - R); ni <= std::min(b.width() - 1, i + R); ++ni) {
          const FilmSample* s = b.pixel(ni, nj);
          for (int k = 0; k < b.spp(); ++k) {
            const double w = f.eval(s[k].x - (i + 0.5f), s[k].y - (j + 0.5f));
            for (int c = 0; c < 3; ++c) num[c] += w * s[k].L[c];
            den += w;
          }
        }
      img.set(i, j, Color(float(num[0] / den), float(num[1] / den), float(num[2] / den)));
    }
  return img;
}

void BM_Weighted(benchmark::State& state, const std::string& name, float radius) {
  auto f = makeFilter(name, radius);
  const SampleBuffer& b = samples();
  for (auto _ : state) benchmark::DoNotOptimize(reconstruct(b, *f, ReconMode::WeightedAverage, 1));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(contributions(*f)));
  state.SetLabel(f->describe());
}

void BM_NaiveGather(benchmark::State& state, const std::string& name, float radius) {
  auto f = makeFilter(name, radius);
  const SampleBuffer& b = samples();
  // same output up to rounding
  const Image fast = reconstruct(b, *f, ReconMode::WeightedAverage, 1).image, slow = naiveGather(b, *f);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i)
      if ((fast.get(i, j) - slow.get(i, j)).abs().maxCoeff() > 1e-5f) {
        state.SkipWithError("fast weighted average differs from the naive gather");
        return;
      }
  for (auto _ : state) benchmark::DoNotOptimize(naiveGather(b, *f));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(contributions(*f)));
  state.SetLabel(f->describe());
}

#define FILM_BENCH(filter)                                                         \
  BENCHMARK_CAPTURE(BM_Weighted, filter##_r0_5, #filter, 0.5f)->Unit(benchmark::kMillisecond); \
  BENCHMARK_CAPTURE(BM_Weighted, filter##_r1_5, #filter, 1.5f)->Unit(benchmark::kMillisecond); \
  BENCHMARK_CAPTURE(BM_Weighted, filter##_r2_3, #filter, 2.3f)->Unit(benchmark::kMillisecond); \
  BENCHMARK_CAPTURE(BM_NaiveGather, filter##_r2_3, #filter, 2.3f)->Unit(benchmark::kMillisecond)->Iterations(1);

FILM_BENCH(box)
FILM_BENCH(tent)
FILM_BENCH(gaussian)
FILM_BENCH(mitchell)
FILM_BENCH(lanczos)
FILM_BENCH(blackmanharris)

}  // namespace
}  // namespace aliaslab

BENCHMARK_MAIN();
