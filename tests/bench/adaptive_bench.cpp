// Trace time of the adaptive samplers against their base sampler for the same number of rays (issue: at most
// about 1.3x): traceSamples(jittered) and traceAdaptive(adaptive-METHOD:jittered) on fence, checker_horizon and
// scenes/controls/edge.txt at 128 x 128, 16 samples per pixel (262,144 rays either way), one thread, the
// default aggregate. items/s is rays per second. Retrace/NAME/SCENE traces the very rays of one adaptive sample
// set (its positions, computed before the timing) in pixel order, writing a buffer: the cost of those rays
// without the method's bookkeeping, since adaptive rays are not average rays (they crowd where the geometry is:
// on fence they are about 2x dearer than the base sampler's). RetraceRounds/NAME/SCENE (contrast, error) traces
// them in the method's order instead (the pilot round, then the rest, each tile by tile). For same-run ratios run with
// --benchmark_repetitions=N --benchmark_enable_random_interleaving=true (the machine is shared). The process keeps
// freed medium blocks in its heap (keepMediumBlocks(), core/huge_pages.h) as the sweep does (study/sweep.cpp):
// otherwise glibc returns the rounds' buffers (0.1 to 2 MB) to the kernel after every trace and the next one
// faults them in again, a cost (5 to 10 % of an adaptive trace in perf) that the study does not pay.
#include "aliaslab_paths.h"
#include <benchmark/benchmark.h>

#include <map>

#include "accel/aggregate.h"
#include "core/huge_pages.h"
#include "render/adaptive.h"
#include "render/render.h"
#include "scene/scene.h"

namespace aliaslab {
namespace {

constexpr int kSize = 128, kSpp = 16;

struct Loaded {
  Scene scene;
  std::unique_ptr<Aggregate> aggregate;
  std::unique_ptr<Tracer> tracer;
};

const Tracer& tracerFor(const std::string& file) {
  static std::map<std::string, Loaded> cache;
  auto it = cache.find(file);
  if (it != cache.end()) return *it->second.tracer;
  Loaded& l = cache[file];
  l.scene = parseScene(std::string(ALIASLAB_SOURCE_DIR) + "/scenes/" + file);
  l.aggregate = makeDefaultAggregate(*l.scene.root);
  l.tracer = std::make_unique<Tracer>(l.scene, *l.aggregate, TraceOptions{});
  return *l.tracer;
}

void base(benchmark::State& state, std::string file) {
  const Tracer& t = tracerFor(file);
  const auto sampler = makeSampler("jittered", kSpp, 1);
  for (auto _ : state) benchmark::DoNotOptimize(traceSamples(t, *sampler, kSize, kSize, 1).samples().data());
  state.SetItemsProcessed(state.iterations() * kSize * kSize * kSpp);
}

void adaptive(benchmark::State& state, std::string file, std::string name) {
  const Tracer& t = tracerFor(file);
  const auto sampler = makeAdaptiveSampler(name, kSpp, 1);
  for (auto _ : state) benchmark::DoNotOptimize(traceAdaptive(t, *sampler, kSize, kSize, 1).samples().data());
  state.SetItemsProcessed(state.iterations() * kSize * kSize * kSpp);
}

void retrace(benchmark::State& state, std::string file, std::string name) {
  const Tracer& t = tracerFor(file);
  const SampleBuffer rays = traceAdaptive(t, *makeAdaptiveSampler(name, kSpp, 1), kSize, kSize, 1);
  for (auto _ : state) {
    std::vector<FilmSample> out(rays.samples().size());
    for (size_t k = 0; k < out.size(); ++k) {
      out[k] = rays.samples()[k];
      out[k].L = t.radianceAt(out[k].x, out[k].y, kSize, kSize);
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * kSize * kSize * kSpp);
}

// RetraceRounds: the same rays in the order the method traces them (contrast and error: the pilot, 4 per pixel
// at 16 spp, then the rest; each round tile by tile, 16 x 16 pixels, as Work::trace), to tell the cost of the
// order from the cost of the bookkeeping.
void retraceRounds(benchmark::State& state, std::string file, std::string name) {
  const Tracer& t = tracerFor(file);
  const SampleBuffer rays = traceAdaptive(t, *makeAdaptiveSampler(name, kSpp, 1), kSize, kSize, 1);
  constexpr int kPilot = 4, kTile = 16;
  for (auto _ : state) {
    std::vector<FilmSample> out(rays.samples().size());
    for (int pass = 0; pass < 2; ++pass)
      for (int tile = 0; tile < (kSize / kTile) * (kSize / kTile); ++tile)
        for (int j = tile / (kSize / kTile) * kTile; j < (tile / (kSize / kTile) + 1) * kTile; ++j)
          for (int i = tile % (kSize / kTile) * kTile; i < (tile % (kSize / kTile) + 1) * kTile; ++i) {
            const FilmSample* in = rays.pixel(i, j);
            const size_t at = static_cast<size_t>(in - rays.samples().data());
            const int from = pass == 0 ? 0 : kPilot, to = pass == 0 ? kPilot : rays.count(i, j);
            for (int k = from; k < to; ++k) {
              out[at + k] = in[k];
              out[at + k].L = t.radianceAt(in[k].x, in[k].y, kSize, kSize);
            }
          }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * kSize * kSize * kSpp);
}

const int registered = [] {
  keepMediumBlocks();
  for (const char* file : {"fence.txt", "checker_horizon.txt", "controls/edge.txt"}) {
    const std::string stem = std::string(file).substr(0, std::string(file).find('.'));
    benchmark::RegisterBenchmark(("Trace/jittered/" + stem).c_str(), base, std::string(file))
        ->Unit(benchmark::kMillisecond);
    for (const std::string& m : adaptiveMethodNames())
      benchmark::RegisterBenchmark(("Trace/adaptive-" + m + ":jittered/" + stem).c_str(), adaptive, std::string(file),
                                   "adaptive-" + m + ":jittered")
          ->Unit(benchmark::kMillisecond);
    for (const std::string& m : adaptiveMethodNames())
      benchmark::RegisterBenchmark(("Retrace/adaptive-" + m + ":jittered/" + stem).c_str(), retrace, std::string(file),
                                   "adaptive-" + m + ":jittered")
          ->Unit(benchmark::kMillisecond);
    for (const char* m : {"contrast", "error"})
      benchmark::RegisterBenchmark(("RetraceRounds/adaptive-" + std::string(m) + ":jittered/" + stem).c_str(),
                                   retraceRounds, std::string(file), "adaptive-" + std::string(m) + ":jittered")
          ->Unit(benchmark::kMillisecond);
  }
  return 0;
}();

}  // namespace
}  // namespace aliaslab

BENCHMARK_MAIN();
