// The splat of the study's references and rows (one thread, 256 x 256 pixels, sobol positions, hashed
// radiance): one 16-spp sample set (a reference batch: a 4096-spp reference adds 256 of them) into every
// filter of the presented study at once (26 (filter, radius) pairs, film/film.h Accumulator), and into one
// filter at a time (a study row). Items = samples splatted (each into every filter of the call).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "core/hash.h"
#include "film/film.h"
#include "film/film_impl.h"
#include "sampling/sampler.h"

#include "bench_samples.h"

namespace aliaslab {
namespace {

constexpr int kSize = 256, kSpp = 16;

/// Sobol positions in each pixel.
const SampleBuffer& samples() {
  static const SampleBuffer b = [] {
    const auto sampler = makeSampler("sobol", kSpp, 7);
    return benchSamples(kSize, kSpp, [&](int i, int j, Vec2* u) { sampler->generate(i, j, u); });
  }();
  return b;
}

/// The presented study's (filter, radius) pairs: every study filter at 0.5, 1, 2, and the targets gaussian:1.5
/// and lanczos:3 (area is box:0.5).
std::vector<std::unique_ptr<Filter>> studyFilters() {
  std::vector<std::unique_ptr<Filter>> out;
  for (float r : {0.5f, 1.f, 2.f})
    for (const std::string& name : filterNames()) out.push_back(makeFilter(name, r));
  out.push_back(makeFilter("gaussian", 1.5f)), out.push_back(makeFilter("lanczos", 3.f));
  return out;
}

/// One reference batch into all 26 filters (a 4096-spp reference does this 256 times, 128 per half).
void BM_AllFilters(benchmark::State& state) {
  const auto filters = studyFilters();
  std::vector<const Filter*> raw;
  for (const auto& f : filters) raw.push_back(f.get());
  std::vector<std::vector<double>> sums(raw.size(), std::vector<double>(4 * size_t(kSize) * kSize));
  std::vector<double*> out;
  for (auto& s : sums) out.push_back(s.data());
  for (auto _ : state) {
    filmimpl::splatAll(samples(), {raw, out, nullptr, true}, 1);
    benchmark::DoNotOptimize(sums[0][0]);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(samples().samples().size()));
}
BENCHMARK(BM_AllFilters)->Unit(benchmark::kMillisecond);

/// One filter (a study row's splat).
void BM_OneFilter(benchmark::State& state, const std::string& name, float radius) {
  const auto f = makeFilter(name, radius);
  std::vector<double> sums(4 * size_t(kSize) * kSize);
  const std::vector<const Filter*> filters{f.get()};
  const std::vector<double*> targets{sums.data()};
  for (auto _ : state) {
    filmimpl::splatAll(samples(), {filters, targets, nullptr, true}, 1);
    benchmark::DoNotOptimize(sums[0]);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(samples().samples().size()));
  state.SetLabel(f->describe());
}
#define ONE_FILTER(filter, tag, r) \
  BENCHMARK_CAPTURE(BM_OneFilter, filter##_##tag, #filter, r)->Unit(benchmark::kMillisecond);
ONE_FILTER(box, r0_5, 0.5f)
ONE_FILTER(tent, r1, 1.f)
ONE_FILTER(mitchell, r2, 2.f)
ONE_FILTER(gaussian, r2, 2.f)
ONE_FILTER(blackmanharris, r2, 2.f)
ONE_FILTER(lanczos, r3, 3.f)

}  // namespace
}  // namespace aliaslab

BENCHMARK_MAIN();
