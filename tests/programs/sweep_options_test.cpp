// The sweep's options behave the same in all three forms: --opt value, --opt=value and `opt = value` in a
// --config file (one parser, CLI11, reads them all; the preset is found by that parser too, then applied before
// the options bound over it). For every option with a value: a bad value in each form gives the same exit code
// and the same message naming the option (a form that dropped the value would run instead). For --preset: the
// three forms give the same --help, whose defaults are the preset's.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "support/run_process.h"
#include "support/scratch_dir.h"

namespace fs = std::filesystem;

namespace {
const std::string kBin = std::string(ALIASLAB_BIN_DIR) + "/sweep";
const fs::path& dir() { return aliaslab::testing::scratchDir("aliaslab_sweep_options_test"); }

std::string slurp(const fs::path& p) { return aliaslab::testing::readText(p.string()); }

struct Result {
  int code;
  std::string out, err;
};
Result sweep(const std::string& args) {
  const fs::path o = dir() / "run.out", e = dir() / "run.err";
  const int status = std::system((kBin + " " + args + " > " + o.string() + " 2> " + e.string()).c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(o), slurp(e)};
}

// A --config file holding `key = value`.
std::string config(const std::string& name, const std::string& key, const std::string& value) {
  const fs::path p = dir() / (name + ".toml");
  std::ofstream(p) << key << " = " << value << "\n";
  return p.string();
}

// The option under test, a value the sweep refuses, how TOML writes it, a part of the expected message, and
// options it needs beside it.
struct BadValue {
  std::string option, value, toml, expect, extra;
};

const std::vector<BadValue> kBad = {
    {"scenes", "/nonexistent/x.txt", "\"/nonexistent/x.txt\"", "x.txt"},
    {"samplers", "nosuch", "\"nosuch\"", "--samplers"},
    {"spp", "0", "\"0\"", "--spp"},
    {"filters", "nosuch", "\"nosuch\"", "--filters"},
    {"radii", "-1", "\"-1\"", "--radii"},
    {"reconstruction", "nosuch", "\"nosuch\"", "--reconstruction"},
    {"prefilter", "nosuch", "\"nosuch\"", "--prefilter"},
    {"seeds", "1", "1", "--seeds"},
    {"ref-spp", "0", "0", "--ref-spp"},
    {"ref-sampler", "nosuch", "\"nosuch\"", "--ref-sampler"},
    {"max-size", "-1", "-1", "--max-size"},
    {"long-side", "-1", "-1", "--long-side"},
    {"target", "nosuch:1", "\"nosuch:1\"", "--target"},
    {"frames", "0", "0", "--frames"},
    {"motion", "x", "\"x\"", "--motion"},
    {"align-offsets", "1", "1", "--align-offsets"},
    {"threads", "-1", "-1", "--threads"},
    {"shard", "3/2", "\"3/2\"", "--shard"},
    {"preset", "nosuch", "\"nosuch\"", "--preset"},
    {"out", "/dev/null/o", "\"/dev/null/o\"", "--out"},
    {"cache", "/dev/null/c", "\"/dev/null/c\"", "--cache"},
    {"csv", "/dev/null/x.csv", "\"/dev/null/x.csv\"", "--csv"},
    {"size", "0 0", "[0, 0]", "--size"},
    {"align-ref-spp", "0", "0", "--align-ref-spp", " --align-offsets 8"},
};

// A tiny valid study but for the option under test (left out here, given in one of the three forms).
std::string baseArgs(const std::string& without) {
  const std::map<std::string, std::string> base = {
      {"scenes", std::string(ALIASLAB_SOURCE_DIR) + "/scenes/sphere_triangle.txt"},
      {"samplers", "random"}, {"spp", "4"}, {"filters", "tent"}, {"radii", "1"}, {"seeds", "2"},
      {"ref-spp", "64"}, {"target", "area"}, {"out", (dir() / "o").string()}, {"cache", (dir() / "c").string()},
      {"max-size", "8"}};
  std::string args = "--quiet --no-images";
  for (const auto& [k, v] : base)
    if (k != without) args += " --" + k + " " + v;
  return args;
}

TEST(SweepOptionForms, EveryOptionIsReadAlikeInItsThreeForms) {
  for (const BadValue& b : kBad) {
    SCOPED_TRACE(b.option);
    const std::string base = baseArgs(b.option) + b.extra;
    const Result spaced = sweep(base + " --" + b.option + " " + b.value);
    const Result equals = sweep(base + " --" + b.option + "=" + b.value);
    const Result file = sweep(base + " --config " + config(b.option, b.option, b.toml));
    EXPECT_NE(spaced.code, 0) << spaced.err;
    EXPECT_NE(spaced.err.find(b.expect), std::string::npos) << spaced.err;
    EXPECT_EQ(equals.code, spaced.code) << equals.err;
    EXPECT_EQ(equals.err, spaced.err);
    EXPECT_EQ(file.code, spaced.code) << file.err;
    EXPECT_EQ(file.err, spaced.err);
  }
  EXPECT_FALSE(fs::exists(dir() / "o" / "study.csv"));
}

TEST(SweepOptionForms, APresetIsAppliedInEachFormAndExplicitOptionsOverrideIt) {
  const Result plain = sweep("--help");
  for (const std::string preset : {"default", "presented"}) {
    SCOPED_TRACE(preset);
    const Result spaced = sweep("--preset " + preset + " --help");
    const Result equals = sweep("--preset=" + preset + " --help");
    const Result file = sweep("--config " + config("preset_" + preset, "preset", "\"" + preset + "\"") + " --help");
    ASSERT_EQ(spaced.code, 0) << spaced.err;
    EXPECT_NE(spaced.out, plain.out) << "the preset's defaults are not shown";
    EXPECT_EQ(equals.out, spaced.out);
    EXPECT_EQ(file.out, spaced.out);
  }
  // The defaults shown are the preset's: presented renders the larger side at 256 px, default at most 48.
  EXPECT_NE(sweep("--preset=presented --help").out.find("results/presented"), std::string::npos);
  EXPECT_NE(sweep("--preset=default --help").out.find("(default: 48)"), std::string::npos);
  // Explicit options override the preset in every form (the preset's 8 seeds replaced by a refused 1).
  const std::string args = baseArgs("seeds");
  const Result over = sweep("--preset=default " + args + " --seeds=1");
  EXPECT_EQ(over.code, 2);
  EXPECT_NE(over.err.find("--seeds: needs K >= 2"), std::string::npos) << over.err;
  EXPECT_EQ(sweep("--config " + config("preset_seeds", "preset", "\"default\"") + " " + args + " --seeds 1").err,
            over.err);
}

TEST(SweepOptionForms, HelpDescribesEachPresetTruthfully) {
  const std::string help = sweep("--help").out;
  EXPECT_EQ(help.find("study_full"), std::string::npos);
  EXPECT_EQ(help.find("'full'"), std::string::npos);
  for (const char* part : {"'default': every bundled scene scaled to at most 48 px", "'presented': every bundled scene at 256 px",
                           "into results/study", "into results/presented", "no per-configuration images",
                           "with per-configuration images", "spp 4,16,64", "8 seeds", "references at 4096 spp"})
    EXPECT_NE(help.find(part), std::string::npos) << part;
}

}  // namespace
