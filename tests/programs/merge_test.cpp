// sweep --merge joins the shards of one study only, and a stream output gets the CSV alone:
//   - shards made with other seeds, targets, or frames with another motion are refused naming both files and
//     the value that differs (a resume refuses the same mixes), and nothing is written;
//   - `--merge /dev/stdout` on a pipe carries exactly the merged CSV (messages on stderr) and creates nothing
//     beside the device (no /dev/spectra/...).
// Tiny shards: sphere_triangle at 24 x 24, 2 groups (spp 4 and 8) split over 2 shards, 64-spp references.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/run_process.h"
#include "support/scratch_dir.h"

namespace fs = std::filesystem;

namespace {
const std::string kBin = std::string(ALIASLAB_BIN_DIR) + "/sweep";
const fs::path& dir() { return aliaslab::testing::scratchDir("aliaslab_merge_test"); }

std::string slurp(const fs::path& p) { return aliaslab::testing::readText(p.string()); }

// Runs `sh -c command`; its stdout and stderr land in *out and *err when given.
int shell(const std::string& command, std::string* out = nullptr, std::string* err = nullptr) {
  const fs::path o = dir() / "run.out", e = dir() / "run.err";
  const int status = std::system(("(" + command + ") > " + o.string() + " 2> " + e.string()).c_str());
  if (out) *out = slurp(o);
  if (err) *err = slurp(e);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Shard i of 2 of the tiny study with `extra` options, into dir()/<name>/study.shard-i-of-2.csv.
std::string shard(const std::string& name, int i, const std::string& extra) {
  const fs::path out = dir() / name;
  const std::string args = " --scenes " + std::string(ALIASLAB_SOURCE_DIR) + "/scenes/sphere_triangle.txt" +
                           " --size 24 24 --samplers random --spp 4,8 --filters tent --radii 1 --ref-spp 64 --quiet" +
                           " --no-images --threads 1 --cache " + (dir() / "cache").string() + " --out " + out.string() +
                           " --shard " + std::to_string(i) + "/2 " + extra;
  std::string err;
  EXPECT_EQ(shell(kBin + args, nullptr, &err), 0) << err;
  return (out / ("study.shard-" + std::to_string(i) + "-of-2.csv")).string();
}

// Merging shard 0 made with `a` and shard 1 made with `b` is refused: exit 2, both files and `what` named.
void expectRefused(const std::string& name, const std::string& a, const std::string& b, const std::string& what) {
  const std::string s0 = shard(name + "_a", 0, a), s1 = shard(name + "_b", 1, b);
  const std::string merged = (dir() / (name + ".csv")).string();
  std::string err;
  EXPECT_EQ(shell(kBin + " --merge " + merged + " " + s0 + " " + s1, nullptr, &err), 2) << err;
  EXPECT_EQ(err.rfind("sweep: --merge: ", 0), 0u) << err;
  for (const std::string& part : {s0, s1, std::string("different studies"), what})
    EXPECT_NE(err.find(part), std::string::npos) << "missing '" << part << "' in:\n" << err;
  EXPECT_FALSE(fs::exists(merged));
}

TEST(MergeOneStudy, ShardsWithOtherSeedsAreRefused) {
  expectRefused("seeds", "--seeds 2 --target area", "--seeds 3 --target area", "seeds 2 in");
}

TEST(MergeOneStudy, ShardsWithOtherTargetsAreRefused) {
  expectRefused("targets", "--seeds 2 --target area", "--seeds 2 --target area,gaussian:1.5", "targets box:0.5 in");
}

TEST(MergeOneStudy, ShardsWithFramesOfAnotherMotionAreRefused) {
  expectRefused("motion", "--seeds 2 --target area --frames 2 --motion 0.5,0",
                "--seeds 2 --target area --frames 2 --motion 0.25,0", "2 frames, motion 0.25,0 in");
}

TEST(MergeOneStudy, ShardsOfOneStudyMerge) {
  const std::string s0 = shard("same", 0, "--seeds 2 --target area"), s1 = shard("same", 1, "--seeds 2 --target area");
  std::string err;
  EXPECT_EQ(shell(kBin + " --merge " + (dir() / "same" / "study.csv").string() + " " + s0 + " " + s1, nullptr, &err), 0)
      << err;
  EXPECT_TRUE(fs::exists(dir() / "same" / "spectra" / "sphere_triangle.csv"));
}

TEST(MergeToStream, StdoutOnAPipeCarriesTheCsvAloneAndNothingIsCreatedBesideIt) {
  const std::string s0 = shard("stream", 0, "--seeds 2 --target area"), s1 = shard("stream", 1, "--seeds 2 --target area");
  const fs::path file = dir() / "stream" / "study.csv";
  std::string err;
  ASSERT_EQ(shell(kBin + " --merge " + file.string() + " " + s0 + " " + s1, nullptr, &err), 0) << err;
  const bool spectraBefore = fs::exists("/dev/spectra");
  std::string out;
  // (timeout: an older sweep read /dev/stdout back for its bound check, which waits forever on a pipe)
  ASSERT_EQ(shell("timeout 120 " + kBin + " --merge /dev/stdout " + s0 + " " + s1 + " | cat", &out, &err), 0) << err;
  EXPECT_EQ(out, slurp(file)) << "the stream must be the merged CSV, nothing more";
  EXPECT_NE(err.find("merged 2 files into /dev/stdout"), std::string::npos) << err;
  if (!spectraBefore) EXPECT_FALSE(fs::exists("/dev/spectra")) << "a merge into /dev/stdout made /dev/spectra";
  EXPECT_FALSE(fs::exists("/dev/stdout.lock"));
}

}  // namespace
