// A study CSV named *.gz (study/csv.h, core/gzip.h): the sweep writes it gzipped with the same content as the
// plain CSV, resumes it after a torn last gzip member or a kill as it resumes a plain CSV after a torn line,
// shards written gzipped merge, a torn gzipped shard is refused by the merge, and a file at a .gz path that is not
// gzip data is left unchanged. gzip(1) is the independent decoder. Tiny sizes, as in sweep_test.cpp.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/gzip.h"
#include "study/records/csv.h"
#include "support/sweep_program.h"
#include "support/scratch_dir.h"

using namespace aliaslab;
namespace fs = std::filesystem;

namespace {
const fs::path& workDir() { return aliaslab::testing::scratchDir("aliaslab_sweep_gzip_test"); }

// The tiny study on one thread, so shards and whole runs print the same threads.
std::string tinyArgs() { return aliaslab::testing::tinySweepArgs(workDir(), 1); }
aliaslab::testing::ProcessResult run(const std::string& args) { return aliaslab::testing::runSweep(args, workDir()); }
std::string slurp(const fs::path& p) { return aliaslab::testing::fileBytes(p); }

// What gzip(1) makes of a file (an independent decoder).
std::string gunzip(const fs::path& p) {
  const fs::path out = p.string() + ".gunzipped";
  EXPECT_EQ(std::system(("gzip -dc " + p.string() + " > " + out.string()).c_str()), 0) << p;
  return slurp(out);
}

// The data lines of a CSV's text with the timing columns blanked (they differ between runs).
std::vector<std::string> withoutTiming(const std::string& text) {
  std::vector<std::string> out;
  size_t start = text.find('\n') + 1;  // after the header
  for (size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1) {
    auto f = splitCsvLine(text.substr(start, nl - start));
    for (size_t c : csvTimingColumns()) f[c] = "";
    std::string joined;
    for (const auto& x : f) joined += x + ",";
    out.push_back(joined);
  }
  return out;
}

// One uninterrupted plain run, shared by the tests.
const fs::path& plainCsv() {
  static const fs::path p = [] {
    const fs::path csv = workDir() / "plain" / "study.csv";
    const auto r = run(tinyArgs() + " --out " + (workDir() / "plain").string() + " --csv " + csv.string());
    EXPECT_EQ(r.exitCode, 0) << r.out;
    return csv;
  }();
  return p;
}

// The first `rows` data lines of the plain run (with the header).
std::string headAndRows(int rows) {
  const std::string text = slurp(plainCsv());
  size_t cut = 0;
  for (int line = 0; line <= rows; ++line) cut = text.find('\n', cut) + 1;
  return text.substr(0, cut);
}
}  // namespace

TEST(SweepGzip, AGzipCsvHoldsTheBytesOfThePlainOne) {
  const std::string plain = slurp(plainCsv());
  ASSERT_EQ(withoutTiming(plain).size(), 12u);
  // The same run written to a .gz name: gzip data, whose text is the plain run's (timings aside).
  const fs::path gz = workDir() / "gz" / "study.csv.gz";
  const auto r = run(tinyArgs() + " --out " + (workDir() / "gz").string() + " --csv " + gz.string());
  ASSERT_EQ(r.exitCode, 0) << r.out;
  ASSERT_TRUE(isGzipData(slurp(gz)));
  const std::string text = gunzip(gz);
  EXPECT_EQ(text.substr(0, text.find('\n')), plain.substr(0, plain.find('\n')));
  EXPECT_EQ(withoutTiming(text), withoutTiming(plain));
  // The spectra of study.csv.gz are study.csv's: spectra/<scene>.csv, equal to the plain run's.
  const std::string stem = fs::path(aliaslab::testing::kZonePlate).stem().string();
  EXPECT_EQ(slurp(workDir() / "gz" / "spectra" / (stem + ".csv")), slurp(workDir() / "plain" / "spectra" / (stem + ".csv")));
  // Writing a given CSV's rows to a .gz name (a merge of one file) gives exactly its bytes once gunzipped.
  const fs::path merged = workDir() / "one.csv.gz";
  ASSERT_EQ(run("--merge " + merged.string() + " " + plainCsv().string()).exitCode, 0);
  EXPECT_EQ(gunzip(merged), plain);
  EXPECT_LT(fs::file_size(merged), plain.size() / 2);
}

TEST(SweepGzip, TheDefaultCsvIsTheGzippedOneWhenOnlyThatExists) {
  // OUT/study.csv.gz alone (a committed study): the sweep without --csv resumes it and writes no study.csv
  const fs::path out = workDir() / "default";
  fs::create_directories(out);
  std::ofstream(out / "study.csv.gz", std::ios::binary) << gzipMember(headAndRows(7));
  const auto r = run(tinyArgs() + " --out " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.out;
  EXPECT_NE(r.out.find("7 resumed"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out / "study.csv"));
  EXPECT_EQ(withoutTiming(gunzip(out / "study.csv.gz")), withoutTiming(slurp(plainCsv())));
}

TEST(SweepGzip, ATornLastMemberIsCutOnResumeAndTheRunEndsWithTheSameRows) {
  const auto expected = withoutTiming(slurp(plainCsv()));
  // As a killed run leaves it: the header and 5 rows in whole members, then half of a member with 2 more rows.
  const std::string rows5 = headAndRows(5), rows7 = headAndRows(7);
  const std::string torn = gzipMember(rows7.substr(rows5.size()));
  const fs::path p = workDir() / "torn" / "study.csv.gz";
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << gzipMember(rows5.substr(0, rows5.find('\n') + 1))
                                     << gzipMember(rows5.substr(rows5.find('\n') + 1)) << torn.substr(0, torn.size() / 2);
  EXPECT_EQ(readCsvLines(p.string()).size(), 5u);  // the reader drops the torn member
  auto r = run(tinyArgs() + " --out " + (workDir() / "torn").string() + " --csv " + p.string());
  ASSERT_EQ(r.exitCode, 0) << r.out;
  EXPECT_NE(r.out.find("5 resumed"), std::string::npos) << r.out;
  EXPECT_EQ(withoutTiming(gunzip(p)), expected);
  // A torn line inside a whole member (a torn plain CSV gzipped) is cut as in a plain CSV.
  const fs::path q = workDir() / "torn_line" / "study.csv.gz";
  fs::create_directories(q.parent_path());
  std::ofstream(q, std::ios::binary) << gzipMember(rows5 + rows7.substr(rows5.size(), 40));
  r = run(tinyArgs() + " --out " + (workDir() / "torn_line").string() + " --csv " + q.string());
  ASSERT_EQ(r.exitCode, 0) << r.out;
  EXPECT_NE(r.out.find("5 resumed"), std::string::npos) << r.out;
  EXPECT_EQ(withoutTiming(gunzip(q)), expected);
}

TEST(SweepGzip, KilledRunsResumeToTheSameRows) {
  const auto expected = withoutTiming(slurp(plainCsv()));
  const fs::path p = workDir() / "killed" / "study.csv.gz";
  const std::string args = tinyArgs() + " --out " + (workDir() / "killed").string() + " --csv " + p.string();
  for (const char* after : {"0.05", "0.1", "0.2"}) {
    const std::string killed = "timeout -s KILL " + std::string(after) + " " + aliaslab::testing::kSweepBin;
    std::system((killed + " " + args + " > /dev/null 2>&1").c_str());
    if (fs::exists(p)) EXPECT_NO_THROW(readCsvLines(p.string())) << "killed after " << after << " s";
  }
  ASSERT_EQ(run(args).exitCode, 0);
  EXPECT_EQ(withoutTiming(gunzip(p)), expected);
  EXPECT_EQ(run(args).exitCode, 0);  // a finished study: nothing to add, still the same rows
  EXPECT_EQ(withoutTiming(gunzip(p)), expected);
}

TEST(SweepGzip, GzippedShardsMergeAndATornOneIsRefused) {
  const auto expected = withoutTiming(slurp(plainCsv()));
  const fs::path dir = workDir() / "shards";
  std::vector<std::string> shards;
  for (int i = 0; i < 2; ++i) {
    shards.push_back((dir / ("study.shard-" + std::to_string(i) + "-of-2.csv.gz")).string());
    ASSERT_EQ(run(tinyArgs() + " --out " + dir.string() + " --shard " + std::to_string(i) + "/2 --csv " + shards[i]).exitCode, 0);
  }
  const fs::path merged = dir / "study.csv";
  ASSERT_EQ(run("--merge " + merged.string() + " " + shards[0] + " " + shards[1]).exitCode, 0);
  EXPECT_EQ(withoutTiming(slurp(merged)), expected);
  // the merge's name rule knows gzipped shards: one of two missing is refused
  auto r = run("--merge " + (dir / "half.csv").string() + " " + shards[0]);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.out.find("shard 1 of 2 is missing"), std::string::npos) << r.out;
  // a shard whose last member is cut (interrupted) is refused, named
  const std::string bytes = slurp(shards[1]);
  std::ofstream(shards[1], std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() - 9);
  r = run("--merge " + (dir / "again.csv").string() + " " + shards[0] + " " + shards[1]);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.out.find(shards[1]), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("interrupted"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "again.csv"));
}

TEST(SweepGzip, AFileAtAGzPathThatIsNotGzipIsLeftUnchanged) {
  const fs::path p = workDir() / "notgz" / "study.csv.gz";
  fs::create_directories(p.parent_path());
  const std::string text = headAndRows(3);
  std::ofstream(p, std::ios::binary) << text;
  const auto r = run(tinyArgs() + " --out " + (workDir() / "notgz").string() + " --csv " + p.string());
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.out.find("not a gzipped study CSV"), std::string::npos) << r.out;
  EXPECT_EQ(slurp(p), text);
}
