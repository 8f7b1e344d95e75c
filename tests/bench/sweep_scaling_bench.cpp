// The sweep's scaling with threads (issue 20): one small vase study run by
// runSweep at 1, 2, ..., nproc threads (references cached beforehand, so
// they are not timed), each run into a fresh output folder.
//   SweepThreads/<n>  wall time of the whole runSweep; counters:
//     speedup      wall(1 thread) / wall(n), both measured in this run
//     setup, trace, splat, resolve, metrics, flip, finish   thread-seconds of work in the parallel phases
//     waiting      thread-seconds idle inside the parallel phases
//     io, refs     wall seconds of the serial steps (waiting for the writer, canonical order; scene + cached refs)
//     writer       seconds the writer thread spent on CSV/spectrum lines, overlapped with the next group
//     serial_frac  (io + refs + wall outside the phases) / wall, at this thread count
//     peak_MB      in-flight task state counted by the scheduler
// Size: ALIASLAB_SCALING_SIZE (default 64) square, samplers random, jittered,
// halton x spp 4, 16 x 8 filters x radii 0.5, 1, 1.5, 2 x 4 seeds (192 rows).
// Set ALIASLAB_SCALING_SIZE=128 and ALIASLAB_SCALING_SEEDS=8 for the vase configuration's film and seeds.
#include "aliaslab_paths.h"
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "core/parallel.h"
#include "study/config.h"
#include "study/sweep/sweep.h"

namespace aliaslab {
namespace {
namespace fs = std::filesystem;

int envInt(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : fallback;
}

const fs::path& scratch() {
  static const fs::path p = fs::temp_directory_path() / ("aliaslab_sweep_scaling_" + std::to_string(::getpid()));
  return p;
}

StudyConfig study(int threads, const std::string& out) {
  StudyConfig c;
  c.scenes = {ALIASLAB_SOURCE_DIR "/scenes/vase.txt"};
  c.width = c.height = envInt("ALIASLAB_SCALING_SIZE", 64);
  c.samplers = {"random", "jittered", "halton"};
  c.spp = {4, 16};
  c.filters = {"box", "tent", "gaussian", "mitchell", "lanczos", "catmullrom", "hann", "blackmanharris"};
  c.radii = {0.5, 1.0, 1.5, 2.0};
  c.seeds = envInt("ALIASLAB_SCALING_SEEDS", 4);
  c.refSpp = 64;
  c.threads = threads;
  c.images = false;
  c.progress = false;
  c.cache = (scratch() / "cache").string();
  c.out = (scratch() / out).string();
  return c;
}

double oneThreadWall = 0;

void sweepThreads(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  static bool warmed = false;
  if (!warmed) runSweep(study(threads, "warm")), warmed = true;  // references into the cache
  SweepSummary s;
  double wall = 0;
  int run = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    s = runSweep(study(threads, "t" + std::to_string(threads) + "_" + std::to_string(run++)));
    wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    state.SetIterationTime(wall);
  }
  if (threads == 1) oneThreadWall = wall;
  const SweepPhases& p = s.phases;
  const double inPhases = (p.setup + p.trace + p.splat + p.resolve + p.metrics + p.flip + p.finish + p.waiting) / threads;
  state.counters["speedup"] = oneThreadWall > 0 ? oneThreadWall / wall : 0;
  state.counters["trace"] = p.trace, state.counters["splat"] = p.splat;
  state.counters["resolve"] = p.resolve, state.counters["metrics"] = p.metrics;
  state.counters["flip"] = p.flip, state.counters["setup"] = p.setup;
  state.counters["finish"] = p.finish;
  state.counters["waiting"] = p.waiting, state.counters["io"] = p.io, state.counters["refs"] = p.references;
  state.counters["writer"] = p.writer;
  state.counters["serial_frac"] = std::max(0.0, wall - inPhases) / wall;
  state.counters["peak_MB"] = s.peakInFlightBytes / 1e6;
  state.counters["rows"] = double(s.rowsWritten);
}

}  // namespace
}  // namespace aliaslab

int main(int argc, char** argv) {
  using namespace aliaslab;
  benchmark::Initialize(&argc, argv);
  const int n = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int t = 1; t <= n; ++t)
    benchmark::RegisterBenchmark(("SweepThreads/" + std::to_string(t)).c_str(), sweepThreads)
        ->Arg(t)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::filesystem::remove_all(aliaslab::scratch());
  return 0;
}
