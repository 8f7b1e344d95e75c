// The sweep's promise: one sample set is traced once and reconstructed with
// every (filter, radius), so one more (filter, radius) should cost little
// next to the trace (target: at most 5 %). Per scene in scenes/ at its
// # render: aspect with larger side kMaxSize, jittered kSpp samples per
// pixel, one thread:
//   Trace/<scene>                     traceSamples(): one sample set
//   OneMore/<scene>/<filter>_r<r>     what the sweep does per extra row and
//                                     seed: reconstruct() (weighted average)
//                                     and the MetricAccumulator update
//   Sweep15/<scene>                   the sweep's way: the default study's 15
//                                     weighted pairs (box, tent, gaussian,
//                                     mitchell, lanczos x r = 0.5, 1, 2) from
//                                     one Accumulator pass that shares each
//                                     radius's footprints, then resolve and
//                                     metrics per pair
// Each OneMore run reports extra_cost = its time / the Trace time of the
// same scene measured just before it in the same run (the Trace benchmark
// of a scene is registered, so it runs, before that scene's OneMore ones);
// Sweep15 reports extra_avg (mean pair) and each pair's own extra cost, and
// splits the mean pair into shared_avg (1/15 of the work no filter owns:
// finiteness, fallback sums, each radius's footprints, band set-up and
// merging), own_avg (the filter's weights and accumulation), resolve_avg
// (its resolve and metric update) and sums_avg (1/15 of making and freeing
// the accumulator, whose sums are 4 doubles per pixel and filter).
#include "aliaslab_paths.h"
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>

#include "film/film.h"
#include "render/render.h"
#include "sampling/sampler.h"
#include "study/config.h"
#include "measure/metrics.h"
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
  MetricAccumulator metrics(RefEstimate{&stand}, {RefEstimate{&stand}});
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

/// The default study's 15 weighted (filter, radius) pairs of one sample set as the sweep runs them: one
/// Accumulator pass (shared footprints per radius), then resolve and the metric update per pair. Each pair's
/// cost is its share from Accumulator::add (own weights and accumulation plus an equal part of the shared
/// work) plus its resolve and metrics; extra_avg = mean pair cost / trace; extra_<filter>_r<r>: each pair's.
void sweepPairs(benchmark::State& state, const std::string& path) {
  Workload& w = workload(path);
  const char* names[] = {"box", "tent", "gaussian", "mitchell", "lanczos"};
  std::vector<std::unique_ptr<Filter>> owned;
  std::vector<const Filter*> filters;
  std::vector<std::string> labels;
  for (float r : {0.5f, 1.f, 2.f})
    for (const char* name : names) {
      owned.push_back(makeFilter(name, r)), filters.push_back(owned.back().get());
      char label[48];
      std::snprintf(label, sizeof label, "extra_%s_r%g", name, r);
      labels.push_back(label);
    }
  const Image stand = reconstruct(w.samples, *filters[0], ReconMode::WeightedAverage, 1).image;
  std::vector<MetricAccumulator> metrics(filters.size(), MetricAccumulator(RefEstimate{&stand}, {RefEstimate{&stand}}));
  std::vector<double> pairSeconds(filters.size(), 0.0);
  // the work no filter owns; resolve and metrics of every pair; making and freeing the accumulator
  double sharedTotal = 0, resolveTotal = 0, sumsTotal = 0;
  for (auto _ : state) {
    auto t0 = std::chrono::steady_clock::now();
    auto acc = std::make_unique<Accumulator>(w.scene->width, w.scene->height, filters);
    sumsTotal += aliaslab::seconds(t0);
    acc->measureShares();
    acc->add(w.samples, 1);
    const std::vector<double>& seconds = acc->filterSeconds();
    sharedTotal += acc->sharedSeconds();
    for (size_t k = 0; k < filters.size(); ++k) {
      t0 = std::chrono::steady_clock::now();
      metrics[k].add(acc->resolve(k).image);
      const double resolveAndMetrics = aliaslab::seconds(t0);
      resolveTotal += resolveAndMetrics;
      pairSeconds[k] += seconds[k] + resolveAndMetrics;
    }
    t0 = std::chrono::steady_clock::now();
    acc.reset();
    sumsTotal += aliaslab::seconds(t0);
  }
  if (w.traceSeconds <= 0) return;
  const double per = static_cast<double>(state.iterations()) * w.traceSeconds;
  const double pairs = static_cast<double>(filters.size());
  double total = sumsTotal;  // each pair's sums are its own memory: an equal share of making and freeing them
  for (size_t k = 0; k < filters.size(); ++k) total += pairSeconds[k];
  state.counters["extra_avg"] = total / pairs / per;
  // extra_avg = shared_avg (1/15 of the shared work) + own_avg (weights, accumulation) + resolve_avg + sums_avg
  state.counters["shared_avg"] = sharedTotal / pairs / per;
  state.counters["resolve_avg"] = resolveTotal / pairs / per;
  state.counters["sums_avg"] = sumsTotal / pairs / per;
  state.counters["own_avg"] = (total - sumsTotal - sharedTotal - resolveTotal) / pairs / per;
  for (size_t k = 0; k < filters.size(); ++k) pairSeconds[k] += sumsTotal / pairs;
  for (size_t k = 0; k < filters.size(); ++k) state.counters[labels[k]] = pairSeconds[k] / per;
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
    benchmark::RegisterBenchmark(("Sweep15/" + stem).c_str(), sweepPairs, path)->Unit(benchmark::kMillisecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
