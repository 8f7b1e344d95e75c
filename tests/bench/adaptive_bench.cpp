// Trace time of the adaptive samplers against their base sampler for the same number of rays (issue: at most
// about 1.3x): traceSamples(jittered) and traceAdaptive(adaptive-METHOD:jittered) on fence, checker_horizon and
// scenes/controls/edge.txt at 128 x 128, 16 samples per pixel (262,144 rays either way), one thread, the
// default aggregate. items/s is rays per second. Retrace/NAME/SCENE traces the very rays of one sample set of
// NAME (its positions, computed before the timing) in pixel order, writing a buffer: the cost of those rays without
// the sampler's own work, since adaptive rays are not average rays (they crowd where the geometry is: on fence
// they are dearer than the base sampler's); Retrace/jittered/SCENE does the same for the base sampler's rays, so
// what each sampler adds beyond its rays is Trace - Retrace, for the base (its point generation and positions) as
// for the adaptive methods. RetraceRounds/NAME/SCENE traces the adaptive rays in the method's own order instead,
// recorded from the camera's calls while the method traced them (its rounds one after another, each tile by
// tile), so the cost of that order is told from the cost of the bookkeeping. For same-run ratios run with
// --benchmark_repetitions=N --benchmark_enable_random_interleaving=true (the machine is shared). The process keeps
// freed medium blocks in its heap (keepMediumBlocks(), core/huge_pages.h) as the sweep does (study/sweep/sweep.cpp):
// otherwise glibc returns the rounds' buffers (0.1 to 2 MB) to the kernel after every trace and the next one
// faults them in again, a cost (5 to 10 % of an adaptive trace in perf) that the study does not pay.
#include "aliaslab_paths.h"
#include <benchmark/benchmark.h>

#include <bit>
#include <map>
#include <unordered_map>

#include "accel/aggregate.h"
#include "core/huge_pages.h"
#include "render/adaptive/adaptive.h"
#include "render/render.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace aliaslab {
namespace {

constexpr int kSize = 128, kSpp = 16;

struct Loaded {
  Scene scene;
  std::unique_ptr<Aggregate> aggregate;
  std::unique_ptr<Tracer> tracer;
};

Loaded& loaded(const std::string& file) {
  static std::map<std::string, Loaded> cache;
  auto it = cache.find(file);
  if (it != cache.end()) return it->second;
  Loaded& l = cache[file];
  l.scene = parseScene(std::string(ALIASLAB_SOURCE_DIR) + "/scenes/" + file);
  l.aggregate = makeDefaultAggregate(*l.scene.root);
  l.tracer = std::make_unique<Tracer>(l.scene, *l.aggregate, TraceOptions{});
  return l;
}

const Tracer& tracerFor(const std::string& file) { return *loaded(file).tracer; }

/// A camera that passes every call on to `real` and logs the screen points of its rays in call order.
class RecordingCamera final : public Camera {
 public:
  RecordingCamera(const Camera& real, std::vector<Vec2>& log) : real_(real), log_(log) {}
  Ray generateRay(const Vec2& screen) const override { return log_.push_back(screen), real_.generateRay(screen); }
  RayDerivatives rayDerivatives(const Vec2& screen) const override { return real_.rayDerivatives(screen); }
  float tMin() const override { return real_.tMin(); }
  std::string describe() const override { return real_.describe(); }

 private:
  const Camera& real_;
  std::vector<Vec2>& log_;
};

/// One adaptive sample set and the order its samples were traced in (indices into its buffer; one thread).
struct Traced {
  SampleBuffer rays;
  std::vector<size_t> order;
};

Traced tracedInOrder(const std::string& file, const std::string& name) {
  Loaded& l = loaded(file);
  std::vector<Vec2> log;
  std::unique_ptr<Camera> real = std::move(l.scene.camera);
  l.scene.camera = std::make_unique<RecordingCamera>(*real, log);
  Traced t{traceAdaptive(*l.tracer, *makeAdaptiveSampler(name, kSpp, 1), kSize, kSize, 1), {}};
  l.scene.camera = std::move(real);
  // each logged screen point back to a sample of the buffer with that point (equal points: equal rays)
  const auto key = [](const Vec2& v) {
    return uint64_t{std::bit_cast<uint32_t>(v.x())} << 32 | std::bit_cast<uint32_t>(v.y());
  };
  std::unordered_map<uint64_t, std::vector<size_t>> at;
  const auto& samples = t.rays.samples();
  for (size_t k = 0; k < samples.size(); ++k)
    at[key(filmToScreen(samples[k].x, samples[k].y, kSize, kSize))].push_back(k);
  if (log.size() != samples.size()) throw std::runtime_error("adaptive_bench: rays traced != samples");
  for (const Vec2& v : log) {
    auto& left = at.at(key(v));
    t.order.push_back(left.back()), left.pop_back();
  }
  return t;
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
  const SampleBuffer rays = isAdaptiveSamplerName(name)
                                ? traceAdaptive(t, *makeAdaptiveSampler(name, kSpp, 1), kSize, kSize, 1)
                                : traceSamples(t, *makeSampler(name, kSpp, 1), kSize, kSize, 1);
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

// RetraceRounds: the same rays in the order the method traced them (tracedInOrder).
void retraceRounds(benchmark::State& state, std::string file, std::string name) {
  const Tracer& t = tracerFor(file);
  const Traced traced = tracedInOrder(file, name);
  const auto& in = traced.rays.samples();
  for (auto _ : state) {
    std::vector<FilmSample> out(in.size());
    for (size_t k : traced.order) {
      out[k] = in[k];
      out[k].L = t.radianceAt(in[k].x, in[k].y, kSize, kSize);
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
    benchmark::RegisterBenchmark(("Retrace/jittered/" + stem).c_str(), retrace, std::string(file), "jittered")
        ->Unit(benchmark::kMillisecond);
    for (const std::string& m : adaptiveMethodNames())
      benchmark::RegisterBenchmark(("Retrace/adaptive-" + m + ":jittered/" + stem).c_str(), retrace, std::string(file),
                                   "adaptive-" + m + ":jittered")
          ->Unit(benchmark::kMillisecond);
    for (const std::string& m : adaptiveMethodNames())
      benchmark::RegisterBenchmark(("RetraceRounds/adaptive-" + m + ":jittered/" + stem).c_str(), retraceRounds,
                                   std::string(file), "adaptive-" + m + ":jittered")
          ->Unit(benchmark::kMillisecond);
  }
  return 0;
}();

}  // namespace
}  // namespace aliaslab

BENCHMARK_MAIN();
