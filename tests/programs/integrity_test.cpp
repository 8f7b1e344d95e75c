// Issue 21 class 1 and issue 16.2: nothing is lost or silently dropped.
// Each test drives the real `sweep` program on a tiny study (8 x 8 pixels,
// 32 reference spp) and checks the files it leaves: a foreign CSV is left
// byte-identical, a second run on one CSV is refused while shards run side
// by side, every damaged shard stops the merge naming file and line, two
// scenes with one stem are refused, a replaced cached reference is noticed,
// leftovers of a killed run are removed, and a rerun with other study-wide
// options does not append a second study.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>
#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sys/stat.h>
#include <thread>
#include <algorithm>
#include <signal.h>
#include <sstream>

#include "support/run_process.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "support/scratch_dir.h"
#include "study/records/csv.h"
#include "study/records/lock.h"
#include "study/records/spectrum_key.h"
#include "study/reference/reference.h"

namespace fs = std::filesystem;
using namespace aliaslab;
using aliaslab::testing::readText;
using aliaslab::testing::runProcess;

namespace {

const std::string kSweep = std::string(ALIASLAB_BIN_DIR) + "/sweep";
const std::string kScene = ALIASLAB_SOURCE_DIR "/scenes/sphere_triangle.txt";

fs::path dirFor(const std::string& name) {
  const fs::path d = aliaslab::testing::scratchDir("aliaslab_integrity") / name;
  fs::create_directories(d / "logs");
  return d;
}

// Runs sweep on the tiny study in `dir` with extra arguments.
aliaslab::testing::ProcessResult sweep(const fs::path& dir, std::vector<std::string> extra, bool tiny = true) {
  std::vector<std::string> argv{kSweep};
  if (tiny)
    for (const char* a : {"--samplers", "random", "--spp", "4", "--filters", "box", "--radii", "1", "--ref-spp", "32",
                          "--size", "8", "8", "--cache", "cache", "--quiet", "--no-images", "--threads", "1", "--target", "area"})
      argv.push_back(a);
  argv.insert(argv.end(), extra.begin(), extra.end());
  return runProcess(argv, dir.string(), (dir / "logs").string());
}

std::vector<std::string> scene() { return {"--scenes", kScene}; }
std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

size_t dataRows(const fs::path& csv) {
  std::ifstream in(csv);
  std::string l;
  size_t n = 0;
  while (std::getline(in, l)) n += !l.empty();
  return n ? n - 1 : 0;
}

}  // namespace

TEST(Integrity, AForeignCsvIsNeverModified) {
  const fs::path d = dirFor("foreign");
  // A text without a trailing newline, and a two-line file: both must stay byte-identical.
  const std::string texts[] = {std::string(5000, 'x'), "a,b\n1,2"};
  for (const std::string& text : texts) {
    std::ofstream(d / "f.csv", std::ios::binary) << text;
    const auto r = sweep(d, scene() + std::vector<std::string>{"--seeds", "2", "--out", "o", "--csv", "f.csv"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("f.csv: not a study CSV"), std::string::npos) << r.err;
    EXPECT_EQ(readText((d / "f.csv").string()), text);
  }
}

TEST(Integrity, ASecondRunOnOneCsvIsRefusedNamingTheHolder) {
  const fs::path d = dirFor("lock");
  fs::create_directories(d / "o");
  {
    const CsvLock held((d / "o" / "study.csv").string(), "test-holder");  // another live run
    const auto r = sweep(d, scene() + std::vector<std::string>{"--seeds", "2", "--out", "o"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("in use by another run (test-holder process " + std::to_string(::getpid())),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(d / "o" / "study.csv"));
  }
  // A lock file left by a crashed run (no process holds it) is stale: the next run takes it.
  std::ofstream(d / "o" / "study.csv.lock") << "sweep process 999999 on gone, started long ago\n";
  const auto r = sweep(d, scene() + std::vector<std::string>{"--seeds", "2", "--out", "o"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(dataRows(d / "o" / "study.csv"), 2u);
  EXPECT_FALSE(fs::exists(d / "o" / "study.csv.lock")) << "released on exit";
}

TEST(Integrity, ShardsAndASharedCacheWorkSideBySide) {
  const fs::path d = dirFor("shards");
  // Two shards of one study and a third, unrelated study, all at once, sharing one reference cache.
  const auto args = scene() + std::vector<std::string>{"--samplers", "random,jittered", "--seeds", "2", "--out", "o"};
  std::vector<std::string> a{kSweep}, b{kSweep}, c{kSweep};
  auto tinyArgs = [](std::vector<std::string>& v, const std::vector<std::string>& extra) {
    for (const char* x : {"--spp", "4", "--filters", "box", "--radii", "1", "--ref-spp", "32", "--size", "8", "8",
                          "--cache", "cache", "--quiet", "--no-images", "--threads", "1", "--target", "area"})
      v.push_back(x);
    v.insert(v.end(), extra.begin(), extra.end());
  };
  tinyArgs(a, args + std::vector<std::string>{"--shard", "0/2"});
  tinyArgs(b, args + std::vector<std::string>{"--shard", "1/2"});
  tinyArgs(c, scene() + std::vector<std::string>{"--samplers", "sobol", "--seeds", "2", "--out", "other"});
  fs::create_directories(d / "la"), fs::create_directories(d / "lb"), fs::create_directories(d / "lc");
  using aliaslab::testing::spawnProcess;
  using aliaslab::testing::waitProcess;
  const pid_t pa = spawnProcess(a, d.string(), (d / "la/o").string(), (d / "la/e").string());
  const pid_t pb = spawnProcess(b, d.string(), (d / "lb/o").string(), (d / "lb/e").string());
  const pid_t pc = spawnProcess(c, d.string(), (d / "lc/o").string(), (d / "lc/e").string());
  const auto ra = waitProcess(pa, (d / "la/o").string(), (d / "la/e").string());
  const auto rb = waitProcess(pb, (d / "lb/o").string(), (d / "lb/e").string());
  const auto rc = waitProcess(pc, (d / "lc/o").string(), (d / "lc/e").string());
  EXPECT_EQ(ra.exitCode, 0) << ra.err;
  EXPECT_EQ(rb.exitCode, 0) << rb.err;
  EXPECT_EQ(rc.exitCode, 0) << rc.err;
  EXPECT_EQ(dataRows(d / "o" / "study.shard-0-of-2.csv"), 2u);
  EXPECT_EQ(dataRows(d / "o" / "study.shard-1-of-2.csv"), 2u);
  EXPECT_EQ(dataRows(d / "other" / "study.csv"), 2u);
  const auto m = runProcess({kSweep, "--merge", "o/all.csv", "o/study.shard-0-of-2.csv", "o/study.shard-1-of-2.csv"},
                            d.string(), (d / "logs").string());
  EXPECT_EQ(m.exitCode, 0) << m.err;
  EXPECT_EQ(dataRows(d / "o" / "all.csv"), 4u);
}

TEST(Integrity, MergeRefusesEveryDamagedShardNamingFileAndLine) {
  const fs::path d = dirFor("merge");
  const auto r = sweep(d, scene() + std::vector<std::string>{"--samplers", "jittered", "--seeds", "2", "--out",
                                                             "o", "--shard", "0/1"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string good = readText((d / "o" / "study.csv").string());  // header + 4 rows
  ASSERT_EQ(dataRows(d / "o" / "study.csv"), 4u);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(d / name, std::ios::binary) << text;
    return name;
  };
  const std::string cut = good.substr(0, good.size() - 4);          // last line cut
  std::string missing = good;                                       // a row missing its last column
  const size_t row3 = missing.find('\n', missing.find('\n', missing.find('\n') + 1) + 1);
  missing.erase(missing.rfind(',', row3), row3 - missing.rfind(',', row3));
  std::string conflict = good;                                      // same key, another mse
  const size_t l2 = conflict.find('\n') + 1;
  auto f = splitCsvLine(conflict.substr(l2, conflict.find('\n', l2) - l2));
  f[10] = "0.123456789";
  std::string line;
  for (const auto& x : f) line += (line.empty() ? "" : ",") + x;
  conflict.replace(l2, conflict.find('\n', l2) - l2, line);
  fs::create_directories(d / "folder.csv");
  struct Bad {
    std::vector<std::string> inputs;
    std::string expect;
  };
  const std::vector<Bad> bad = {
      {{write("cut.csv", cut)}, "cut.csv:5: cut line"},
      {{write("missing.csv", missing)},
       "missing.csv:3: has " + std::to_string(csvColumns().size() - 1) + " fields, expected " +
           std::to_string(csvColumns().size())},
      {{write("study.shard-0-of-1.csv", std::string())}, "study.shard-0-of-1.csv: is empty"},
      {{write("headeronly.csv", csvHeader() + "\n")}, "headeronly.csv: holds no rows"},
      {{"folder.csv"}, "folder.csv: is a folder"},
      {{"o/study.csv", write("conflict.csv", conflict)}, "conflict.csv: line 2 and o/study.csv line 2 give different"},
  };
  for (const Bad& b : bad) {
    std::vector<std::string> argv{kSweep, "--merge", "merged.csv"};
    argv.insert(argv.end(), b.inputs.begin(), b.inputs.end());
    const auto m = runProcess(argv, d.string(), (d / "logs").string());
    EXPECT_EQ(m.exitCode, 2) << b.expect << "\n" << m.err;
    EXPECT_NE(m.err.find(b.expect), std::string::npos) << m.err;
    EXPECT_FALSE(fs::exists(d / "merged.csv")) << b.expect;
  }
  // An empty highest shard of a study with fewer groups than shards is legitimate.
  write("s.shard-0-of-2.csv", csvHeader() + "\n" + good.substr(l2, good.find('\n', l2) - l2 + 1));
  write("s.shard-1-of-2.csv", csvHeader() + "\n");
  {  // with that row's spectra (a merge checks them: tests/programs/spectra_integrity_test.cpp)
    const auto g = splitCsvLine(good.substr(l2, good.find('\n', l2) - l2));
    const std::string prefix = spectrumKeyOfCsvRow(g) + ',';  // its spectrum lines start with its key
    std::istringstream all(readText((d / "o" / "spectra" / "sphere_triangle.csv").string()));
    std::string text, l;
    for (bool header = true; std::getline(all, l); header = false)
      if (header || l.rfind(prefix, 0) == 0) text += l + '\n';
    fs::create_directories(d / "spectra");
    write("spectra/sphere_triangle.s.shard-0-of-2.csv", text);
  }
  const auto ok = runProcess({kSweep, "--merge", "merged.csv", "s.shard-0-of-2.csv", "s.shard-1-of-2.csv"},
                             d.string(), (d / "logs").string());
  EXPECT_EQ(ok.exitCode, 0) << ok.err;
  EXPECT_EQ(dataRows(d / "merged.csv"), 1u);
}

TEST(Integrity, TwoScenesWithOneStemAreRefusedNamingBoth) {
  const fs::path d = dirFor("stems");
  fs::create_directories(d / "a"), fs::create_directories(d / "b");
  fs::copy_file(kScene, d / "a" / "s.txt");
  fs::copy_file(ALIASLAB_SOURCE_DIR "/scenes/sinc.txt", d / "b" / "s.txt");
  const auto r = sweep(d, {"--scenes", "a/s.txt,b/s.txt", "--seeds", "2", "--out", "o"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("'a/s.txt' and 'b/s.txt'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(d / "o" / "study.csv"));
}

TEST(Integrity, AReplacedCachedReferenceIsNotTrusted) {
  const fs::path d = dirFor("cache");
  const auto first = sweep(d, scene() + std::vector<std::string>{"--seeds", "2", "--out", "o"});
  ASSERT_EQ(first.exitCode, 0) << first.err;
  const std::string csv = readText((d / "o" / "study.csv").string());
  // Replace every cached EXR by another valid EXR of the same size (all pixels 7).
  for (const auto& e : fs::directory_iterator(d / "cache"))
    if (e.path().extension() == ".exr") writeImage(e.path().string(), Image(8, 8, Color(7, 7, 7)));
  fs::remove(d / "o" / "study.csv");
  const auto again = sweep(d, scene() + std::vector<std::string>{"--seeds", "2", "--out", "o"});
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(again.err.find("does not match its manifest"), std::string::npos) << again.err;
  // The rerun rendered the references again, so its results equal the first run's (timing aside).
  auto results = [](const std::string& text) {
    std::string out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) {
      auto f = splitCsvLine(l);
      f.resize(21);
      for (const auto& x : f) out += x + ",";
      out += "\n";
    }
    return out;
  };
  EXPECT_EQ(results(readText((d / "o" / "study.csv").string())), results(csv));
}

TEST(Integrity, AReplacedHalfDifferenceIsNotTrusted) {
  const fs::path d = dirFor("cache-diff");
  const auto first = sweep(d, scene() + std::vector<std::string>{"--seeds", "2", "--out", "o"});
  ASSERT_EQ(first.exitCode, 0) << first.err;
  // Each cache entry holds G (<key>.exr) and D (<key>.diff.exr); replace only the D images.
  int replaced = 0;
  for (const auto& e : fs::directory_iterator(d / "cache"))
    if (e.path().string().size() > 9 && e.path().string().substr(e.path().string().size() - 9) == ".diff.exr")
      writeImage(e.path().string(), Image(8, 8, Color(7, 7, 7))), ++replaced;
  ASSERT_GT(replaced, 0) << "the cache keeps no half-difference images";
  fs::remove(d / "o" / "study.csv");
  const auto again = sweep(d, scene() + std::vector<std::string>{"--seeds", "2", "--out", "o"});
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(again.err.find("no matching half-difference image"), std::string::npos) << again.err;
}

TEST(Integrity, LeftoversOfAKilledRunAreRemoved) {
  const fs::path d = dirFor("partial");
  fs::create_directories(d / "o" / "images" / "x");
  // pid 999999 does not run (beyond the default pid_max of 4194304 it could not; check anyway).
  ASSERT_NE(::kill(999999, 0), 0);
  const fs::path dead = d / "o" / "images" / "x" / "a.png.partial.999999.0.png";
  const fs::path live = d / "o" / ("b.png.partial." + std::to_string(::getpid()) + ".0.png");
  std::ofstream(dead).put('x');
  std::ofstream(live).put('x');
  const auto r = sweep(d, scene() + std::vector<std::string>{"--seeds", "2", "--out", "o"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live)) << "a running process's temporary is not touched";
}

TEST(Integrity, DiskFullNamesTheFileAndTheReason) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  try {
    writeTextFile("/dev/full", "some text\n");
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: write failed: No space left on device"), std::string::npos)
        << e.what();
  }
}

TEST(Integrity, ARerunWithOtherStudyOptionsDoesNotAppendASecondStudy) {
  const fs::path d = dirFor("rerun");
  ASSERT_EQ(sweep(d, scene() + std::vector<std::string>{"--seeds", "3", "--out", "o"}).exitCode, 0);
  const std::string before = readText((d / "o" / "study.csv").string());
  struct Other {
    std::vector<std::string> args;
    std::string option;
  };
  const std::vector<Other> others = {
      {{"--seeds", "2"}, "--seeds: o/study.csv holds a study made with seeds 3"},
      {{"--seeds", "3", "--ref-spp", "64"}, "--ref-spp: o/study.csv holds a study made with ref_spp 32"},
  };
  for (const Other& o : others) {
    std::vector<std::string> argv{kSweep, "--scenes", kScene, "--samplers", "random", "--spp", "4", "--filters", "box",
                                  "--radii", "1", "--cache", "cache", "--quiet", "--no-images", "--out", "o",
                                  "--target", "area"};
    argv.insert(argv.end(), o.args.begin(), o.args.end());
    if (o.option.find("ref-spp") == std::string::npos) argv.insert(argv.end(), {"--ref-spp", "32"});
    argv.insert(argv.end(), {"--size", "8", "8"});
    const auto r = runProcess(argv, d.string(), (d / "logs").string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(r.err.rfind("sweep: " + o.option, 0), 0u) << r.err;
    EXPECT_EQ(readText((d / "o" / "study.csv").string()), before);
  }
  // The size of a scene is part of the study too.
  std::vector<std::string> argv{kSweep, "--scenes", kScene, "--samplers", "random", "--spp", "4", "--filters", "box",
                                "--radii", "1", "--cache", "cache", "--quiet", "--no-images", "--out", "o",
                                "--seeds", "3", "--ref-spp", "32", "--size", "6", "6", "--target", "area"};
  const auto s = runProcess(argv, d.string(), (d / "logs").string());
  EXPECT_EQ(s.exitCode, 2) << s.err;
  EXPECT_NE(s.err.find("--size: o/study.csv holds scene sphere_triangle at 8 x 8"), std::string::npos) << s.err;
  EXPECT_EQ(readText((d / "o" / "study.csv").string()), before);
}

// Class 4: files that are not plain files.
TEST(NonPlainOutputs, TextGoesThroughAFifoAndLinksStayLinks) {
  const fs::path d = dirFor("fifo");
  const fs::path fifo = d / "pipe.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  // A reader drains the FIFO (opening it blocks until filterprofile opens it for writing).
  std::string got;
  std::thread reader([&] { got = readText(fifo.string()); });
  const auto r = runProcess({std::string(ALIASLAB_BIN_DIR) + "/filterprofile", "--output", fifo.string()}, d.string(),
                            (d / "logs").string());
  // Should filterprofile exit without opening the FIFO, release the reader rather than hang.
  if (const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK); fd >= 0) ::close(fd);
  reader.join();
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::is_fifo(fifo)) << "the FIFO was replaced by a regular file";
  EXPECT_GT(std::count(got.begin(), got.end(), '\n'), 100);

  // A symbolic link is followed: the link stays, its target gets the text.
  fs::create_symlink("target.csv", d / "link.csv");
  const auto l = runProcess({std::string(ALIASLAB_BIN_DIR) + "/filterprofile", "--output", "link.csv"}, d.string(),
                            (d / "logs").string());
  EXPECT_EQ(l.exitCode, 0) << l.err;
  EXPECT_TRUE(fs::is_symlink(d / "link.csv"));
  EXPECT_EQ(readText((d / "target.csv").string()), got);
}

TEST(NonPlainOutputs, AnImageOntoADeviceIsRefused) {
  const fs::path d = dirFor("device");
  fs::create_symlink("/dev/null", d / "null.png");
  const auto r = runProcess({std::string(ALIASLAB_BIN_DIR) + "/raytracer", "-input", kScene, "-size", "8", "8",
                             "-output", "null.png"},
                            d.string(), (d / "logs").string());
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("null.png: not a regular file"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(NonPlainOutputs, AnOutputEqualToAnInputIsRefused) {
  const fs::path d = dirFor("same");
  fs::copy_file(kScene, d / "in.png");
  const std::string scene = readText((d / "in.png").string());
  const auto r = runProcess({std::string(ALIASLAB_BIN_DIR) + "/raytracer", "-input", "in.png", "-size", "8", "8",
                             "-output", "./in.png"},
                            d.string(), (d / "logs").string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("-output: './in.png' is also an input"), std::string::npos) << r.err;
  EXPECT_EQ(readText((d / "in.png").string()), scene);
  // The sweep's CSV onto its scene file.
  fs::copy_file(kScene, d / "s.csv");
  const auto s = sweep(d, {"--scenes", "s.csv", "--seeds", "2", "--out", "o", "--csv", "s.csv"});
  EXPECT_EQ(s.exitCode, 2) << s.err;
  EXPECT_NE(s.err.find("--csv: 's.csv' is also an input"), std::string::npos) << s.err;
  EXPECT_EQ(readText((d / "s.csv").string()), scene);
}

// Class 5: configuration files say what they mean.
TEST(ConfigFiles, UnknownKeysAndSectionsAreErrorsNamingKeyAndLine) {
  const fs::path d = dirFor("config");
  const std::pair<std::string, std::string> cases[] = {
      {"[sweep]\nseeds = 4\n", "c.toml:1: section [sweep]"},
      {"# a study\nseeds = 4\nsede = 3\n", "c.toml:3: unknown key 'sede'"},
      {"seeds = 4\nsamplers\n", "c.toml:2: expected 'key = value'"},
  };
  for (const auto& [text, expect] : cases) {
    std::ofstream(d / "c.toml") << text;
    const auto r = sweep(d, scene() + std::vector<std::string>{"--config", "c.toml", "--out", "o"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("sweep: --config: " + expect), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(d / "o" / "study.csv"));
  }
  // Known keys, with '_' for '-', still work.
  std::ofstream(d / "c.toml") << "# a study\nseeds = 2\nref_spp = 32\n";
  const auto ok = runProcess({kSweep, "--config", "c.toml", "--scenes", kScene, "--samplers", "random", "--spp", "4",
                              "--filters", "box", "--radii", "1", "--size", "8", "8", "--cache", "cache", "--quiet",
                              "--no-images", "--out", "o"},
                             d.string(), (d / "logs").string());
  EXPECT_EQ(ok.exitCode, 0) << ok.err;
  const std::string csv = readText((d / "o" / "study.csv").string());
  EXPECT_NE(csv.find(",2,"), std::string::npos);
}
