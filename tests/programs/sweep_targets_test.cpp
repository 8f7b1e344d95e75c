// Several targets per study and the reference's own error (issue 29): one row per (configuration, target), the
// target-independent columns repeated, resume per configuration (done only when all its target rows are there),
// the flag rule, deterministic, mse_target_seeds; and the reference's error taken out of aliasing: a study run
// with 256-spp and again with 4096-spp references gives the same aliasing and mse_target within the combined
// standard errors for unbiased rows, while the uncorrected values (aliasing + ref_error) do not agree. Tiny sizes.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/error.h"
#include "study/config.h"
#include "study/records/csv.h"
#include "study/records/spectrum_key.h"
#include "study/presets.h"
#include "filter/filter.h"
#include "sampling/sampler.h"
#include "support/sweep_program.h"
#include "support/scratch_dir.h"

using namespace aliaslab;
namespace fs = std::filesystem;

namespace {
const std::string kScene = aliaslab::testing::kZonePlate;

const fs::path& workDir() { return aliaslab::testing::scratchDir("aliaslab_sweep_targets_test"); }

int run(const std::string& args, std::string* output = nullptr) {
  const auto r = aliaslab::testing::runSweep(args, workDir());
  if (output) *output = r.out;
  return r.exitCode;
}

size_t col(const std::string& name) { return csvColumn(name); }
double num(const std::vector<std::string>& f, const std::string& name) { return std::stod(f[col(name)]); }

// A configuration's identity without its target: the key of its spectra.
std::string configuration(const std::vector<std::string>& f) { return spectrumKeyOfCsvRow(f); }

// The CSV's rows (fields) with the timing columns blanked.
std::vector<std::vector<std::string>> rows(const std::string& path) {
  std::vector<std::vector<std::string>> out;
  for (const std::string& l : readCsvLines(path)) {
    auto f = splitCsvLine(l);
    for (size_t c : csvTimingColumns()) f[c] = "";
    out.push_back(f);
  }
  return out;
}

const std::string kTargets = "area,gaussian:1,lanczos:2";

std::string targetArgs(const fs::path& out) {
  return "--scenes " + kScene + " --size 16 16 --samplers uniform,jittered --spp 4 --filters box,tent --radii 0.5 "
         "--seeds 4 --ref-spp 256 --threads 2 --quiet --no-images --target " + kTargets +
         " --cache " + (workDir() / "cache").string() + " --out " + out.string();
}

const std::string& targetCsv() {
  static const std::string path = [] {
    const fs::path out = workDir() / "targets";
    std::string output;
    EXPECT_EQ(run(targetArgs(out), &output), 0) << output;
    return (out / "study.csv").string();
  }();
  return path;
}
}  // namespace

TEST(SweepTargets, OneRowPerConfigurationAndTargetWithTheTargetFreeColumnsRepeated) {
  const auto all = rows(targetCsv());
  ASSERT_EQ(all.size(), 2u * 2 * 3);  // 2 samplers x (box, tent) x 3 targets
  std::map<std::string, std::vector<std::vector<std::string>>> byConfig;
  for (const auto& f : all) byConfig[configuration(f)].push_back(f);
  ASSERT_EQ(byConfig.size(), 4u);
  for (const auto& [key, fs] : byConfig) {
    std::set<std::string> targets;
    for (const auto& f : fs) targets.insert(f[col("target")]);
    EXPECT_EQ(targets, (std::set<std::string>{"box:0.5", "gaussian:1", "lanczos:2"})) << key;
    for (const auto& f : fs)
      for (const char* c : {"mse", "aliasing", "noise", "mse_area", "psnr", "ref_error", "mse_se", "noise_se",
                            "aliasing_se", "deterministic", "blurred_mse_own", "lowfreq_error_own",
                            "lowfreq_error_own_se", "mean_spp", "max_spp"})
        EXPECT_EQ(f[col(c)], fs.front()[col(c)]) << key << " " << c;
    // The target-dependent columns differ between the targets.
    std::set<std::string> mseTargets;
    for (const auto& f : fs) mseTargets.insert(f[col("mse_target")]);
    EXPECT_EQ(mseTargets.size(), 3u) << key;
  }
}

TEST(SweepTargets, TheTermsOfEachTargetAndItsOwnColumns) {
  for (const auto& f : rows(targetCsv())) {
    const std::string row = configuration(f) + " target " + f[col("target")];
    // mse_area is the corrected mse against the area: the mse_target of the box:0.5 row.
    if (f[col("target")] == "box:0.5") {
      EXPECT_EQ(f[col("mse_target")], f[col("mse_area")]) << row;
      if (f[col("filter")] == "box") {
        EXPECT_EQ(num(f, "blur"), 0.0) << row;  // G is T
      }
    }
    // The four corrected terms add up to the corrected mse_target.
    const double sum = num(f, "noise") + num(f, "aliasing") + num(f, "blur") + num(f, "cross");
    EXPECT_NEAR(sum, num(f, "mse_target"), 1e-6 * num(f, "mse_target")) << row;
    EXPECT_GT(num(f, "target_ref_error"), 0.0) << row;
    // mse_target_seeds: K values whose mean is mse_target.
    std::vector<double> seeds;
    std::stringstream ss(f[col("mse_target_seeds")]);
    for (std::string x; std::getline(ss, x, ';');) seeds.push_back(std::stod(x));
    ASSERT_EQ(seeds.size(), 4u) << row;
    double mean = 0;
    for (double v : seeds) mean += v / seeds.size();
    EXPECT_NEAR(mean, num(f, "mse_target"), 1e-6 * std::abs(num(f, "mse_target"))) << row;
    // The flag rule: mse_target cannot be told from zero.
    EXPECT_EQ(f[col("flagged")], num(f, "mse_target") < 2 * num(f, "mse_target_se") ? "1" : "0") << row;
    // The fixed grid is the same for every seed: deterministic, no noise and equal per-seed values (its standard
    // errors are the references' part alone); jittered is not.
    if (f[col("sampler")] == "uniform") {
      EXPECT_EQ(f[col("deterministic")], "1") << row;
      EXPECT_EQ(num(f, "noise"), 0.0) << row;
      EXPECT_EQ(num(f, "noise_se"), 0.0) << row;
      for (size_t k = 1; k < seeds.size(); ++k) EXPECT_EQ(seeds[k], seeds[0]) << row;
    } else {
      EXPECT_EQ(f[col("deterministic")], "0") << row;
      EXPECT_GT(num(f, "noise_se"), 0.0) << row;
    }
    EXPECT_GT(num(f, "mse_target_se"), 0.0) << row;  // the references' error is in every standard error
  }
}

// The shifted grid: one offset of the whole image's grid per seed, so its error (structured for each seed) varies
// from seed to seed: not deterministic, a positive noise and standard error, per-seed values that differ. The fixed
// grid beside it stays deterministic.
TEST(SweepTargets, TheShiftedGridHasASpreadTheFixedGridHasNot) {
  const fs::path out = workDir() / "grids";
  std::string output;
  ASSERT_EQ(run("--scenes " + kScene + " --size 16 16 --samplers uniform,uniform-shifted --spp 4 --filters box "
                "--radii 0.5 --seeds 4 --ref-spp 256 --threads 2 --quiet --no-images --target area --cache " +
                    (workDir() / "cache").string() + " --out " + out.string(),
                &output),
            0)
      << output;
  const auto all = rows((out / "study.csv").string());
  ASSERT_EQ(all.size(), 2u);
  for (const auto& f : all) {
    std::set<std::string> perSeed;
    std::stringstream ss(f[col("mse_target_seeds")]);
    for (std::string x; std::getline(ss, x, ';');) perSeed.insert(x);
    if (f[col("sampler")] == "uniform-shifted") {
      EXPECT_EQ(f[col("deterministic")], "0");
      EXPECT_GT(num(f, "noise"), 0.0);
      EXPECT_GT(num(f, "mse_se"), 0.0);
      EXPECT_GT(num(f, "noise_se"), 0.0);
      EXPECT_EQ(perSeed.size(), 4u) << f[col("mse_target_seeds")];
    } else {
      EXPECT_EQ(f[col("deterministic")], "1");
      EXPECT_EQ(num(f, "noise"), 0.0);
      EXPECT_EQ(perSeed.size(), 1u) << f[col("mse_target_seeds")];
    }
  }
}

TEST(SweepTargets, AConfigurationIsDoneOnlyWhenAllItsTargetRowsArePresent) {
  const auto expected = rows(targetCsv());
  // Drop one target row of one configuration and every row of another: both are measured again, the
  // configurations whose rows are all there are skipped.
  const fs::path out = workDir() / "resume";
  fs::create_directories(out);
  const std::vector<std::string> lines = readCsvLines(targetCsv());
  std::vector<std::string> kept;
  for (const std::string& l : lines) {
    const auto f = splitCsvLine(l);
    const bool dropOne =
        f[col("sampler")] == "jittered" && f[col("filter")] == "box" && f[col("target")] == "lanczos:2";
    const bool dropAll = f[col("sampler")] == "uniform" && f[col("filter")] == "tent";
    if (!dropOne && !dropAll) kept.push_back(l);
  }
  ASSERT_EQ(kept.size(), lines.size() - 4);
  writeCsvFile((out / "study.csv").string(), kept);
  std::string output;
  ASSERT_EQ(run(targetArgs(out), &output), 0) << output;
  EXPECT_NE(output.find("4 rows written, 8 resumed"), std::string::npos) << output;
  EXPECT_EQ(rows((out / "study.csv").string()), expected);
  // A complete CSV: nothing to do.
  ASSERT_EQ(run(targetArgs(out), &output), 0) << output;
  EXPECT_NE(output.find("0 rows written, 12 resumed"), std::string::npos) << output;
}

// (the sweep refusing such lists on its command line: sweep_test.cpp AnUnusableTargetIsRefusedNamingTheOption)
TEST(SweepTargets, TargetListsAreParsedOnceAndDuplicatesRefused) {
  FilterCache filters;
  const auto t = parseTargets({"area", "gaussian:1.5", "lanczos:3"}, filters);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].label, "box:0.5");
  EXPECT_EQ(t[2].filter.spec, (FilterSpec{"lanczos", 3.0}));
  EXPECT_EQ(t[2].filter.filter->describe(), makeFilter("lanczos", 3.f)->describe());
  EXPECT_THROW(parseTargets({}, filters), OptionError);
  EXPECT_THROW(parseTargets({"area", "box:0.5"}, filters), OptionError);  // the same target twice
  EXPECT_THROW(parseTargets({"gaussian:1", "gaussian:1.0"}, filters), OptionError);
}

// The reference's own error is not aliasing: unbiased estimators (independent or stratified samples, box r = 0.5:
// a plain mean of the pixel's own samples) measured against 256-spp and against 4096-spp references.
TEST(SweepReferenceError, AliasingAgreesBetween256And4096SppReferencesWhileTheUncorrectedValueDoesNot) {
  auto study = [](int refSpp) {
    const fs::path out = workDir() / ("refs" + std::to_string(refSpp));
    std::string output;
    EXPECT_EQ(run("--scenes " + kScene + " --size 16 16 --samplers random,jittered,sobol --spp 64 --filters box "
                  "--radii 0.5 --seeds 8 --ref-spp " + std::to_string(refSpp) +
                      " --threads 2 --quiet --no-images --target area --cache " + (workDir() / "cache").string() +
                      " --out " + out.string(),
                  &output),
              0)
        << output;
    std::map<std::string, std::vector<std::string>> bySampler;
    for (const auto& f : rows((out / "study.csv").string())) bySampler[f[col("sampler")]] = f;
    return bySampler;
  };
  const auto coarse = study(256), fine = study(4096);
  ASSERT_EQ(coarse.size(), 3u);
  int uncorrectedApart = 0;
  for (const auto& [sampler, c] : coarse) {
    const auto& f = fine.at(sampler);
    EXPECT_GT(num(c, "ref_error"), 4 * num(f, "ref_error")) << sampler;  // the coarse reference is worse
    for (const auto& [value, se] : {std::pair{"aliasing", "aliasing_se"}, std::pair{"mse_target", "mse_target_se"}}) {
      const double combined = std::hypot(num(c, se), num(f, se));
      EXPECT_LT(std::abs(num(c, value) - num(f, value)), 3 * combined) << sampler << " " << value;
    }
    // What the study reported before the correction: aliasing + ref_error tracks the reference.
    const double before = num(c, "aliasing") + num(c, "ref_error"), after = num(f, "aliasing") + num(f, "ref_error");
    if (before - after > 3 * std::hypot(num(c, "aliasing_se"), num(f, "aliasing_se"))) ++uncorrectedApart;
  }
  EXPECT_EQ(uncorrectedApart, 3);  // at 64 spp the 256-spp reference's error is ~10 standard errors
}

// The bundled studies: references at least 64 x the highest spp, the three targets, every filter also at its natural
// radius, the fixed grid over 8 offsets; the presented study every bundled scene at 256 px with every sampler and
// filter and no per-configuration images; the quick one the same scenes at 48 px.
TEST(SweepPresets, ConvergedReferencesAndThreeTargets) {
  EXPECT_EQ(studyPresetNames(), (std::vector<std::string>{"default", "presented"}));
  for (const std::string& name : studyPresetNames()) {
    StudyConfig c;
    ASSERT_TRUE(applyStudyPreset(name, c)) << name;
    EXPECT_GE(c.refSpp, 64 * *std::max_element(c.spp.begin(), c.spp.end())) << name;
    EXPECT_EQ(c.targets, (std::vector<std::string>{"area", "gaussian:1.5", "lanczos:3"})) << name;
    FilterCache filters;
    EXPECT_NO_THROW(parseTargets(c.targets, filters)) << name;
    EXPECT_EQ(c.radii, (std::vector<double>{0.5, 1.0, 2.0})) << name;
    EXPECT_TRUE(c.naturalRadii) << name;
    EXPECT_EQ(c.alignOffsets, 8) << name;
    // the offset references: converged past the highest judged spp (4 x), and together (K x alignRefSpp) at most half
    // the main references' samples (docs/science.md "The grid and alignment": their cost)
    EXPECT_GE(c.alignRefSpp, 4 * *std::max_element(c.spp.begin(), c.spp.end())) << name;
    EXPECT_LE(c.alignOffsets * c.alignRefSpp, c.refSpp / 2) << name;
    EXPECT_EQ(c.spp, (std::vector<int>{4, 16, 64})) << name;
    EXPECT_EQ(c.seeds, 8) << name;
    EXPECT_EQ(c.refSpp, 4096) << name;
    // the folder of bundled scenes: ten of them, meshes, reflection and refraction among the analytic patterns
    const std::vector<std::string> scenes = expandScenePaths(c.scenes);
    EXPECT_EQ(scenes.size(), 10u) << name;
    for (const char* stem : {"zoneplate", "checker_horizon", "vase", "gem", "glass_sphere", "reflective_refractive"})
      EXPECT_TRUE(std::any_of(scenes.begin(), scenes.end(),
                              [&](const std::string& s) { return fs::path(s).stem() == stem; }))
          << name << " " << stem;
  }
  StudyConfig presented;
  applyStudyPreset("presented", presented);
  EXPECT_EQ(presented.longSide, 256);
  EXPECT_EQ(presented.samplers, samplerNames());
  EXPECT_EQ(presented.filters, filterNames());
  EXPECT_EQ(presented.images, std::optional<bool>(false));
  EXPECT_EQ(studyFilters(presented).size(), filterNames().size() * 3 + 3);  // + gaussian 1.5, lanczos 3, hann 3
  StudyConfig quick;
  applyStudyPreset("default", quick);
  EXPECT_EQ(quick.maxSize, 48);
  for (const std::string& f : quick.filters)
    EXPECT_NE(std::find(presented.filters.begin(), presented.filters.end(), f), presented.filters.end()) << f;
}
