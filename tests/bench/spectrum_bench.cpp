// The spectra as the sweep computes them for one configuration: 256 x 256 images (the presented study's size),
// G and three targets with halves, K = 8 images. One thread; time per configuration.
//   Definition/Setup    before: each configuration making its own references' side (full-plane DFTs of G - T, the
//                       half-differences' energies), as up to 3d442ac
//   Shared/Setup        after: a configuration of a G whose SpectrumReference is already made (shared)
//   Reference/Make      making one SpectrumReference (once per G and scene)
//   Definition/Add8, Half/Add8   the K images added (full plane / half plane), then result()
// Run with --benchmark_enable_random_interleaving=true --benchmark_repetitions=N on a shared machine.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "bench_images.h"
#include "measure/spectrum.h"
#include "measure/spectrum_definition.h"

namespace aliaslab {
namespace {

constexpr int kSize = 256, kSeeds = 8;

Image pattern(uint64_t seed, double noise) { return benchPattern(seed, noise, kSize); }

struct Work {
  Image g = pattern(1, 0.01), gHalf = pattern(2, 0.003);
  std::vector<Image> t, tHalf, images;
  std::vector<RefEstimate> targets;
  std::shared_ptr<const SpectrumReference> shared;
  Work() {
    for (int j = 0; j < 3; ++j) t.push_back(pattern(3 + j, 0.02)), tHalf.push_back(pattern(6 + j, 0.003));
    for (int j = 0; j < 3; ++j) targets.push_back({&t[j], &tHalf[j]});
    for (int k = 0; k < kSeeds; ++k) images.push_back(pattern(20 + k, 0.2));
    shared = std::make_shared<const SpectrumReference>(RefEstimate{&g, &gHalf}, targets);
  }
};

const Work& work() {
  static const Work w;
  return w;
}

void DefinitionSetup(benchmark::State& state) {
  const Work& w = work();
  for (auto _ : state) {
    SpectrumDefinition d({&w.g, &w.gHalf}, w.targets);
    benchmark::DoNotOptimize(d);
  }
}
void SharedSetup(benchmark::State& state) {
  const Work& w = work();
  for (auto _ : state) {
    SpectrumAccumulator a(w.shared);
    benchmark::DoNotOptimize(a);
  }
}
void ReferenceMake(benchmark::State& state) {
  const Work& w = work();
  for (auto _ : state) benchmark::DoNotOptimize(SpectrumReference({&w.g, &w.gHalf}, w.targets));
}
void DefinitionAdd8(benchmark::State& state) {
  const Work& w = work();
  SpectrumDefinition d({&w.g, &w.gHalf}, w.targets);
  for (auto _ : state) {
    SpectrumDefinition a = d;
    for (const Image& im : w.images) a.add(im);
    benchmark::DoNotOptimize(a.result());
  }
}
void HalfAdd8(benchmark::State& state) {
  const Work& w = work();
  for (auto _ : state) {
    SpectrumAccumulator a(w.shared);
    for (const Image& im : w.images) a.add(im);
    benchmark::DoNotOptimize(a.result());
  }
}

BENCHMARK(DefinitionSetup)->Name("Definition/Setup")->Unit(benchmark::kMillisecond);
BENCHMARK(SharedSetup)->Name("Shared/Setup")->Unit(benchmark::kMillisecond);
BENCHMARK(ReferenceMake)->Name("Reference/Make")->Unit(benchmark::kMillisecond);
BENCHMARK(DefinitionAdd8)->Name("Definition/Add8")->Unit(benchmark::kMillisecond);
BENCHMARK(HalfAdd8)->Name("Half/Add8")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace aliaslab

BENCHMARK_MAIN();
