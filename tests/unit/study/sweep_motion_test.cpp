// The sweep with frames (study/sweep_motion.h) at 24 px: its motion columns are the motion study's numbers
// (study/motion_study.h, another assembly of the same frames, references rendered into another cache); its still
// columns are those of the same study without frames (frame 0 is the still image), whose CSV has no motion
// columns; no number depends on the thread count; two shards merge into the unsharded CSV; a CSV of one kind is
// not resumed by a study of another.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.h"
#include "study/config.h"
#include "study/csv.h"
#include "study/merge.h"
#include "study/motion_study.h"
#include "study/sweep.h"

namespace aliaslab {
namespace {
namespace fs = std::filesystem;

const fs::path& scratch() {
  static const fs::path d = [] {
    fs::path p = fs::temp_directory_path() / ("aliaslab_sweep_motion_" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
  }();
  return d;
}

std::string gratingScene() {
  const fs::path p = scratch() / "grating.txt";
  std::ofstream(p) << "# render: -size 24 24\n"
                      "OrthographicCamera { center 0 0 1 direction 0 0 -1 up 0 1 0 size 2 }\n"
                      "Background { color 1 0 0 }\n"
                      "Materials { numMaterials 3 PhongMaterial { diffuseColor 0 0 0 } "
                      "PhongMaterial { diffuseColor 1 1 1 }\n"
                      "Pattern { materialIndex 0 materialIndex 1 type grating frequency 4 angle 20 } }\n"
                      "Group { numObjects 1 MaterialIndex 2 Plane { normal 0 0 1 offset 0 } }\n";
  return p.string();
}

StudyConfig study(const std::string& name, int frames, int threads) {
  StudyConfig c;
  c.scenes = {gratingScene()};
  c.samplers = {"uniform", "jittered"};
  c.spp = {4};
  c.filters = {"box", "gaussian"};
  c.radii = {0.5, 1.5};
  c.targets = {"area", "gaussian:1.5"};
  c.seeds = 4, c.frames = frames, c.motionDx = 0.25, c.motionDy = 0.125;
  c.refSpp = 64;
  c.out = (scratch() / name).string();
  c.cache = (scratch() / (name + "-cache")).string();
  c.threads = threads;
  c.images = false;
  c.progress = false;
  return c;
}

// The CSV's header and rows, each row split into fields.
std::vector<std::vector<std::string>> readRows(const StudyConfig& c, std::string& header) {
  std::ifstream in(csvPath(c));
  std::getline(in, header);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) rows.push_back(splitCsvLine(line));
  return rows;
}

size_t col(const std::string& name) {
  const auto& still = csvColumns();
  for (size_t i = 0; i < still.size(); ++i)
    if (still[i] == name) return i;
  const auto& motion = csvMotionColumns();
  for (size_t i = 0; i < motion.size(); ++i)
    if (motion[i] == name) return still.size() + i;
  throw std::out_of_range(name);
}

bool variable(size_t i) {  // columns that may differ between runs
  for (size_t t : csvTimingColumns())
    if (t == i) return true;
  return i == col("threads");
}

std::vector<std::vector<std::string>> framesStudy(int threads, const std::string& name) {
  const StudyConfig c = study(name, 3, threads);
  runSweep(c);
  std::string header;
  auto rows = readRows(c, header);
  EXPECT_EQ(header, csvHeader(true));
  return rows;
}

TEST(SweepMotion, MotionColumnsAreTheMotionStudysNumbers) {
  const auto rows = framesStudy(1, "frames");
  ASSERT_EQ(rows.size(), 2u * 4 * 2);  // samplers x (filter, radius) x targets
  MotionStudyConfig m;
  const StudyConfig c = study("unused", 3, 1);
  m.scene = c.scenes[0];
  m.samplers = c.samplers, m.spp = c.spp;
  m.filters = {{"box", 0.5}, {"box", 1.5}, {"gaussian", 0.5}, {"gaussian", 1.5}};
  m.seeds = c.seeds, m.frames = c.frames, m.dx = c.motionDx, m.dy = c.motionDy;
  m.reference = referenceOptions(c);
  m.reference.progress = false;
  m.cache = (scratch() / "motion-cache").string();
  m.threads = 1, m.progress = false;
  std::ostringstream log;
  size_t matched = 0;
  for (const MotionRow& r : runMotionStudy(m, log))
    for (const auto& f : rows) {
      if (f[col("sampler")] != r.sampler || f[col("filter")] != r.filter || std::stod(f[col("radius")]) != r.radius ||
          f[col("target")] != "box:0.5")
        continue;
      ++matched;
      EXPECT_EQ(f[col("frames")], "3");
      EXPECT_EQ(f[col("motion_dx")], "0.25");
      EXPECT_EQ(f[col("motion_dy")], "0.125");
      const std::pair<const char*, double> pairs[] = {
          {"shimmer", r.motion.shimmer},          {"shimmer_se", r.motion.shimmerSe},
          {"flicker_same", r.motion.flickerSameSeed}, {"flicker_same_se", r.motion.flickerSameSeedSe},
          {"flicker_new", r.motion.flickerNewSeed},   {"flicker_new_se", r.motion.flickerNewSeedSe},
          {"shimmer_filter", r.motionFilter.shimmer}, {"shimmer_filter_se", r.motionFilter.shimmerSe},
          {"mse_target", r.mseTarget}};
      for (const auto& [name, want] : pairs)
        EXPECT_NEAR(std::stod(f[col(name)]), want, 1e-7 * std::abs(want) + 1e-15)
            << name << " " << r.sampler << " " << r.filter << " " << r.radius;
    }
  EXPECT_EQ(matched, 8u);
}

TEST(SweepMotion, StillColumnsAreTheStillStudysAndThreadsChangeNothing) {
  const auto one = framesStudy(1, "frames1"), two = framesStudy(2, "frames2");
  const StudyConfig still = study("still", 1, 1);
  runSweep(still);
  std::string header;
  const auto stillRows = readRows(still, header);
  EXPECT_EQ(header, csvHeader());  // F = 1: no motion columns
  ASSERT_EQ(stillRows.size(), one.size());
  ASSERT_EQ(two.size(), one.size());
  for (size_t r = 0; r < one.size(); ++r) {
    ASSERT_EQ(one[r].size(), csvColumns().size() + csvMotionColumns().size());
    ASSERT_EQ(stillRows[r].size(), csvColumns().size());
    for (size_t i = 0; i < one[r].size(); ++i) {
      if (variable(i)) continue;
      EXPECT_EQ(two[r][i], one[r][i]) << "row " << r << " column " << i;
      if (i < csvColumns().size()) {
        EXPECT_EQ(stillRows[r][i], one[r][i]) << "row " << r << " column " << i;
      }
    }
  }
  // A CSV holds one kind of study and one motion.
  StudyConfig again = study("frames1", 2, 1);
  EXPECT_THROW(runSweep(again), OptionError);
  again.frames = 3, again.motionDx = 0.5;
  EXPECT_THROW(runSweep(again), OptionError);
  again = study("frames1", 1, 1);
  EXPECT_THROW(runSweep(again), FileError);
  again = study("still", 3, 1);
  EXPECT_THROW(runSweep(again), FileError);
}

TEST(SweepMotion, ShardsMergeIntoTheWholeStudy) {
  const auto whole = framesStudy(1, "whole");
  std::vector<std::string> shards;
  for (int i = 0; i < 2; ++i) {
    StudyConfig c = study("sharded", 3, 1);
    c.shardIndex = i, c.shardCount = 2;
    runSweep(c);
    shards.push_back(csvPath(c));
  }
  StudyConfig merged = study("sharded", 3, 1);
  merged.csv = (scratch() / "sharded" / "merged.csv").string();
  mergeStudy(merged.csv, shards, "test");
  std::string header;
  const auto rows = readRows(merged, header);
  EXPECT_EQ(header, csvHeader(true));
  ASSERT_EQ(rows.size(), whole.size());
  for (size_t r = 0; r < rows.size(); ++r)
    for (size_t i = 0; i < rows[r].size(); ++i) {
      if (!variable(i)) {
        EXPECT_EQ(rows[r][i], whole[r][i]) << "row " << r << " column " << i;
      }
    }
}

TEST(SweepMotion, RefusesBadFramesAndMotion) {
  StudyConfig c = study("bad", 0, 1);
  EXPECT_THROW(runSweep(c), OptionError);
  c.frames = 2, c.motionDx = NAN;
  EXPECT_THROW(runSweep(c), OptionError);
  EXPECT_THROW(parseMotion("0.25"), OptionError);
  EXPECT_THROW(parseMotion("0.25,x"), OptionError);
  EXPECT_THROW(parseMotion("1,2,3"), OptionError);
  EXPECT_THROW(parseMotion("inf,0"), OptionError);
  EXPECT_EQ(parseMotion("0.25,-1"), (std::pair<double, double>{0.25, -1}));
  EXPECT_FALSE(fs::exists(scratch() / "bad" / "study.csv"));
}

}  // namespace
}  // namespace aliaslab
