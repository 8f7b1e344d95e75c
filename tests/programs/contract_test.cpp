// The theory contract (study/records/contract.h; docs/science.md "What the samplers guarantee") and the negative
// control (scenes/controls/negative_spp*.txt): on a small real study every sampler bound holds within 3 standard
// errors; a deliberately broken sampler (the test's own: jittered whose strata share one jitter, i.e. a grid
// shifted by one random offset per pixel) violates its bound and the study reports it, as the sweep's warning
// (the sweep program resuming the study) and as the analysis's finding (findings/contract.py); on the negative
// control jittered's noise is random's, the per-pixel-shifted grid's spp times random's, and the fixed grid's
// error exactly 1/2 everywhere.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/hash.h"
#include "film/film.h"
#include "filter/filter.h"
#include "measure/metrics.h"
#include "render/render.h"
#include "study/config.h"
#include "study/records/contract.h"
#include "study/records/csv.h"
#include "study/study_scene.h"
#include "study/sweep/sweep.h"
#include "support/scratch_dir.h"

namespace aliaslab {
namespace {

namespace fs = std::filesystem;
const std::string kSrc = ALIASLAB_SOURCE_DIR;
const fs::path& workDir() { return testing::scratchDir("aliaslab_contract_test"); }

/// A k x k grid (spp = k^2) shifted by one random offset (u, v) per pixel: every point of a pixel shares the
/// jitter. Claiming jittered's bound it is the broken jittered of the test (its strata's jitter shared).
class PixelShiftedGrid final : public Sampler {
 public:
  PixelShiftedGrid(int spp, uint64_t seed, bool claimsJittered) : Sampler(spp, seed), claims_(claimsJittered) {
    k_ = static_cast<int>(std::lround(std::sqrt(spp)));
  }
  void generate(int px, int py, Vec2* out) const override {
    const uint64_t h = hashWords(pixelSeed(seed(), px, py), 0x7368696674ULL);
    const double u = (h >> 40) * 0x1p-24, v = ((h >> 8) & 0xffffff) * 0x1p-24;
    for (int r = 0; r < k_; ++r)
      for (int c = 0; c < k_; ++c) *out++ = Vec2(float((c + u) / k_), float((r + v) / k_));
  }
  std::string name() const override { return claims_ ? "jittered" : "grid shifted per pixel"; }
  std::string describe() const override { return name(); }
  double varianceBound() const override { return claims_ ? 1.0 : 0.0; }

 private:
  int k_ = 1;
  bool claims_;
};

const std::vector<std::string> kScenes = {kSrc + "/scenes/controls/edge.txt",
                                          kSrc + "/scenes/controls/negative_spp4.txt",
                                          kSrc + "/scenes/controls/negative_spp16.txt"};

StudyConfig smallStudy() {
  StudyConfig c;
  c.scenes = kScenes;
  c.samplers = {"random", "uniform", "jittered", "nrooks", "sobol"};
  c.spp = {4, 16};
  c.filters = {"box"};
  c.radii = {0.5};
  c.seeds = 8;
  c.refSpp = 1024;
  c.targets = {"area"};
  c.out = (workDir() / "study").string();
  c.cache = (workDir() / "cache").string();
  c.threads = 2;
  c.images = false;
  c.progress = false;
  return c;
}

/// The small study, swept once for every test of the program.
const SweepSummary& study() {
  static const SweepSummary s = runSweep(smallStudy());
  return s;
}

/// noise and noise_se of K seeds of `make(seed)` on a scene, box r = 0.5 (as the sweep measures them).
template <class Make>
Metrics measure(const std::string& scenePath, int seeds, Make make) {
  const auto scene = loadStudyScene(scenePath);
  const auto box = makeFilter("box", 0.5f);
  const Image zero(scene->width, scene->height, Color::Zero());
  MetricAccumulator acc(RefEstimate{&zero, nullptr, 0.5}, {});
  for (int k = 0; k < seeds; ++k) {
    const auto sampler = make(uint64_t(k));
    acc.add(reconstruct(traceSamples(*scene->tracer, *sampler, scene->width, scene->height, 2), *box,
                        ReconMode::WeightedAverage, 2).image);
  }
  return acc.result();
}

std::string stem(const std::string& path) { return fs::path(path).stem().string(); }

const ContractRow* findRow(const std::vector<ContractRow>& rows, const std::string& scene, const std::string& sampler,
                           int spp) {
  for (const ContractRow& r : rows)
    if (r.scene == scene && r.sampler == sampler && r.spp == spp) return &r;
  return nullptr;
}

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int shell(const std::string& command, std::string* output) {
  const fs::path log = workDir() / "shell.log";
  const int status = std::system((command + " > " + log.string() + " 2>&1").c_str());
  *output = readText(log);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The arithmetic: the ratio, its delta-method standard error and the 3-se rule, by hand.
TEST(Contract, RatioStandardErrorAndVerdict) {
  const std::vector<ContractRow> rows = {{"s", "random", 16, 2.0, 0.1},
                                         {"s", "jittered", 16, 2.5, 0.1},
                                         {"s", "nrooks", 16, 2.1, 0.1},
                                         {"s", "pmj02", 16, 9.0, 0.1},
                                         {"flat", "random", 16, 0.0, 0.0},
                                         {"flat", "jittered", 16, 1.0, 0.1}};
  const auto checks = checkContract(rows);
  ASSERT_EQ(checks.size(), 3u);  // nothing on the flat scene: random's noise is 0
  EXPECT_DOUBLE_EQ(checks[0].ratio, 1.25);
  EXPECT_NEAR(checks[0].se, 1.25 * std::sqrt(0.04 * 0.04 + 0.05 * 0.05), 1e-12);
  EXPECT_NEAR(checks[0].z(), 0.25 / checks[0].se, 1e-12);
  EXPECT_TRUE(checks[0].violated());  // z = 3.12
  EXPECT_DOUBLE_EQ(checks[1].bound, 16.0 / 15);
  EXPECT_FALSE(checks[1].violated());  // 1.05 against 1.0667
  EXPECT_EQ(checks[2].bound, 0);       // pmj02: no theorem, never a violation
  EXPECT_FALSE(checks[2].violated());
  EXPECT_EQ(contractViolations(checks).size(), 1u);
  EXPECT_NE(contractViolations(checks)[0].find("s, jittered at 16 spp"), std::string::npos);
}

TEST(Contract, TheBoundsTheSamplersClaim) {
  EXPECT_EQ(claimedBound("random", 16), 1);
  EXPECT_EQ(claimedBound("jittered", 16), 1);
  EXPECT_EQ(claimedBound("jittered", 8), 1);  // 2 x 4 equal strata
  EXPECT_DOUBLE_EQ(claimedBound("nrooks", 16), 16.0 / 15);
  EXPECT_EQ(claimedBound("sobol", 64), 2);
  EXPECT_EQ(claimedBound("sobol", 12), 0);  // not a net
  for (const char* s : {"uniform", "uniform-shifted", "pmj02", "halton", "cmj", "zsobol", "bluenoise"})
    EXPECT_EQ(claimedBound(s, 16), 0) << s;
  EXPECT_EQ(claimedBound("adaptive-contrast:jittered", 16), 0);
}

// Every bound holds within 3 se on a small real study (the edge control and the negative controls), as the sweep
// checked it at its end; and the check of the CSV as written gives the same.
TEST(ContractStudy, EveryBoundHoldsOnASmallRealStudy) {
  const SweepSummary& s = study();
  size_t bounded = 0;
  for (const ContractCheck& c : s.contract) {
    SCOPED_TRACE(c.scene + " " + c.sampler + " " + std::to_string(c.spp));
    EXPECT_FALSE(c.violated()) << c.ratio << " +- " << c.se << " bound " << c.bound;
    if (c.bound > 0) {
      ++bounded;
      EXPECT_GT(c.se, 0);  // judged, not skipped
    }
  }
  EXPECT_EQ(bounded, 3u * 2 * 3);  // jittered, nrooks, sobol x 2 spp x 3 scenes
  const auto again = checkContract(contractRows(csvPath(smallStudy())));
  ASSERT_EQ(again.size(), s.contract.size());
  for (size_t i = 0; i < again.size(); ++i) EXPECT_EQ(again[i].ratio, s.contract[i].ratio);
}

// The negative control at its own spp: jittered is random (ratio 1 within 3 se), the fixed grid samples every
// trough (mse against the pixel area exactly 1/4, no noise).
TEST(NegativeControl, JitteredIsRandomAndTheFixedGridMissesEveryCrest) {
  const auto rows = contractRows(csvPath(smallStudy()));
  for (int spp : {4, 16}) {
    const std::string scene = "negative_spp" + std::to_string(spp);
    SCOPED_TRACE(scene);
    const ContractRow *j = findRow(rows, scene, "jittered", spp), *r = findRow(rows, scene, "random", spp);
    ASSERT_TRUE(j && r);
    const double ratio = j->noise / r->noise;
    const double se = ratio * std::hypot(j->noiseSe / j->noise, r->noiseSe / r->noise);
    std::printf("%s: jittered / random = %.4f +- %.4f\n", scene.c_str(), ratio, se);
    EXPECT_LT(std::abs(ratio - 1), 3 * se);
    // random's noise is the variance of one uniform point's value over the pixel (1/8 per channel) over spp
    EXPECT_LT(std::abs(r->noise - 0.125 / spp), 3 * r->noiseSe);
  }
  // the fixed grid, straight from the renderer: every sample at a trough, every pixel 0 where it is worth 0.5
  for (int spp : {4, 16}) {
    const auto scene = loadStudyScene(kSrc + "/scenes/controls/negative_spp" + std::to_string(spp) + ".txt");
    const SampleBuffer b = traceSamples(*scene->tracer, *makeSampler("uniform", spp, 0), 64, 64, 2);
    const Image img = reconstruct(b, *makeFilter("box", 0.5f), ReconMode::WeightedAverage, 2).image;
    EXPECT_NEAR(meanSquaredDifference(img, Image(64, 64, Color::Constant(0.5f))), 0.25, 1e-6);
  }
  // and in the study's CSV: mse against the 1024-spp area reference 1/4 within its standard error (the
  // reference's own error, its variance subtracted, is what is left), noise exactly 0
  const auto lines = readCsvLines(csvPath(smallStudy()));
  int seen = 0;
  for (const std::string& line : lines) {
    const auto f = splitCsvLine(line);
    if (f[csvColumn("sampler")] != "uniform" || f[csvColumn("scene")].rfind("negative_spp", 0) != 0) continue;
    if (f[csvColumn("scene")] != "negative_spp" + f[csvColumn("spp")]) continue;
    ++seen;
    EXPECT_NEAR(std::stod(f[csvColumn("mse_target")]), 0.25, 3 * std::stod(f[csvColumn("mse_target_se")])) << line;
    EXPECT_EQ(std::stod(f[csvColumn("noise")]), 0) << line;
  }
  EXPECT_EQ(seen, 2);
}

// The grid shifted by one random offset per pixel: every sample of a pixel at the same phase, so its noise is
// spp times random's (the variance of one sample).
TEST(NegativeControl, ThePerPixelShiftedGridHasSppTimesRandomsNoise) {
  const auto rows = contractRows(csvPath(smallStudy()));
  for (int spp : {4, 16}) {
    const std::string path = kSrc + "/scenes/controls/negative_spp" + std::to_string(spp) + ".txt";
    const Metrics m = measure(path, 8, [&](uint64_t k) { return std::make_unique<PixelShiftedGrid>(spp, k, false); });
    const ContractRow* r = findRow(rows, stem(path), "random", spp);
    ASSERT_TRUE(r);
    const double expected = spp * r->noise, se = std::hypot(m.noiseSe, spp * r->noiseSe);
    std::printf("negative_spp%d: shifted grid noise %.5f +- %.5f, spp x random's %.5f +- %.5f\n", spp, m.noise,
                m.noiseSe, expected, spp * r->noiseSe);
    EXPECT_LT(std::abs(m.noise - expected), 3 * se);
  }
}

// A broken jittered (its strata share one jitter) measured on the study's scenes in place of jittered: the contract
// finds it (ratio spp on the negative controls), the sweep warns when it checks the CSV, the analysis's finding
// names it, and the analysis exits 1.
TEST(ContractStudy, ABrokenSamplerIsReported) {
  const StudyConfig c = smallStudy();
  study();
  std::vector<std::string> lines = readCsvLines(csvPath(c));
  std::map<std::pair<std::string, int>, Metrics> broken;
  for (const std::string& path : kScenes)
    for (int spp : c.spp)
      broken[{stem(path), spp}] =
          measure(path, c.seeds, [&](uint64_t k) { return std::make_unique<PixelShiftedGrid>(spp, k, true); });
  const size_t noise = csvColumn("noise"), noiseSe = csvColumn("noise_se");
  for (std::string& line : lines) {
    auto f = splitCsvLine(line);
    if (f[csvColumn("sampler")] != "jittered") continue;
    const Metrics& m = broken.at({f[csvColumn("scene")], std::stoi(f[csvColumn("spp")])});
    char a[64], b[64];
    std::snprintf(a, sizeof a, "%.9g", m.noise), std::snprintf(b, sizeof b, "%.9g", m.noiseSe);
    f[noise] = a, f[noiseSe] = b;
    line.clear();
    for (size_t i = 0; i < f.size(); ++i) line += (i ? "," : "") + f[i];
  }
  const fs::path csv = workDir() / "study" / "broken.csv";
  writeCsvFile(csv.string(), lines);

  const auto checks = checkContract(contractRows(csv.string()));
  std::set<std::string> flagged;
  for (const ContractCheck& k : checks)
    if (k.violated()) {
      EXPECT_EQ(k.sampler, "jittered");
      flagged.insert(k.scene + "@" + std::to_string(k.spp));
    }
  EXPECT_TRUE(flagged.count("negative_spp4@4") && flagged.count("negative_spp16@16"));

  // The sweep program resuming this CSV (every row there, nothing traced) checks it and warns.
  std::string out;
  std::string args;
  for (const std::string& s : kScenes) args += (args.empty() ? "" : ",") + s;
  ASSERT_EQ(shell(std::string(ALIASLAB_BIN_DIR) + "/sweep --scenes " + args +
                      " --samplers random,uniform,jittered,nrooks,sobol --spp 4,16 --filters box --radii 0.5 "
                      "--seeds 8 --ref-spp 1024 --target area --threads 2 --quiet --no-images --cache " + c.cache +
                      " --out " + c.out + " --csv " + csv.string(),
                  &out),
            0)
      << out;
  EXPECT_NE(out.find("warning: sampler bound violated"), std::string::npos) << out;
  EXPECT_NE(out.find("negative_spp16, jittered at 16 spp"), std::string::npos) << out;

  // The analysis: the same checks from the CSV, exit 1 and the violation named.
  const int rc = shell("cd " + kSrc + " && /usr/bin/python3 -m analysis.aliaslab_analysis.findings.contract " +
                           csv.string(), &out);
  EXPECT_EQ(rc, 1) << out;
  EXPECT_NE(out.find("negative_spp16,jittered,16"), std::string::npos) << out;
  EXPECT_NE(out.find("VIOLATED"), std::string::npos) << out;
  // and the study as measured passes the same analysis
  EXPECT_EQ(shell("cd " + kSrc + " && /usr/bin/python3 -m analysis.aliaslab_analysis.findings.contract " +
                      csvPath(c), &out), 0) << out;
}

}  // namespace
}  // namespace aliaslab
