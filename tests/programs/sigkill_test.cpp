// Nothing lost: a small sweep (build/bin/sweep) is killed with SIGKILL at
// several points — during start-up and reference rendering (after fractions
// of an uninterrupted run's time) and just after its CSV reaches k rows —
// and resumed with the same command each time. The final CSV must equal an
// uninterrupted run's, field by field except the timing columns.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <thread>

#include "support/run_process.h"
#include "study/records/csv.h"

namespace fs = std::filesystem;
using namespace aliaslab;
using namespace aliaslab::testing;
using Clock = std::chrono::steady_clock;

namespace {

const std::string kSweep = std::string(ALIASLAB_BIN_DIR) + "/sweep";

std::vector<std::string> sweepCommand(const fs::path& dir) {
  const std::string s = ALIASLAB_SOURCE_DIR "/scenes/";
  return {kSweep, "--scenes", s + "sphere_triangle.txt," + s + "zoneplate.txt," + s + "siemens.txt",
          "--samplers", "random,jittered,sobol", "--spp", "4,16", "--filters", "box,tent,mitchell,lanczos",
          "--radii", "1,2", "--seeds", "4", "--ref-spp", "256", "--max-size", "32", "--threads", "1",
          "--out", (dir / "out").string(), "--cache", (dir / "cache").string(), "--no-images", "--quiet"};
}

size_t csvLines(const fs::path& csv) {
  const std::string text = readText(csv.string());
  return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

/// Starts the sweep, kills it with SIGKILL once `ready` says so, returns whether it was still running.
template <class Ready>
bool runAndKill(const fs::path& dir, Ready ready) {
  const std::string out = (dir / "stdout.txt").string(), err = (dir / "stderr.txt").string();
  const pid_t pid = spawnProcess(sweepCommand(dir), dir.string(), out, err);
  int status = 0;
  while (!ready()) {
    if (waitpid(pid, &status, WNOHANG) == pid) return false;  // finished first
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  ::kill(pid, SIGKILL);
  const ProcessResult r = waitProcess(pid, out, err);
  return r.signaled && r.signal == SIGKILL;
}

TEST(SigKill, ResumedAfterKillsTheCsvEqualsAnUninterruptedRun) {
  if (!fs::exists(kSweep)) GTEST_SKIP() << kSweep << " is not built";
  const fs::path root = fs::temp_directory_path() / ("aliaslab_sigkill_" + std::to_string(::getpid()));
  fs::remove_all(root);
  const fs::path once = root / "once", killed = root / "killed";
  fs::create_directories(once);
  fs::create_directories(killed);

  // The uninterrupted run and its duration.
  const auto t0 = Clock::now();
  const ProcessResult whole = runProcess(sweepCommand(once), once.string(), once.string());
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  ASSERT_EQ(whole.exitCode, 0) << whole.err;
  const fs::path csv = killed / "out" / "study.csv";
  const size_t rows = csvLines(once / "out" / "study.csv") - 1;
  ASSERT_GT(rows, 100u);

  // Kill after fractions of that time (start-up, references), then after k rows.
  int kills = 0;
  for (double fraction : {0.05, 0.15, 0.3}) {
    const auto start = Clock::now();
    kills += runAndKill(killed, [&] {
      return std::chrono::duration<double>(Clock::now() - start).count() > fraction * seconds;
    });
  }
  for (size_t k : {rows / 5, rows / 2, rows - rows / 5})
    kills += runAndKill(killed, [&] { return fs::exists(csv) && csvLines(csv) >= k + 1; });
  std::printf("%d of 6 kills landed while the sweep ran (%zu rows, uninterrupted %.1f s)\n", kills, rows, seconds);
  EXPECT_GE(kills, 4) << "most kills should land while the sweep runs";

  // Resume to the end.
  const ProcessResult last = runProcess(sweepCommand(killed), killed.string(), killed.string());
  ASSERT_EQ(last.exitCode, 0) << last.err;
  EXPECT_NE(last.out.find("resumed"), std::string::npos) << last.out;

  // Same rows, same order, same numbers (timing columns aside).
  std::istringstream a(readText((once / "out" / "study.csv").string())), b(readText(csv.string()));
  const auto timing = csvTimingColumns();
  std::string la, lb;
  size_t line = 0;
  while (std::getline(a, la)) {
    ++line;
    ASSERT_TRUE(std::getline(b, lb)) << "resumed CSV ends at line " << line;
    const auto fa = splitCsvLine(la), fb = splitCsvLine(lb);
    ASSERT_EQ(fa.size(), fb.size()) << "line " << line;
    for (size_t i = 0; i < fa.size(); ++i) {
      if (std::find(timing.begin(), timing.end(), i) == timing.end()) {
        EXPECT_EQ(fa[i], fb[i]) << "line " << line << " column " << csvColumns()[i];
      }
    }
  }
  EXPECT_FALSE(std::getline(b, lb)) << "resumed CSV has extra lines: " << lb;
  EXPECT_EQ(line, rows + 1);
  fs::remove_all(root);
}

}  // namespace
