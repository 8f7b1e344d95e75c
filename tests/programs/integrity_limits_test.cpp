// Issue 31 (round two of "nothing lost, nothing silently wrong"), the classes beside the spectra
// (tests/programs/spectra_integrity_test.cpp) and the bad-input corpus (tests/badinput/cases.tsv):
// degenerate sizes work, a --target change and an older CSV are refused on resume, special files in the
// reference cache are refused without blocking (and a folder there never gives a stale "Success"),
// overflowing light is refused by the references and counted by the CSV, CR-only scene files are read,
// and the memory estimates hold against an address-space limit (ulimit -v) in sweep, reference, raytracer and
// imgdiff.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "study/records/csv.h"
#include "support/run_process.h"
#include "support/scratch_dir.h"

namespace fs = std::filesystem;
using namespace aliaslab;
using namespace aliaslab::testing;

namespace {

const std::string kBin = ALIASLAB_BIN_DIR;
const std::string kScene = ALIASLAB_SOURCE_DIR "/scenes/sphere_triangle.txt";

fs::path dirFor(const std::string& name) {
  const fs::path d = scratchDir("aliaslab_integrity_limits") / name;
  fs::remove_all(d);
  fs::create_directories(d / "logs");
  return d;
}

ProcessResult sweep(const fs::path& dir, std::vector<std::string> extra) {
  std::vector<std::string> argv{kBin + "/sweep", "--samplers", "random", "--spp", "4", "--filters", "box",
                                "--radii", "1", "--seeds", "2", "--ref-spp", "16", "--cache", "cache", "--quiet",
                                "--no-images", "--threads", "1"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return runProcess(argv, dir.string(), (dir / "logs").string());
}

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

TEST(IntegrityLimits, OnePixelOnASideWorksAndIsMeasured) {
  const fs::path d = dirFor("one_pixel");
  const std::vector<std::vector<std::string>> sizes = {
      {"--size", "1", "64"}, {"--size", "64", "1"}, {"--size", "1", "1"}, {"--long-side", "1"}, {"--max-size", "1"}};
  int n = 0;
  for (const auto& size : sizes) {
    const std::string out = "o" + std::to_string(n++);
    const ProcessResult r = sweep(d, std::vector<std::string>{"--scenes", kScene, "--target", "area", "--out", out} + size);
    ASSERT_FALSE(r.signaled) << size[0] << ": signal " << r.signal << "\n" << r.err;
    ASSERT_EQ(r.exitCode, 0) << size[0] << "\n" << r.err;
    const auto lines = readCsvLines((d / out / "study.csv").string());
    ASSERT_FALSE(lines.empty());
    for (const std::string& line : lines) {
      const auto f = splitCsvLine(line);
      for (const char* c : {"mse", "noise", "mse_target", "lowfreq_error", "blurred_mse"})
        EXPECT_TRUE(std::isfinite(std::stod(f[csvColumn(c)]))) << size[0] << " " << c << " = " << f[csvColumn(c)];
      EXPECT_EQ(f[csvColumn("nonfinite_samples")], "0");
    }
    EXPECT_TRUE(fs::exists(d / out / "spectra" / "sphere_triangle.csv"));
  }
}

TEST(IntegrityLimits, AnotherTargetListOrAnOlderCsvIsNotResumed) {
  const fs::path d = dirFor("targets");
  ASSERT_EQ(sweep(d, {"--scenes", kScene, "--size", "8", "8", "--target", "area", "--out", "o"}).exitCode, 0);
  const std::string csv = (d / "o" / "study.csv").string(), before = readText(csv);
  const ProcessResult r = sweep(d, {"--scenes", kScene, "--size", "8", "8", "--target", "area,gaussian:1.5", "--out", "o"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(r.err.rfind("sweep: --target: o/study.csv holds a study made with the targets box:0.5; this run asks for "
                        "box:0.5,gaussian:1.5",
                        0),
            0u)
      << r.err;
  EXPECT_EQ(readText(csv), before);
  // The same targets in another order are the same study: nothing to do.
  const ProcessResult same = sweep(d, {"--scenes", kScene, "--size", "8", "8", "--target", "box:0.5", "--out", "o"});
  EXPECT_EQ(same.exitCode, 0) << same.err;

  // A CSV of an older sweep (without the last six columns, natural_radius and the alignment's) is refused naming
  // the file and the missing columns.
  std::string old;
  {
    std::istringstream lines(before);
    for (std::string line; std::getline(lines, line);) {
      for (int k = 0; k < 6; ++k) line.erase(line.rfind(','));
      old += line + "\n";
    }
  }
  ASSERT_EQ(old.find("natural_radius"), std::string::npos);
  std::ofstream(csv, std::ios::binary) << old;
  const ProcessResult o = sweep(d, {"--scenes", kScene, "--size", "8", "8", "--target", "area", "--out", "o"});
  EXPECT_EQ(o.exitCode, 2) << o.err;
  EXPECT_NE(o.err.find("o/study.csv: written by an older sweep"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("natural_radius"), std::string::npos) << o.err;
  EXPECT_EQ(readText(csv), old);
}

TEST(IntegrityLimits, SpecialFilesInTheReferenceCacheAreRefusedWithoutBlocking) {
  const fs::path d = dirFor("cache");
  ASSERT_EQ(sweep(d, {"--scenes", kScene, "--size", "8", "8", "--target", "area", "--out", "o"}).exitCode, 0);
  fs::path exr;
  for (const auto& e : fs::directory_iterator(d / "cache"))
    if (e.path().extension() == ".exr" && e.path().string().find(".diff.") == std::string::npos) exr = e.path();
  ASSERT_FALSE(exr.empty());
  for (const char* kind : {"FIFO", "folder"}) {
    fs::remove_all(exr);
    if (std::string(kind) == "FIFO") ASSERT_EQ(::mkfifo(exr.c_str(), 0644), 0);
    else fs::create_directories(exr);
    const ProcessResult r =
        sweep(d, {"--scenes", kScene, "--size", "8", "8", "--target", "area", "--out", std::string("p") + kind});
    EXPECT_EQ(r.exitCode, 2) << kind << "\n" << r.err;
    EXPECT_NE(r.err.find(exr.filename().string() + ": is a " + (std::string(kind) == "FIFO" ? "FIFO" : "folder")),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("Success"), std::string::npos) << r.err;
  }
  fs::remove_all(exr);
}

TEST(IntegrityLimits, OverflowingLightIsRefusedByTheReferencesNotMeasuredAsBlack) {
  const fs::path d = dirFor("light");
  const std::string scene = ALIASLAB_SOURCE_DIR "/tests/badinput/scenes/light_colour_overflow.txt";
  const ProcessResult r = sweep(d, {"--scenes", scene, "--size", "8", "8", "--target", "area", "--out", "o"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("NaN or infinite samples"), std::string::npos) << r.err;
  // No row with mse 0 was written.
  EXPECT_TRUE(!fs::exists(d / "o" / "study.csv") || readCsvLines((d / "o" / "study.csv").string()).empty());
  // The reference program refuses the same way (before: black references, exit 0).
  const ProcessResult ref = runProcess({kBin + "/reference", "--scene", scene, "--size", "8", "8", "--spp", "16",
                                        "--filters", "box", "--radii", "1", "--out", "refs"},
                                       d.string(), (d / "logs").string());
  EXPECT_EQ(ref.exitCode, 2) << ref.err;
  EXPECT_NE(ref.err.find("reference: " + scene + ": the reference (box r=0.5) met"), std::string::npos) << ref.err;
  EXPECT_TRUE(!fs::exists(d / "refs") || fs::is_empty(d / "refs"));
}

TEST(IntegrityLimits, AnEmptySceneNameIsAnOptionError) {
  const fs::path d = dirFor("empty_scene");
  const ProcessResult r = sweep(d, {"--scenes", "", "--out", "o"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(r.err.rfind("sweep: --scenes: an empty name in the list", 0), 0u) << r.err;
}

TEST(IntegrityLimits, ACrOnlySceneFileIsReadLikeItsLfTwin) {
  const fs::path d = dirFor("cr");
  std::string text = readText(kScene);
  for (char& c : text)
    if (c == '\n') c = '\r';
  std::ofstream(d / "cr_scene.txt", std::ios::binary) << text;
  const ProcessResult r = sweep(d, {"--scenes", "cr_scene.txt", "--max-size", "8", "--target", "area", "--out", "o"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const ProcessResult lf = sweep(d, {"--scenes", kScene, "--max-size", "8", "--target", "area", "--out", "l"});
  ASSERT_EQ(lf.exitCode, 0) << lf.err;
  const auto a = splitCsvLine(readCsvLines((d / "o" / "study.csv").string()).at(0));
  const auto b = splitCsvLine(readCsvLines((d / "l" / "study.csv").string()).at(0));
  for (const char* c : {"width", "height", "mse", "mse_target", "noise"})
    EXPECT_EQ(a[csvColumn(c)], b[csvColumn(c)]) << c;  // the render line's size, the same picture
}

TEST(IntegrityLimits, MemoryIsEstimatedAgainstTheAddressSpaceLimit) {
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer reserves terabytes of shadow address space at start-up, so no program starts under an
  // address-space limit (ulimit -v) in the sanitizer build; the release suite runs this test.
  GTEST_SKIP() << "an address-space limit cannot be set under AddressSanitizer";
#endif
  const fs::path d = dirFor("memory");
  // 2 GB of address space; the estimates are far above it, physical memory is not the limit that applies.
  const std::string limit = "ulimit -v 2000000 && exec ";
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"sweep", kBin + "/sweep --scenes " + kScene + " --size 4096 4096 --spp 64 --seeds 2 --samplers random "
                                                     "--filters box --target area --out o --cache c --quiet"},
      {"reference", kBin + "/reference --scene " + kScene + " --size 8192 8192 --spp 64 --filters box --radii 1 --out r"},
      {"raytracer", kBin + "/raytracer -input " + kScene + " -size 4096 4096 --sampler random --spp 8 -output r.png"},
      // a PPM whose header says 30000 x 30000 and holds no pixels: imgdiff must refuse from the header alone
      {"imgdiff", kBin + "/imgdiff big.ppm big.ppm"}};
  {
    std::ofstream ppm(d / "big.ppm", std::ios::binary);
    ppm << "P6\n30000 30000\n255\n";
  }
  for (const auto& [program, command] : runs) {
    const ProcessResult r = runProcess({"/bin/sh", "-c", limit + command}, d.string(), (d / "logs").string());
    EXPECT_NE(r.exitCode, 0) << program;
    EXPECT_FALSE(r.signaled) << program;
    EXPECT_NE(r.err.find("more than this process may use"), std::string::npos) << program << ": " << r.err;
    EXPECT_NE(r.err.find("ulimit -v"), std::string::npos) << program << ": " << r.err;
    EXPECT_EQ(r.err.find("bad_alloc"), std::string::npos) << program << ": " << r.err;
  }
}
