// The motion study (study/motion_study.h) end to end at 32 px: point sampling of the grating against the
// rendered pixel-area references matches the closed form; on the grating and the zone plate the shimmer against
// each filter's own references falls as the Gaussian widens while the blur rises; results do not depend on
// the thread count; bad configurations are refused before any work.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/math.h"
#include "study/motion_study.h"

namespace aliaslab {
namespace {
namespace fs = std::filesystem;

std::string writeScene(const std::string& name, const std::string& pattern) {
  const fs::path p = fs::temp_directory_path() / ("aliaslab_motion_" + name + ".txt");
  std::ofstream(p) << "# render: -size 32 32\n"
                      "OrthographicCamera { center 0 0 1 direction 0 0 -1 up 0 1 0 size 2 }\n"
                      "Background { color 1 0 0 }\n"
                      "Materials { numMaterials 3 PhongMaterial { diffuseColor 0 0 0 } "
                      "PhongMaterial { diffuseColor 1 1 1 }\n"
                      "Pattern { materialIndex 0 materialIndex 1 " << pattern << " } }\n"
                      "Group { numObjects 1 MaterialIndex 2 Plane { normal 0 0 1 offset 0 } }\n";
  return p.string();
}

MotionStudyConfig pointSampling(const std::string& scene) {
  MotionStudyConfig c;
  c.scene = scene;
  c.samplers = {"uniform"};  // one sample at each pixel centre
  c.spp = {1};
  c.filters = {{"box", 0.5}, {"gaussian", 1}, {"gaussian", 1.5}, {"gaussian", 2}};
  c.seeds = 2, c.frames = 3, c.dx = 0.25, c.dy = 0;
  c.reference.spp = 256;
  c.threads = 1;
  c.progress = false;
  return c;
}

TEST(MotionStudy, GratingShimmerMatchesClosedFormAndFallsWithWidth) {
  const MotionStudyConfig c = pointSampling(writeScene("grating", "type grating frequency 6"));  // 0.375 c/px
  std::ostringstream log;
  const std::vector<MotionRow> rows = runMotionStudy(c, log);
  ASSERT_EQ(rows.size(), 4u);
  const double nu = 0.375, A = std::sin(kPi * nu) / (kPi * nu), s = std::sin(kPi * nu * 0.25);
  const double expected = 0.5 * (1 - A) * (1 - A) * s * s;  // docs/science.md, "Motion"
  EXPECT_NEAR(rows[0].motion.shimmer, expected, 0.02 * expected);
  for (size_t j = 2; j < rows.size(); ++j) {
    EXPECT_LT(rows[j].motionFilter.shimmer, rows[j - 1].motionFilter.shimmer) << "radius " << rows[j].radius;
    EXPECT_GT(rows[j].blur, rows[j - 1].blur) << "radius " << rows[j].radius;
  }
}

TEST(MotionStudy, ZonePlateShimmerFallsWithWidthAndThreadsChangeNothing) {
  MotionStudyConfig c = pointSampling(writeScene("zoneplate", "type zoneplate frequency 32"));
  std::ostringstream log;
  const std::vector<MotionRow> rows = runMotionStudy(c, log);
  for (size_t j = 2; j < rows.size(); ++j) {
    EXPECT_LT(rows[j].motionFilter.shimmer, rows[j - 1].motionFilter.shimmer) << "radius " << rows[j].radius;
    EXPECT_GT(rows[j].blur, rows[j - 1].blur) << "radius " << rows[j].radius;
  }
  c.samplers = {"jittered"}, c.spp = {4}, c.filters = {{"gaussian", 1.5}};
  const std::string one = motionCsv(runMotionStudy(c, log));
  c.threads = 2, c.reference.threads = 2;
  EXPECT_EQ(motionCsv(runMotionStudy(c, log)), one);
}

TEST(MotionStudy, RefusesBadConfigurations) {
  MotionStudyConfig c = pointSampling(writeScene("grating", "type grating frequency 6"));
  c.frames = 1;
  EXPECT_THROW(validateMotionStudy(c), OptionError);
  c.frames = 3, c.seeds = 1;
  EXPECT_THROW(validateMotionStudy(c), OptionError);
  c.seeds = 2, c.dx = NAN;
  EXPECT_THROW(validateMotionStudy(c), OptionError);
  EXPECT_THROW(parseFilterSpec("gaussian"), OptionError);
  EXPECT_THROW(parseFilterSpec("gaussian:-1"), OptionError);
  EXPECT_THROW(parseFilterSpec("nosuch:1"), OptionError);
  EXPECT_EQ(parseFilterSpec("gaussian:1.5"), (FilterSpec{"gaussian", 1.5}));
}

}  // namespace
}  // namespace aliaslab
