// The sweep with frames (study/sweep/sweep_motion.h), the one motion driver, against closed forms (docs/science.md
// "Motion"): a point-sampled grating above Nyquist shimmers 2 a^2 sin^2(pi k v) with a = 1/2, a Gaussian or
// box resolve of it a^2 times the filter's response at the folded frequency squared (summed over the filter's
// weights at the integer offsets of the other samples, an independent computation); a grating below Nyquist
// scores zero within its standard error for the grid, jittered and random samplers at every filter. Its still
// columns are those of the same study without frames (frame 0 is the still image), whose CSV has no motion
// columns; no number depends on the thread count; two shards merge into the unsharded CSV; a CSV of one kind is
// not resumed by a study of another.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "core/error.h"
#include "study/config.h"
#include "study/records/csv.h"
#include "study/records/merge.h"
#include "filter/filter.h"
#include "study/sweep/motion_frame.h"
#include "study/sweep/sweep.h"
#include "support/study_rows.h"

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

// A grating along x of nu cycles per pixel at n pixels (2 world units across).
std::string gratingScene(const std::string& name, int n = 24, double nu = 4.0 / 12, double angle = 20) {
  const fs::path p = scratch() / (name + ".txt");
  std::ofstream(p) << "# render: -size " << n << " " << n << "\n"
                      "OrthographicCamera { center 0 0 1 direction 0 0 -1 up 0 1 0 size 2 }\n"
                      "Background { color 1 0 0 }\n"
                      "Materials { numMaterials 3 PhongMaterial { diffuseColor 0 0 0 } "
                      "PhongMaterial { diffuseColor 1 1 1 }\n"
                      "Pattern { materialIndex 0 materialIndex 1 type grating frequency " << nu * n / 2
                   << " angle " << angle << " } }\n"
                      "Group { numObjects 1 MaterialIndex 2 Plane { normal 0 0 1 offset 0 } }\n";
  return p.string();
}

StudyConfig study(const std::string& name, int frames, int threads) {
  StudyConfig c;
  c.scenes = {gratingScene("grating")};
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

// The response at frequency nu along x of a filter's weights at the integer offsets of the 1-spp grid (the
// weighted average of point samples at the pixel centres).
double gridResponse(const std::string& filter, double radius, double nu) {
  const auto f = makeFilter(filter, static_cast<float>(radius));
  double sum = 0, weights = 0;
  const int r = static_cast<int>(std::ceil(radius));
  for (int j = -r; j <= r; ++j)
    for (int i = -r; i <= r; ++i) {
      const double w = f->eval(static_cast<float>(i), static_cast<float>(j));
      sum += w * std::cos(2 * M_PI * nu * i), weights += w;
    }
  return sum / weights;
}

TEST(SweepMotion, GratingAboveNyquistShimmersAsTheClosedForm) {
  StudyConfig c = study("above", 3, 2);
  const double nu = 0.7, v = 0.25;  // folded to -0.3: 15 periods in the 50-pixel interior
  c.scenes = {gratingScene("above", 68, nu, 0)};
  c.samplers = {"uniform"}, c.spp = {1}, c.filters = {"box", "gaussian"}, c.radii = {0.5, 1.5};
  c.targets = {"area"}, c.motionDx = v, c.motionDy = 0;
  runSweep(c);
  std::string header;
  const auto rows = readRows(c, header);
  ASSERT_EQ(rows.size(), 4u);
  const double pointShimmer = 2 * 0.25 * std::pow(std::sin(M_PI * v), 2);  // k = 1, a = 1/2
  for (const auto& f : rows) {
    const double H = gridResponse(f[col("filter")], std::stod(f[col("radius")]), nu - 1);
    const double expected = pointShimmer * H * H;
    EXPECT_NEAR(std::stod(f[col("shimmer")]), expected, 0.02 * expected) << f[col("filter")] << " " << f[col("radius")];
    if (f[col("radius")] == "1.5") {
      EXPECT_LT(H, 0.8);  // the wider filters do lower it (box 0.13, gaussian 0.72)
    }
    EXPECT_NEAR(std::stod(f[col("flicker_same")]), expected, 0.02 * expected);  // deterministic: no noise
  }
}

TEST(SweepMotion, GratingBelowNyquistDoesNotShimmer) {
  StudyConfig c = study("below", 3, 2);
  c.scenes = {gratingScene("below", 40, 0.375, 0)};
  c.samplers = {"uniform", "jittered", "random"}, c.spp = {4}, c.filters = {"box", "gaussian", "tent"};
  c.radii = {0.5, 1.5}, c.targets = {"area"}, c.seeds = 8;
  runSweep(c);
  std::string header;
  const auto rows = readRows(c, header);
  ASSERT_EQ(rows.size(), 3u * 6);
  for (const auto& f : rows) {
    const double s = std::stod(f[col("shimmer")]), se = std::stod(f[col("shimmer_se")]);
    // 3 se: 18 rows tested at once; 1e-5: the border's interpolation error (measure/registration.h)
    EXPECT_LT(std::abs(s), 3 * se + 1e-5) << f[col("sampler")] << " " << f[col("filter")] << " " << f[col("radius")];
    // the noise is seen: new seeds flicker, twice the noise (a shared-nothing pair of frames)
    if (f[col("sampler")] == "uniform") continue;
    const double noise = std::stod(f[col("noise")]), flicker = std::stod(f[col("flicker_new")]);
    EXPECT_NEAR(flicker, 2 * noise, 0.15 * 2 * noise) << f[col("sampler")] << " " << f[col("filter")];
  }
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
  const std::vector<std::string> shards = aliaslab::testing::runShards(study("sharded", 3, 1), 2);
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

// A study with frames resumes row by row like a still one: a rerun skips every row, and after a kill (the CSV
// cut back to its header and first rows) the rerun measures only the rows lost and ends with the same CSV.
TEST(SweepMotion, ResumesRowByRow) {
  const StudyConfig c = study("resume", 3, 1);
  runSweep(c);
  std::ifstream in(csvPath(c));
  const std::string whole((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const SweepSummary again = runSweep(c);
  EXPECT_EQ(again.rowsWritten, 0u);
  EXPECT_EQ(again.rowsSkipped, 16u);
  std::vector<std::string> lines;
  std::istringstream text(whole);
  for (std::string l; std::getline(text, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 17u);
  {
    std::ofstream cut(csvPath(c), std::ios::trunc);
    for (size_t i = 0; i < 9; ++i) cut << lines[i] << "\n";  // the header and 8 rows: one configuration's kept
  }
  const SweepSummary resumed = runSweep(c);
  EXPECT_EQ(resumed.rowsSkipped, 8u);
  EXPECT_EQ(resumed.rowsWritten, 8u);
  std::string header;
  const auto rows = readRows(c, header);
  std::vector<std::vector<std::string>> want;
  for (size_t i = 1; i < lines.size(); ++i) want.push_back(splitCsvLine(lines[i]));
  ASSERT_EQ(rows.size(), want.size());
  for (size_t r = 0; r < rows.size(); ++r)
    for (size_t i = 0; i < rows[r].size(); ++i)
      if (!variable(i)) EXPECT_EQ(rows[r][i], want[r][i]) << "row " << r << " column " << i;
}

// Frame 0 is the still pass's: a study with F frames traces F times the still study's primary rays, not F + 1.
TEST(SweepMotion, FrameZeroIsTracedOnce) {
  const SweepSummary still = runSweep(study("rays-still", 1, 1));
  const SweepSummary frames = runSweep(study("rays-frames", 3, 1));
  ASSERT_GT(still.primaryRays, 0u);
  EXPECT_EQ(frames.primaryRays, 3 * still.primaryRays);
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
