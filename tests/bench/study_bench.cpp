// The sweep's promise: one sample set is traced once and reconstructed with
// every (filter, radius), so one more (filter, radius) should cost little
// next to the trace (target: at most 5 %). Per scene in scenes/ at its
// # render: aspect with larger side kMaxSize, jittered kSpp samples per
// pixel, one thread:
//   Trace/<scene>                     traceSamples(): one sample set
//   OneMore/<scene>/<filter>_r<r>     what the sweep does per extra row and
//                                     seed: reconstruct() (weighted average)
//                                     and the MetricAccumulator update
// Each OneMore run reports extra_cost = its time / the Trace time of the
// same scene measured just before it in the same run (the Trace benchmark
// of a scene is registered, so it runs, before that scene's OneMore ones).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>

#include "film/film.h"
#include "render/render.h"
#include "sampling/sampler.h"
#include "study/config.h"
#include "study/metrics.h"
#include "study/study_scene.h"

namespace aliaslab {
namespace {

constexpr int kMaxSize = 128, kSpp = 16;

struct Workload {
  std::unique_ptr<StudyScene> scene;
  std::unique_ptr<Sampler> sampler;
  SampleBuffer samples;
  double traceSeconds = 0;  ///< per sample set, from the Trace benchmark
};

Workload& workload(const std::string& path) {
  static std::map<std::string, Workload> cache;
  Workload& w = cache[path];
  if (!w.scene) {
    const auto native = loadStudyScene(path);  // its # render: size, scaled to larger side kMaxSize
    const double scale = double(kMaxSize) / std::max(native->width, native->height);
    w.scene = loadStudyScene(path, std::max(1, int(std::lround(native->width * scale))),
                             std::max(1, int(std::lround(native->height * scale))));
    w.sampler = makeSampler("jittered", kSpp, 1);
    w.samples = traceSamples(*w.scene->tracer, *w.sampler, w.scene->width, w.scene->height, 1);
  }
  return w;
}

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void trace(benchmark::State& state, const std::string& path) {
  Workload& w = workload(path);
  double total = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(traceSamples(*w.scene->tracer, *w.sampler, w.scene->width, w.scene->height, 1));
    total += seconds(t0);
  }
  w.traceSeconds = total / static_cast<double>(state.iterations());
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(w.samples.samples().size()));
  state.SetLabel(std::to_string(w.scene->width) + "x" + std::to_string(w.scene->height) + " " +
                 std::to_string(kSpp) + " spp");
}

void oneMore(benchmark::State& state, const std::string& path, const std::string& filterName, float radius) {
  Workload& w = workload(path);
  const auto filter = makeFilter(filterName, radius);
  const Image stand = reconstruct(w.samples, *filter, ReconMode::WeightedAverage, 1).image;  // any image will do
  MetricAccumulator metrics(stand, stand);
  double total = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const Reconstruction r = reconstruct(w.samples, *filter, ReconMode::WeightedAverage, 1);
    metrics.add(r.image);
    total += seconds(t0);
  }
  const double perRow = total / static_cast<double>(state.iterations());
  if (w.traceSeconds > 0) state.counters["extra_cost"] = perRow / w.traceSeconds;
  state.SetLabel(filter->describe());
}

}  // namespace
}  // namespace aliaslab

int main(int argc, char** argv) {
  using namespace aliaslab;
  benchmark::Initialize(&argc, argv);
  const std::pair<const char*, float> filters[] = {
      {"box", 0.5f}, {"tent", 1.f}, {"gaussian", 1.f}, {"mitchell", 2.f}, {"lanczos", 2.f}};
  for (const std::string& path : expandScenePaths({ALIASLAB_SOURCE_DIR "/scenes"})) {
    const std::string stem = std::filesystem::path(path).stem().string();
    benchmark::RegisterBenchmark(("Trace/" + stem).c_str(), trace, path)->Unit(benchmark::kMillisecond);
    for (const auto& [name, radius] : filters) {
      char label[64];
      std::snprintf(label, sizeof label, "OneMore/%s/%s_r%g", stem.c_str(), name, radius);
      benchmark::RegisterBenchmark(label, oneMore, path, std::string(name), radius)->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
