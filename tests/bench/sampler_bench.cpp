// Sampler throughput in 2-D points per second, single thread: generate() over
// a 64 x 64 block of pixels per iteration at spp 16 and 64, for every
// registered sampler (construction, e.g. pmj02's pool, is outside the loop).
// Targets: sobol >= 50 M points/s/core, cmj >= 20 M.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "sampling/sampler.h"

using namespace aliaslab;

namespace {

void BM_Sampler(benchmark::State& state, const std::string& name) {
  const int spp = static_cast<int>(state.range(0));
  const auto sampler = makeSampler(name, spp, 1);
  std::vector<Vec2> out(spp);
  constexpr int kSide = 64;
  int frame = 0;
  for (auto _ : state) {
    for (int py = 0; py < kSide; ++py)
      for (int px = 0; px < kSide; ++px) {
        sampler->generate(px + frame * kSide, py, out.data());
        benchmark::DoNotOptimize(out.data());
      }
    ++frame;
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kSide * kSide * spp);
  state.SetLabel(sampler->describe());
}

const int kRegistered = [] {
  for (const std::string& name : samplerNames())
    benchmark::RegisterBenchmark(("sampler/" + name).c_str(), BM_Sampler, name)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond);
  return 0;
}();

}  // namespace

BENCHMARK_MAIN();
