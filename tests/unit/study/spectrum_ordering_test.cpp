// The expected ordering of issue 22, end to end through the sweep: a
// blue-noise dithered sampler leaves less of its error at low screen
// frequencies than its base sampler (lowfreq_error lower by more than twice
// the combined standard error), at an mse within 10 % of the base's, on the
// horizon checkerboard and the zone plate at 1 and 4 spp (native sizes,
// box r = 0.5, 8 seeds).
//
// Measured (results/spectrum_ordering.md): it holds on the checkerboard's
// edges for the random base at 1 and 4 spp (asserted below). It does NOT hold
// on the zone plate, whose error beyond Nyquist is aliasing of a texture
// that changes phase from pixel to pixel (the dithered share is higher), nor
// for the jittered base at 4 spp, whose pixel-aligned strata the toroidal
// shift breaks (mse +34 %). Those cases are kept as the DISABLED_ test, the
// issue's hypothesis as written, so they can be run (--gtest_also_run_disabled_tests)
// and re-examined; they are reported, not hidden.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "aliaslab_paths.h"
#include "support/scratch_dir.h"
#include "study/records/csv.h"
#include "measure/spectrum.h"
#include "study/sweep/sweep.h"

using namespace aliaslab;
namespace fs = std::filesystem;

namespace {

struct Measured {
  double mse = 0, lowfreq = 0, lowfreqSe = 0, blurred = 0;
};

/// The study of both scenes, run once per test program: rows keyed "scene/sampler/spp".
const std::map<std::string, Measured>& study() {
  static const std::map<std::string, Measured> rows = [] {
    const fs::path dir = aliaslab::testing::scratchDir("aliaslab_spectrum_ordering_test");
    StudyConfig c;
    c.scenes = {std::string(ALIASLAB_SOURCE_DIR) + "/scenes/checker_horizon.txt",
                std::string(ALIASLAB_SOURCE_DIR) + "/scenes/zoneplate.txt"};
    c.samplers = {"random", "bluenoise-dither:random", "jittered", "bluenoise-dither:jittered"};
    c.spp = {1, 4};
    c.filters = {"box"};
    c.radii = {0.5};
    c.seeds = 8;
    c.refSpp = 256;
    c.maxSize = 128;  // the zone plate is made for 256 px; 128 keeps this test's cost
    c.targets = {"area"};  // lowfreq_error against the area = against the rows' own reference (box 0.5)
    c.threads = 2;
    c.images = false;
    c.progress = false;
    c.out = (dir / "study").string();
    c.cache = (dir / "cache").string();
    runSweep(c);
    for (const char* scene : {"checker_horizon", "zoneplate"})  // the per-scene spectra are written too
      EXPECT_TRUE(fs::is_regular_file(fs::path(c.out) / "spectra" / (std::string(scene) + ".csv"))) << scene;
    const std::vector<std::string>& cols = csvColumns();
    const auto col = [&](const char* name) {
      return static_cast<size_t>(std::find(cols.begin(), cols.end(), name) - cols.begin());
    };
    std::map<std::string, Measured> out;
    for (const std::string& line : readCsvLines(csvPath(c))) {
      const auto f = splitCsvLine(line);
      out[f[col("scene")] + "/" + f[col("sampler")] + "/" + f[col("spp")]] =
          Measured{std::stod(f[col("mse")]), std::stod(f[col("lowfreq_error")]),
                   std::stod(f[col("lowfreq_error_se")]), std::stod(f[col("blurred_mse")])};
    }
    return out;
  }();
  return rows;
}

/// The ordering for one (scene, base, spp).
void expectDitherOrdering(const std::string& scene, const std::string& base, int spp) {
  const auto& rows = study();
  ASSERT_EQ(rows.size(), 16u);
  const std::string at = scene + "/" + base + "/" + std::to_string(spp);
  const Measured b = rows.at(at);
  const Measured d = rows.at(scene + "/bluenoise-dither:" + base + "/" + std::to_string(spp));
  const double se = std::hypot(b.lowfreqSe, d.lowfreqSe);
  std::printf("%-16s %-9s spp %d  lowfreq_error %.4f -> %.4f (se %.4f)  mse %.4g -> %.4g  blurred_mse %.4g -> %.4g\n",
              scene.c_str(), base.c_str(), spp, b.lowfreq, d.lowfreq, se, b.mse, d.mse, b.blurred, d.blurred);
  EXPECT_LT(d.lowfreq, b.lowfreq - 2 * se) << at << ": dithered " << d.lowfreq << " base " << b.lowfreq;
  EXPECT_NEAR(d.mse / b.mse, 1.0, 0.10) << at << ": dithered mse " << d.mse << " base " << b.mse;
}

TEST(SpectrumOrdering, DitherMovesEdgeErrorToHighFrequenciesAtEqualMse) {
  for (int spp : {1, 4}) expectDitherOrdering("checker_horizon", "random", spp);
  // at 1 spp every base is one uniform point shifted: jittered's rows equal random's
  expectDitherOrdering("checker_horizon", "jittered", 1);
}

// The hypothesis where measurement refutes it (see the top of the file).
TEST(SpectrumOrdering, DISABLED_DitherOrderingOnTheZonePlateAndForJitteredAt4Spp) {
  for (int spp : {1, 4}) expectDitherOrdering("zoneplate", "random", spp);
  expectDitherOrdering("zoneplate", "jittered", 4);
  expectDitherOrdering("checker_horizon", "jittered", 4);
}

}  // namespace
