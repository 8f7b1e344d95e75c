// A sweep refused after its CSV was opened leaves no header-only study.csv (which would look like a study with
// no rows yet, and be resumed or merged as one), and a refusal never removes a CSV that was there before the run.
// The refusal: a scene whose light overflows float range, so its reference holds NaN samples; that is found
// while rendering the references, after the CSV was created.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "study/records/csv.h"
#include "support/run_process.h"
#include "support/scratch_dir.h"

namespace fs = std::filesystem;

namespace {
const std::string kBin = std::string(ALIASLAB_BIN_DIR) + "/sweep";
const fs::path& dir() { return aliaslab::testing::scratchDir("aliaslab_sweep_leftovers_test"); }

std::string slurp(const fs::path& p) { return aliaslab::testing::readText(p.string()); }

int sweep(const std::string& args, std::string* err) {
  const fs::path e = dir() / "run.err";
  const int status = std::system((kBin + " " + args + " > /dev/null 2> " + e.string()).c_str());
  *err = slurp(e);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string study(const std::string& out) {
  return "--scenes " + std::string(ALIASLAB_SOURCE_DIR) + "/tests/badinput/scenes/light_colour_overflow.txt" +
         " --samplers random --spp 4 --filters tent --radii 1 --seeds 2 --ref-spp 64 --target area --quiet" +
         " --no-images --size 8 8 --out " + (dir() / out).string() + " --cache " + (dir() / "cache").string();
}

TEST(SweepLeftovers, ARefusalAfterTheCsvWasOpenedLeavesNoHeaderOnlyCsv) {
  std::string err;
  EXPECT_EQ(sweep(study("fresh"), &err), 2) << err;
  EXPECT_NE(err.find("light_colour_overflow.txt"), std::string::npos) << err;
  EXPECT_NE(err.find("NaN or infinite"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir() / "fresh" / "study.csv")) << "left: " << slurp(dir() / "fresh" / "study.csv");
  EXPECT_FALSE(fs::exists(dir() / "fresh" / "study.csv.lock"));
}

TEST(SweepLeftovers, ARefusalLeavesAnExistingCsvAsItWas) {
  // A CSV that was there before the run (here header only) is not this run's to remove: it stays as it was.
  fs::create_directories(dir() / "held");
  const fs::path csv = dir() / "held" / "study.csv";
  const std::string text = aliaslab::csvHeader() + "\n";
  std::ofstream(csv) << text;  // header only, but not created by this run: left as it was
  std::string err;
  EXPECT_EQ(sweep(study("held"), &err), 2) << err;
  EXPECT_EQ(slurp(csv), text);
}

}  // namespace
