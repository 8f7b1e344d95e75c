// The sweep's scheduler (lib/study/sweep/sweep.cpp): sample sets (seeds) and the
// (seed, row) reconstructions run as tasks, each writing its own slot, folded
// in seed order. So the CSV (timing and threads columns aside), the spectra
// and every image are identical for 1, 2, 3, 5 threads and for more threads
// than tasks; a run whose tasks are handed out in a shuffled order gives the
// same bits; and the in-flight task state the scheduler counts stays within
// sweepMemoryBound(). Tiny sizes (odd 19x13 film, 4 seeds, 64-spp references).
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "support/scratch_dir.h"
#include "support/sweep_program.h"
#include "core/parallel.h"
#include "core/stopwatch.h"
#include "study/config.h"
#include "study/validate.h"
#include "study/records/csv.h"
#include "study/reference/reference.h"
#include "study/study_scene.h"
#include "study/sweep/sweep.h"

using namespace aliaslab;
namespace fs = std::filesystem;

namespace {
const std::string kScene = aliaslab::testing::kZonePlate;

const fs::path& workDir() { return aliaslab::testing::scratchDir("aliaslab_sweep_parallel_test"); }

// Every mode: weighted (shared Accumulator), classic, importance (own traces), supersample (uniform, spp 4);
// an adaptive sampler (its own trace, mean_spp/max_spp folded over seeds) and pre-filtered groups (a second
// tracer), so every path of the scheduler is covered.
StudyConfig tinyStudy(int threads, const std::string& name) {
  StudyConfig c;
  c.scenes = {kScene};
  c.width = 19, c.height = 13;
  c.samplers = {"uniform", "jittered", "adaptive-contrast:jittered"};
  c.prefilter = {"none", "footprint"};
  c.spp = {4};
  c.seeds = 4;
  c.refSpp = 64;
  c.threads = threads;
  c.images = true;
  c.progress = false;
  c.cache = (workDir() / "cache").string();
  c.filters = {"box", "gaussian", "mitchell"};
  c.radii = {0.5, 1.5};
  c.reconstruction = {"weighted", "classic", "importance", "supersample"};
  c.out = (workDir() / name).string();
  return c;
}

std::string readBytes(const fs::path& p) { return aliaslab::testing::fileBytes(p); }

// Everything a run wrote, file by file (relative path -> content), with the CSV's timing and threads
// columns blanked.
std::map<std::string, std::string> outputs(const StudyConfig& c) {
  std::map<std::string, std::string> files;
  const size_t threads = std::find(csvColumns().begin(), csvColumns().end(), "threads") - csvColumns().begin();
  for (const auto& e : fs::recursive_directory_iterator(c.out)) {
    if (!e.is_regular_file()) continue;
    const std::string rel = fs::relative(e.path(), c.out).string();
    if (rel == "study.csv") {
      std::string rows;
      for (const std::string& line : readCsvLines(e.path().string())) {
        auto f = splitCsvLine(line);
        for (size_t col : csvTimingColumns()) f[col] = "";
        f[threads] = "";
        for (const auto& x : f) rows += x + ",";
        rows += "\n";
      }
      files[rel] = rows;
    } else if (rel.rfind("references/", 0) == 0) {  // the manifest's "seconds" is a timing
      std::istringstream in(readBytes(e.path()));
      std::string kept;
      for (std::string line; std::getline(in, line);)
        if (line.find("\"seconds\"") == std::string::npos) kept += line + "\n";
      files[rel] = kept;
    } else {
      files[rel] = readBytes(e.path());
    }
  }
  return files;
}

void expectSameOutputs(const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b,
                       const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (const auto& [name, content] : a) {
    ASSERT_TRUE(b.count(name)) << what << ": " << name << " missing";
    EXPECT_TRUE(b.at(name) == content) << what << ": " << name << " differs";
  }
}

const std::map<std::string, std::string>& oneThread() {
  static const auto files = [] {
    const StudyConfig c = tinyStudy(1, "t1");
    const SweepSummary s = runSweep(c);
    EXPECT_GT(s.rowsWritten, 30u);
    return outputs(c);
  }();
  return files;
}
}  // namespace

TEST(SweepParallel, OneTwoThreeFiveAndMoreThreadsThanTasksGiveTheSameCsvSpectraAndImages) {
  const auto& base = oneThread();
  ASSERT_TRUE(base.count("study.csv"));
  ASSERT_GT(base.size(), 20u);  // CSV, spectra, manifest, reference and configuration images, contact sheets
  for (int threads : {2, 3, 5, 64}) {  // 64 > seeds and > rows of a group
    const StudyConfig c = tinyStudy(threads, "t" + std::to_string(threads));
    runSweep(c);
    expectSameOutputs(base, outputs(c), std::to_string(threads) + " threads");
  }
}

TEST(SweepParallel, TasksHandedOutInAShuffledOrderGiveTheSameBits) {
  const auto& base = oneThread();
  for (int threads : {1, 3}) {
    for (uint64_t seed : {7u, 1234567u}) {
      const StudyConfig c = tinyStudy(threads, "shuffled" + std::to_string(threads) + "_" + std::to_string(seed));
      setParallelShuffle(seed);
      runSweep(c);
      setParallelShuffle(0);
      expectSameOutputs(base, outputs(c), "shuffled " + std::to_string(seed) + ", " + std::to_string(threads));
    }
  }
}

TEST(SweepParallel, ShuffleHookReallyReordersItems) {  // so the test above can fail
  std::vector<int> order;
  setParallelShuffle(7);
  parallelFor(20, 1, [&](int i) { order.push_back(i); });
  setParallelShuffle(0);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_NE(order, sorted);
  for (int i = 0; i < 20; ++i) EXPECT_EQ(sorted[i], i);
}

// The one timing helper of the sweep's phases: every item runs once; work counts each task x its inner threads,
// idle = wall x threads - work, never negative.
TEST(SweepParallel, TimedParallelForRunsEveryItemAndAccountsWorkAndIdle) {
  for (int inner : {1, 3}) {
    std::vector<int> ran(7, 0);
    const Stopwatch wall;
    const PhaseTime t = timedParallelFor(7, 2, inner, [&](int i) { ++ran[i]; });
    for (int r : ran) EXPECT_EQ(r, 1);
    EXPECT_GE(t.work, 0.0);
    EXPECT_GE(t.idle, 0.0);
    EXPECT_LE(t.work + t.idle, std::max(wall.seconds() * 2, t.work) + 1e-9);
  }
  const PhaseTime none = timedParallelFor(0, 2, 1, [](int) { FAIL() << "no items"; });
  EXPECT_EQ(none.work, 0.0);
}

TEST(SweepParallel, InFlightStateStaysWithinTheDocumentedBound) {
  for (int threads : {1, 2, 3, 16}) {
    StudyConfig c = tinyStudy(threads, "mem" + std::to_string(threads));
    c.images = false;
    const SweepSummary s = runSweep(c);
    // per group: 3 filters x 2 radii x {weighted, classic, importance} + 1 supersample (uniform only)
    const size_t bound = sweepMemoryBound(threads, c.width, c.height, 4, 3 * 2 * 3 + 1, 3 * 2, c.seeds);
    EXPECT_GT(s.peakInFlightBytes, 0u);
    EXPECT_LE(s.peakInFlightBytes, bound) << threads << " threads";
    // and the bound is not loose by more than the importance buffers: at least one seed's set was in flight
    EXPECT_GE(s.peakInFlightBytes, size_t(c.width) * c.height * 4 * 24) << threads << " threads";
  }
}

TEST(ReferenceParallel, OneTwoThreeFiveAndMoreThreadsThanBatchesGiveTheSameReferences) {
  const auto scene = loadStudyScene(kScene, 19, 13);
  const std::vector<FilterSpec> specs{{"box", 0.5}, {"gaussian", 1.5}, {"mitchell", 2.0}};
  auto render = [&](int threads) {
    ReferenceOptions o;
    o.spp = 96, o.batchSpp = 16, o.threads = threads, o.progress = false;  // 6 batches: 3 pairs
    FilterCache filters;
    return renderReferences(*scene, filters.get(specs), o);
  };
  const ReferenceSet base = render(1);
  for (int threads : {2, 3, 5, 64}) {
    const ReferenceSet r = render(threads);
    ASSERT_EQ(r.images.size(), base.images.size());
    for (size_t i = 0; i < r.images.size(); ++i) {
      const Image& a = base.images[i].image;
      const Image& b = r.images[i].image;
      bool same = a.width() == b.width() && a.height() == b.height();
      for (int y = 0; same && y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) same = same && (a.get(x, y) == b.get(x, y)).all();
      EXPECT_TRUE(same) << threads << " threads, reference " << i;
      EXPECT_EQ(r.images[i].error, base.images[i].error) << threads << " threads, reference " << i;
    }
  }
}

// pointsets runs one task per (sampler, count), each into its own slot and files: its tables and images are
// the same bytes for 1 and 3 threads (3 jobs x 2 counts: odd, so the partition is uneven).
TEST(PointsetsParallel, OneAndThreeThreadsWriteTheSameFiles) {
  std::map<std::string, std::string> runs[2];
  int i = 0;
  for (int threads : {1, 3}) {
    const fs::path out = workDir() / ("pointsets" + std::to_string(threads));
    const std::string cmd = std::string(ALIASLAB_BIN_DIR) + "/pointsets --samplers random,jittered,sobol --counts 16,64 " +
                            "--sets 6 --no-chart --threads " + std::to_string(threads) + " --out " + out.string() +
                            " > " + (workDir() / "pointsets.log").string() + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    for (const auto& e : fs::directory_iterator(out)) runs[i][e.path().filename().string()] = readBytes(e.path());
    ++i;
  }
  ASSERT_GE(runs[0].size(), 13u);  // 6 point plots, 6 periodograms, the tables
  EXPECT_EQ(runs[0], runs[1]);
}
