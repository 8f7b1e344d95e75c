// FLIP as the sweep computes it: one row image of a 256 x 256 render (the presented study's size) against the
// row's three targets (area, gaussian:1.5 and lanczos:3 reconstructions of a 64-spp set). One thread; time per
// image, items = pixels.
//   Definition/Row3         before: the scalar definition (libm) per target, the image's side redone for each
//                           (what the sweep did up to a22d95c, bit for bit)
//   Fast/Row3               after: meanFlips, the image's side once, vectorised cube roots and powers
//   Definition/One, Fast/One   one target
//   Stage1/Linear           the exact convolutions (shared by both)
//   Stage2/{Definition,Fast}   Lab and feature magnitudes of one image
//   Stage3/{Definition,Fast}   the per-pixel combination against one target
// Run with --benchmark_enable_random_interleaving=true --benchmark_repetitions=N on a shared machine.
#include <benchmark/benchmark.h>

#include <memory>

#include "aliaslab_paths.h"
#include "film/film.h"
#include "filter/filter.h"
#include "measure/flip/flip.h"
#include "measure/flip/flip_definition.h"
#include "render/render.h"
#include "sampling/sampler.h"
#include "study/study_scene.h"

namespace aliaslab {
namespace {

struct Work {
  Image test;
  std::vector<Image> targets;
  std::vector<std::unique_ptr<FlipReference>> prepared;
  std::vector<FlipPlanes> definitionPlanes;
  std::vector<const FlipReference*> pointers;
};

const Work& work() {
  static const Work w = [] {
    Work w;
    const auto s = loadStudyScene(std::string(ALIASLAB_SOURCE_DIR) + "/scenes/fence.txt", 256, 256);
    const SampleBuffer ref = traceSamples(*s->tracer, *makeSampler("jittered", 64, 9), s->width, s->height, 0);
    for (auto [name, r] : {std::pair{"box", 0.5f}, {"gaussian", 1.5f}, {"lanczos", 3.f}})
      w.targets.push_back(reconstruct(ref, *makeFilter(name, r), ReconMode::WeightedAverage, 0).image);
    const SampleBuffer row = traceSamples(*s->tracer, *makeSampler("jittered", 4, 1), s->width, s->height, 0);
    w.test = reconstruct(row, *makeFilter("mitchell", 2), ReconMode::WeightedAverage, 0).image;
    for (const Image& t : w.targets) {
      w.prepared.push_back(std::make_unique<FlipReference>(t));
      w.pointers.push_back(w.prepared.back().get());
      w.definitionPlanes.push_back(flipPlanesDefinition(flipLinear(t, kFlipDefaultPixelsPerDegree)));
    }
    return w;
  }();
  return w;
}

void pixels(benchmark::State& state) { state.SetItemsProcessed(state.iterations() * work().test.width() * work().test.height()); }

// The definition against prepared targets (the old FlipReference): the image's side per target.
void definitionRow(benchmark::State& state, size_t targets) {
  const Work& w = work();
  std::vector<float> map(static_cast<size_t>(w.test.width()) * w.test.height());
  for (auto _ : state)
    for (size_t j = 0; j < targets; ++j) {
      const FlipPlanes t = flipPlanesDefinition(flipLinear(w.test, kFlipDefaultPixelsPerDegree));
      flipCombineDefinition(t, w.definitionPlanes[j], map.data());
      benchmark::DoNotOptimize(map.data());
    }
  pixels(state);
}
void fastRow(benchmark::State& state, size_t targets) {
  const Work& w = work();
  const std::vector<const FlipReference*> some(w.pointers.begin(), w.pointers.begin() + targets);
  for (auto _ : state) benchmark::DoNotOptimize(meanFlips(w.test, some));
  pixels(state);
}
void stage1(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(flipLinear(work().test, kFlipDefaultPixelsPerDegree));
  pixels(state);
}
void stage2(benchmark::State& state, bool fast) {
  const FlipLinear lin = flipLinear(work().test, kFlipDefaultPixelsPerDegree);
  for (auto _ : state) benchmark::DoNotOptimize(fast ? flipPlanesFast(lin) : flipPlanesDefinition(lin));
  pixels(state);
}
void stage3(benchmark::State& state, bool fast) {
  const Work& w = work();
  const FlipLinear lin = flipLinear(w.test, kFlipDefaultPixelsPerDegree);
  const FlipPlanes t = flipPlanesDefinition(lin);
  std::vector<float> map(t.L.size());
  for (auto _ : state) {
    (fast ? flipCombineFast : flipCombineDefinition)(t, w.definitionPlanes[0], map.data());
    benchmark::DoNotOptimize(map.data());
  }
  pixels(state);
}

BENCHMARK_CAPTURE(definitionRow, Row3, 3)->Name("Definition/Row3")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fastRow, Row3, 3)->Name("Fast/Row3")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(definitionRow, One, 1)->Name("Definition/One")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fastRow, One, 1)->Name("Fast/One")->Unit(benchmark::kMillisecond);
BENCHMARK(stage1)->Name("Stage1/Linear")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stage2, Definition, false)->Name("Stage2/Definition")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stage2, Fast, true)->Name("Stage2/Fast")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stage3, Definition, false)->Name("Stage3/Definition")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stage3, Fast, true)->Name("Stage3/Fast")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace aliaslab

BENCHMARK_MAIN();
