// The error metrics as the sweep computes them for one configuration (study/sweep/row_measure.cpp): 256 x 256
// images (the presented study's size), G and three targets with halves, K = 8 images added to a
// MetricAccumulator, then result(). One thread; time per configuration.
//   Metrics/Add8Result  the K images added, then result()
//   Metrics/Add8        the K images added alone
//   Metrics/Result      result() alone (the K images already added)
// Run with --benchmark_enable_random_interleaving=true --benchmark_repetitions=N on a shared machine.
#include <benchmark/benchmark.h>

#include "bench_images.h"
#include "measure/metrics.h"

namespace aliaslab {
namespace {

constexpr int kSize = 256, kSeeds = 8, kTargets = 3;

Image noisyPattern(uint64_t seed, double noise) { return benchPattern(seed, noise, kSize); }

struct MetricWork {
  Image g = noisyPattern(1, 0.01), gHalf = noisyPattern(2, 0.003);
  std::vector<Image> t, tHalf, images;
  std::vector<RefEstimate> targets;
  MetricWork() {
    for (int j = 0; j < kTargets; ++j)
      t.push_back(noisyPattern(3 + j, 0.02)), tHalf.push_back(noisyPattern(6 + j, 0.003));
    for (int j = 0; j < kTargets; ++j) targets.push_back({&t[j], &tHalf[j], 1.5 + j});
    for (int k = 0; k < kSeeds; ++k) images.push_back(noisyPattern(20 + k, 0.2));
  }
  RefEstimate own() const { return {&g, &gHalf, 2.0}; }
};

const MetricWork& metricWork() {
  static const MetricWork w;
  return w;
}

void Add8Result(benchmark::State& state) {
  const MetricWork& w = metricWork();
  for (auto _ : state) {
    MetricAccumulator a(w.own(), w.targets);
    for (const Image& im : w.images) a.add(im);
    benchmark::DoNotOptimize(a.result());
  }
}
void Add8(benchmark::State& state) {
  const MetricWork& w = metricWork();
  for (auto _ : state) {
    MetricAccumulator a(w.own(), w.targets);
    for (const Image& im : w.images) a.add(im);
    benchmark::DoNotOptimize(a);
  }
}
void ResultOnly(benchmark::State& state) {
  const MetricWork& w = metricWork();
  MetricAccumulator a(w.own(), w.targets);
  for (const Image& im : w.images) a.add(im);
  for (auto _ : state) benchmark::DoNotOptimize(a.result());
}

}  // namespace

BENCHMARK(Add8Result)->Name("Metrics/Add8Result")->Unit(benchmark::kMillisecond);
BENCHMARK(Add8)->Name("Metrics/Add8")->Unit(benchmark::kMillisecond);
BENCHMARK(ResultOnly)->Name("Metrics/Result")->Unit(benchmark::kMillisecond);

}  // namespace aliaslab

BENCHMARK_MAIN();
