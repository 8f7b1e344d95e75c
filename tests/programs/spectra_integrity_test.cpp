// Issue 31: the spectra files have the study CSV's guarantees (docs/integrity.md "Spectra files").
// A tiny sweep (2 scenes, 8 x 8 pixels, 32 reference spp) is run once uninterrupted; then
//  - killed with SIGKILL while its spectra grow, and left in each state a kill or a full disk during a group's
//    spectra write can leave (a torn line, a block cut at a line boundary, a group's spectra written but not its
//    CSV rows, spectra out of canonical order): each resumed run ends with spectra files byte-identical to the
//    uninterrupted run's and the same CSV (timing columns aside);
//  - run as two shards whose spectra are then damaged (missing, empty, a FIFO, cut mid-line, cut at a line
//    boundary, one configuration's block removed): every merge is refused naming the spectra file, and writes
//    nothing.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "study/records/csv.h"
#include "support/run_process.h"
#include "support/scratch_dir.h"

namespace fs = std::filesystem;
using namespace aliaslab;
using namespace aliaslab::testing;

namespace {

const std::string kSweep = std::string(ALIASLAB_BIN_DIR) + "/sweep";

fs::path dirFor(const std::string& name) {
  const fs::path d = scratchDir("aliaslab_spectra_integrity") / name;
  fs::remove_all(d);
  fs::create_directories(d / "logs");
  return d;
}

std::vector<std::string> command(const fs::path& dir, std::vector<std::string> extra = {}) {
  const std::string s = ALIASLAB_SOURCE_DIR "/scenes/";
  std::vector<std::string> argv{kSweep, "--scenes", s + "sphere_triangle.txt," + s + "zoneplate.txt",
                                "--samplers", "random,jittered", "--spp", "4", "--filters", "box,tent",
                                "--radii", "1", "--seeds", "2", "--ref-spp", "32", "--size", "8", "8",
                                "--threads", "1", "--target", "area", "--no-images", "--quiet",
                                "--out", (dir / "out").string(), "--cache", (dir / "cache").string()};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

ProcessResult run(const fs::path& dir, std::vector<std::string> extra = {}) {
  return runProcess(command(dir, extra), dir.string(), (dir / "logs").string());
}

void writeBytes(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

/// The CSV's lines without the timing columns (they differ between runs).
std::vector<std::string> untimed(const fs::path& csv) {
  std::vector<std::string> out;
  const auto timing = csvTimingColumns();
  for (const std::string& l : readCsvLines(csv.string())) {
    auto f = splitCsvLine(l);
    std::string s;
    for (size_t i = 0; i < f.size(); ++i)
      if (std::find(timing.begin(), timing.end(), i) == timing.end()) s += f[i] + '|';
    out.push_back(s);
  }
  return out;
}

/// The uninterrupted run (made once), its spectra files by name.
struct Reference {
  fs::path dir;
  std::map<std::string, std::string> spectra;
};
const Reference& uninterrupted() {
  static const Reference r = [] {
    Reference ref{dirFor("once"), {}};
    const ProcessResult p = run(ref.dir);
    EXPECT_EQ(p.exitCode, 0) << p.err;
    for (const auto& e : fs::directory_iterator(ref.dir / "out" / "spectra"))
      ref.spectra[e.path().filename().string()] = readText(e.path().string());
    return ref;
  }();
  return r;
}

/// Resumes `dir` and checks its spectra and CSV equal the uninterrupted run's.
void expectResumedToTheSameBytes(const fs::path& dir, const std::string& state) {
  const Reference& once = uninterrupted();
  const ProcessResult p = run(dir);
  ASSERT_EQ(p.exitCode, 0) << state << "\n" << p.err;
  for (const auto& [name, text] : once.spectra)
    EXPECT_TRUE(readText((dir / "out" / "spectra" / name).string()) == text) << state << ": spectra/" << name
                                                                             << " differs from the uninterrupted run's";
  EXPECT_EQ(untimed(dir / "out" / "study.csv"), untimed(once.dir / "out" / "study.csv")) << state;
}

/// A copy of the uninterrupted run's output in a fresh folder (cache shared through a copy too).
fs::path copyOfOnce(const std::string& name) {
  const fs::path d = dirFor(name);
  fs::copy(uninterrupted().dir / "out", d / "out", fs::copy_options::recursive);
  fs::copy(uninterrupted().dir / "cache", d / "cache", fs::copy_options::recursive);
  return d;
}

}  // namespace

TEST(SpectraIntegrity, AKillDuringASpectraWriteResumesToTheUninterruptedBytes) {
  if (!fs::exists(kSweep)) GTEST_SKIP() << kSweep << " is not built";
  const Reference& once = uninterrupted();
  ASSERT_EQ(once.spectra.size(), 2u);
  const std::string name = "zoneplate.csv";
  const std::string full = once.spectra.at(name);
  const std::string header = full.substr(0, full.find('\n') + 1);
  // zoneplate's rows in the CSV (its scene is the last one a run writes)
  auto withoutRowsOf = [](const fs::path& csv, const std::string& scene, size_t keep) {
    std::vector<std::string> lines = readCsvLines(csv.string()), kept;
    size_t n = 0;
    for (const std::string& l : lines)
      if (splitCsvLine(l)[csvColumn("scene")] != scene || n++ < keep) kept.push_back(l);
    writeCsvFile(csv.string(), kept);
  };

  // 1. A torn line (the kill landed inside the write) with the group's CSV rows not written.
  {
    const fs::path d = copyOfOnce("torn");
    writeBytes(d / "out" / "spectra" / name, full.substr(0, full.size() * 2 / 3));
    withoutRowsOf(d / "out" / "study.csv", "zoneplate", 1);
    expectResumedToTheSameBytes(d, "torn line, rows missing");
  }
  // 2. The last block cut at a line boundary while the CSV holds its rows: its spectra are measured again.
  {
    const fs::path d = copyOfOnce("boundary");
    size_t cut = full.size() - 1;
    for (int lines = 0; lines < 5; ++lines) cut = full.rfind('\n', cut - 1);
    ++cut;
    writeBytes(d / "out" / "spectra" / name, full.substr(0, cut));
    expectResumedToTheSameBytes(d, "cut at a line boundary, rows present");
  }
  // 3. The spectra written, the CSV rows not (a kill between the two writes): measured again, one copy kept.
  {
    const fs::path d = copyOfOnce("rows");
    withoutRowsOf(d / "out" / "study.csv", "zoneplate", 0);
    expectResumedToTheSameBytes(d, "spectra present, rows missing");
  }
  // 4. Everything written but not yet in canonical order (a kill in the final step): put back in order.
  {
    const fs::path d = copyOfOnce("order");
    std::vector<std::string> lines;
    for (size_t s = header.size(), nl; (nl = full.find('\n', s)) != std::string::npos; s = nl + 1)
      lines.push_back(full.substr(s, nl - s + 1));
    std::reverse(lines.begin(), lines.end());
    std::string shuffled = header;
    for (const std::string& l : lines) shuffled += l;
    writeBytes(d / "out" / "spectra" / name, shuffled);
    expectResumedToTheSameBytes(d, "out of canonical order");
  }
  // 5. Real kills with SIGKILL while the spectra grow, then one resume.
  {
    const fs::path d = dirFor("killed");
    const fs::path spectra = d / "out" / "spectra" / "sphere_triangle.csv";
    int landed = 0;
    for (size_t bytes : {size_t(1), full.size() / 3}) {
      const pid_t pid = spawnProcess(command(d), d.string(), (d / "logs" / "o").string(), (d / "logs" / "e").string());
      int status = 0;
      bool done = false;
      std::error_code ec;
      while (!(fs::exists(spectra, ec) && fs::file_size(spectra, ec) >= bytes))
        if (waitpid(pid, &status, WNOHANG) == pid) {
          done = true;
          break;
        }
      if (done) continue;
      ::kill(pid, SIGKILL);
      const ProcessResult r = waitProcess(pid, (d / "logs" / "o").string(), (d / "logs" / "e").string());
      landed += r.signaled;
    }
    std::printf("%d of 2 kills landed while the sweep ran\n", landed);
    expectResumedToTheSameBytes(d, "after SIGKILL");
  }
}

TEST(SpectraIntegrity, AMergeOfShardsWithDamagedSpectraIsRefusedNamingTheFile) {
  if (!fs::exists(kSweep)) GTEST_SKIP() << kSweep << " is not built";
  const fs::path d = dirFor("shards");
  for (const char* shard : {"0/2", "1/2"}) {
    const ProcessResult p = run(d, {"--shard", shard});
    ASSERT_EQ(p.exitCode, 0) << p.err;
  }
  const fs::path out = d / "out";
  const std::vector<std::string> shards{(out / "study.shard-0-of-2.csv").string(),
                                        (out / "study.shard-1-of-2.csv").string()};
  auto merge = [&](const fs::path& to) {
    fs::create_directories(to.parent_path());
    std::vector<std::string> argv{kSweep, "--merge", to.string()};
    argv.insert(argv.end(), shards.begin(), shards.end());
    return runProcess(argv, d.string(), (d / "logs").string());
  };
  // The undamaged shards merge, and the merged spectra equal an uninterrupted run's.
  {
    const ProcessResult p = merge(d / "merged" / "study.csv");
    ASSERT_EQ(p.exitCode, 0) << p.err;
    for (const auto& [name, text] : uninterrupted().spectra)
      EXPECT_TRUE(readText((d / "merged" / "spectra" / name).string()) == text) << "merged spectra/" << name;
  }
  // Each damage of shard 1's spectra of one scene.
  const fs::path victim = out / "spectra" / "zoneplate.study.shard-1-of-2.csv";
  ASSERT_TRUE(fs::exists(victim));
  const std::string good = readText(victim.string());
  std::vector<std::string> lines;
  for (size_t s = 0, nl; (nl = good.find('\n', s)) != std::string::npos; s = nl + 1) lines.push_back(good.substr(s, nl - s + 1));
  ASSERT_GT(lines.size(), 10u);
  auto firstLines = [&](size_t n) {
    std::string t;
    for (size_t i = 0; i < n; ++i) t += lines[i];
    return t;
  };
  // one configuration's noise block removed (the first configuration's)
  std::string noNoise = lines[0];
  const std::string firstKey = lines[1].substr(0, lines[1].find(",error,"));
  for (size_t i = 1; i < lines.size(); ++i)
    if (lines[i].rfind(firstKey + ",noise,", 0) != 0) noNoise += lines[i];
  const std::vector<std::pair<std::string, std::string>> damages = {
      {"missing", ""},
      {"empty", "is empty"},
      {"fifo", "is a FIFO"},
      {"cut mid-line", "cut last line"},
      {"one line short", "another set of noise bins"},
      {"two thirds", "the spectra are damaged"},
      {"no noise block", "has no noise spectrum"}};
  int attempt = 0;
  for (const auto& [damage, expected] : damages) {
    fs::remove(victim);
    if (damage == "empty") writeBytes(victim, "");
    if (damage == "fifo") {
      ASSERT_EQ(::mkfifo(victim.c_str(), 0644), 0);
    }
    if (damage == "cut mid-line") writeBytes(victim, good.substr(0, good.size() - 5));
    if (damage == "one line short") writeBytes(victim, firstLines(lines.size() - 1));
    if (damage == "two thirds") writeBytes(victim, firstLines(lines.size() * 2 / 3));
    if (damage == "no noise block") writeBytes(victim, noNoise);
    const fs::path to = d / ("m-" + std::to_string(attempt++)) / "study.csv";
    const ProcessResult p = merge(to);
    EXPECT_NE(p.exitCode, 0) << damage;
    EXPECT_FALSE(p.signaled) << damage;
    EXPECT_NE(p.err.find("zoneplate.study.shard-1-of-2.csv"), std::string::npos) << damage << ": " << p.err;
    EXPECT_NE(p.err.find(damage == "missing" ? "missing" : expected), std::string::npos) << damage << ": " << p.err;
    EXPECT_FALSE(fs::exists(to)) << damage << ": the merge wrote its CSV";
    EXPECT_FALSE(fs::exists(to.parent_path() / "spectra")) << damage << ": the merge wrote spectra";
  }
  fs::remove(victim);
  writeBytes(victim, good);
}
