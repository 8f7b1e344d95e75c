// The sweep's guarantees: resume after truncation or kill -9, shards merged
// under GNU parallel equal one run, one trace per sample set whatever the
// number of filters, the theory's orderings on the zone plate, and bad input
// refused before any work, a merge refusing an incomplete set of shards, and
// reference manifests that point at the cached images. Tiny sizes (24x24,
// <= 16 spp, 256-spp references).
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <algorithm>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "support/sweep_program.h"
#include "support/scratch_dir.h"
#include "core/error.h"
#include "core/image.h"
#include "study/reference/reference.h"
#include "study/config.h"
#include "study/records/merge.h"
#include "study/validate.h"
#include "study/records/csv.h"
#include "study/records/spectrum_key.h"
#include "filter/filter.h"
#include "measure/metrics.h"
#include "study/sweep/sweep.h"

using namespace aliaslab;
namespace fs = std::filesystem;

namespace {
const std::string kBin = aliaslab::testing::kSweepBin;
const std::string kScene = aliaslab::testing::kZonePlate;

const fs::path& workDir() { return aliaslab::testing::scratchDir("aliaslab_sweep_test"); }

// The common tiny study (several targets: sweep_targets_test.cpp).
std::string tinyArgs(int threads = 2) { return aliaslab::testing::tinySweepArgs(workDir(), threads); }

int run(const std::string& args, std::string* output = nullptr) {
  const auto r = aliaslab::testing::runSweep(args, workDir());
  if (output) *output = r.out;
  return r.exitCode;
}

// The CSV's data lines with the timing columns blanked.
std::vector<std::string> withoutTiming(const std::string& path) {
  std::vector<std::string> out;
  for (const std::string& line : readCsvLines(path)) {
    auto f = splitCsvLine(line);
    for (size_t c : csvTimingColumns()) f[c] = "";
    std::string joined;
    for (const auto& x : f) joined += x + ",";
    out.push_back(joined);
  }
  return out;
}

// The rows (as withoutTiming joins them) with the threads column (1 per shard, 2 unsharded) blanked.
std::vector<std::string> withoutThreads(std::vector<std::string> rows) {
  const size_t threads =
      std::find(csvColumns().begin(), csvColumns().end(), "threads") - csvColumns().begin();
  for (auto& row : rows) {
    auto f = splitCsvLine(row);
    f[threads] = "";
    row.clear();
    for (const auto& x : f) row += x + ",";
  }
  return rows;
}

std::string slurp(const fs::path& p) { return aliaslab::testing::fileBytes(p); }

// One uninterrupted run, shared by the tests.
const std::string& fullCsv() {
  static const std::string path = [] {
    const std::string p = (workDir() / "full.csv").string();
    EXPECT_EQ(run(tinyArgs() + " --out " + (workDir() / "full").string() + " --csv " + p), 0);
    return p;
  }();
  return path;
}
}  // namespace

TEST(SweepResume, TruncatedInTheMiddleOfALineResumesToTheSameCsv) {
  const auto expected = withoutTiming(fullCsv());
  ASSERT_EQ(expected.size(), 12u);  // 4 groups x (box 0.5, box 1, tent 1)
  // Keep the header, 5 rows and half of the 6th, as a killed run would.
  const std::string p = (workDir() / "resumed.csv").string();
  std::ifstream in(fullCsv());
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t cut = 0;
  for (int line = 0; line < 6; ++line) cut = text.find('\n', cut) + 1;
  cut += (text.find('\n', cut) - cut) / 2;
  std::ofstream(p, std::ios::binary | std::ios::trunc) << text.substr(0, cut);
  std::string output;
  ASSERT_EQ(run(tinyArgs() + " --out " + (workDir() / "resumed").string() + " --csv " + p, &output), 0) << output;
  EXPECT_NE(output.find("5 resumed"), std::string::npos) << output;
  EXPECT_EQ(withoutTiming(p), expected);
}

TEST(SweepResume, KilledRunResumesToTheSameCsv) {
  const auto expected = withoutTiming(fullCsv());
  const std::string p = (workDir() / "killed.csv").string();
  const std::string args = tinyArgs() + " --out " + (workDir() / "killed").string() + " --csv " + p;
  std::system(("timeout -s KILL 0.3 " + kBin + " " + args + " > /dev/null 2>&1").c_str());
  ASSERT_EQ(run(args), 0);
  EXPECT_EQ(withoutTiming(p), expected);
}

TEST(SweepShards, ThreeShardsUnderGnuParallelMergeToTheUnshardedCsv) {
  const auto expected = withoutTiming(fullCsv());
  const fs::path dir = workDir() / "shards";
  const std::string cmd = "parallel --will-cite -j 3 " + kBin + " " + tinyArgs(1) + " --out " +
                          dir.string() + " --shard {}/3 --csv " + dir.string() + "/s{}.csv ::: 0 1 2 > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string merged = (dir / "merged.csv").string();
  ASSERT_EQ(run("--merge " + merged + " " + (dir / "s0.csv").string() + " " + (dir / "s1.csv").string() + " " +
                (dir / "s2.csv").string()),
            0);
  // Shards hold disjoint groups (4 groups over 3 shards: 2, 1, 1 of them).
  EXPECT_EQ(readCsvLines((dir / "s0.csv").string()).size(), 6u);
  EXPECT_EQ(readCsvLines((dir / "s2.csv").string()).size(), 3u);
  EXPECT_EQ(withoutThreads(withoutTiming(merged)), withoutThreads(expected));
}

// The shipped scripts: experiments/sweep/parallel_sweep.sh, and slurm_sweep.sh
// against a stand-in sbatch that runs each job's --wrap command at once
// (array tasks one after another, with SLURM_ARRAY_TASK_ID set).
TEST(SweepShards, TheGnuParallelScriptMergesToTheUnshardedCsv) {
  const fs::path dir = workDir() / "parallel_script";
  const std::string cmd = "SWEEP=" + kBin + " bash " + ALIASLAB_SOURCE_DIR + "/experiments/sweep/parallel_sweep.sh 3 " +
                          tinyArgs(1) + " --out " + dir.string() + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(withoutThreads(withoutTiming((dir / "study.csv").string())), withoutThreads(withoutTiming(fullCsv())));
  // The shards' spectra (spectra/<scene>.study.shard-i-of-3.csv) merge into spectra/<scene>.csv, equal to the
  // unsharded run's (spectra have no timing columns).
  const std::string stem = fs::path(kScene).stem().string();
  const std::string merged = slurp(dir / "spectra" / (stem + ".csv"));
  EXPECT_GT(std::count(merged.begin(), merged.end(), '\n'), 12);
  EXPECT_EQ(merged, slurp(workDir() / "spectra" / (stem + ".full.csv")));
}

TEST(SweepShards, TheSlurmScriptSubmitsReferencesShardsAndMerge) {
  const fs::path dir = workDir() / "slurm_script", bin = workDir() / "fake_slurm";
  fs::create_directories(bin);
  std::ofstream(bin / "sbatch") << R"(#!/bin/bash
wrap= array=
for a in "$@"; do
  case $a in --wrap=*) wrap=${a#--wrap=} ;; --array=*) array=${a#--array=} ;; esac
done
echo "$*" >> "$(dirname "$0")/submitted.log"
if [[ -n $array ]]; then
  for ((t = ${array%-*}; t <= ${array#*-}; ++t)); do
    SLURM_ARRAY_TASK_ID=$t SLURM_CPUS_PER_TASK=1 bash -c "$wrap" > /dev/null 2>&1 || exit 1
  done
else
  bash -c "$wrap" > /dev/null 2>&1 || exit 1
fi
echo $((1000 + RANDOM))
)";
  fs::permissions(bin / "sbatch", fs::perms::owner_all);
  const std::string cmd = "PATH=" + bin.string() + ":$PATH SWEEP=" + kBin + " bash " + ALIASLAB_SOURCE_DIR +
                          "/experiments/sweep/slurm_sweep.sh 3 " + tinyArgs(1) + " --out " + dir.string() +
                          " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::vector<std::string> jobs;  // one line per sbatch call
  std::ifstream log(bin / "submitted.log");
  for (std::string line; std::getline(log, line);) jobs.push_back(line);
  ASSERT_EQ(jobs.size(), 3u);
  EXPECT_NE(jobs[0].find("--refs-only"), std::string::npos) << jobs[0];
  // the references use the task's cores, not the shards' --threads 1
  EXPECT_NE(jobs[0].find("--threads ${SLURM_CPUS_PER_TASK:-0}"), std::string::npos) << jobs[0];
  EXPECT_EQ(jobs[0].find("--threads 1"), std::string::npos) << jobs[0];
  EXPECT_NE(jobs[1].find("--array=0-2"), std::string::npos) << jobs[1];
  EXPECT_NE(jobs[1].find("--dependency=afterok:"), std::string::npos) << jobs[1];
  EXPECT_NE(jobs[2].find("--merge"), std::string::npos) << jobs[2];
  EXPECT_NE(jobs[2].find("study.shard-2-of-3.csv"), std::string::npos) << jobs[2];
  EXPECT_EQ(withoutThreads(withoutTiming((dir / "study.csv").string())), withoutThreads(withoutTiming(fullCsv())));
}

TEST(SweepShards, MergeRefusesAnIncompleteSetOfShardFiles) {
  const fs::path dir = workDir() / "incomplete";
  fs::create_directories(dir);
  std::vector<std::string> shard;
  for (int i = 0; i < 3; ++i) {
    shard.push_back((dir / ("study.shard-" + std::to_string(i) + "-of-3.csv")).string());
    std::ofstream(shard.back()) << csvHeader() << "\n";
  }
  const std::string merged = (dir / "merged.csv").string();
  std::string output;
  EXPECT_EQ(run("--merge " + merged + " " + shard[0] + " " + shard[2], &output), 2);
  EXPECT_NE(output.find("--merge: shard 1 of 3 is missing"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(merged));
  // Every shard there but none with a row: rows were lost (a study has at least one configuration).
  EXPECT_EQ(run("--merge " + merged + " " + shard[2] + " " + shard[0] + " " + shard[1], &output), 2) << output;
  EXPECT_NE(output.find("holds no rows"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(merged));

  // In-process: every shard once, of one split; other names are not checked.
  EXPECT_NO_THROW(checkShardSet({"a/study.shard-1-of-2.csv", "b/study.shard-0-of-2.csv", "mine.csv"}));
  EXPECT_THROW(checkShardSet({"study.shard-0-of-2.csv", "study.shard-1-of-3.csv"}), OptionError);  // two splits
  EXPECT_THROW(checkShardSet({"study.shard-0-of-2.csv", "study.shard-1-of-2.csv", "x/study.shard-1-of-2.csv"}),
               OptionError);  // one given twice
  EXPECT_THROW(checkShardSet({"study.shard-0-of-1.csv", "study.shard-1-of-1.csv"}), OptionError);  // beyond N-1
}

TEST(SweepOutput, ReferenceManifestsPointAtTheCachedImages) {
  fullCsv();  // (writes full/references/zoneplate.json)
  const fs::path manifest = workDir() / "full" / "references" / "zoneplate.json";
  std::ifstream in(manifest);
  ASSERT_TRUE(in) << manifest;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  int images = 0;
  const std::string field = "\"image\": \"";
  for (size_t at = text.find(field); at != std::string::npos; at = text.find(field, at + 1)) {
    const size_t from = at + field.size();
    const std::string image = text.substr(from, text.find('"', from) - from);
    EXPECT_TRUE(fs::is_regular_file(manifest.parent_path() / image)) << image;
    ++images;
  }
  EXPECT_EQ(images, 3);  // box 0.5, box 1, tent 1
}

// The Python reader (analysis/aliaslab_analysis/charts/spectra.py) names a configuration's spectra by the same key
// as the library (study/records/spectrum_key.h): its KEY columns are spectrumKeyColumns(), and the configurations it
// reads from the uninterrupted run's spectra, written as the library writes keys, are the study CSV rows' keys.
TEST(SweepOutput, PythonReadsTheSpectrumKeyTheLibraryWrites) {
  const fs::path dir = workDir() / "python_key";
  fs::create_directories(dir / "spectra");
  const std::string stem = fs::path(kScene).stem().string();
  fs::copy_file(fullCsv(), dir / "study.csv", fs::copy_options::overwrite_existing);
  fs::copy_file(workDir() / "spectra" / (stem + ".full.csv"), dir / "spectra" / (stem + ".csv"),
                fs::copy_options::overwrite_existing);
  const std::string code =
      "import sys\n"
      "from analysis.aliaslab_analysis.charts import spectra\n"
      "print(','.join(spectra.KEY))\n"
      "s = spectra.load(sys.argv[1])\n"
      "for t in s[spectra.KEY].drop_duplicates().itertuples(index=False):\n"
      "    print(','.join('%.9g' % v if k == 'radius' else str(v) for k, v in zip(spectra.KEY, t)))\n";
  fs::create_directories(dir / "logs");
  const auto r = aliaslab::testing::runProcess({"/usr/bin/python3", "-c", code, (dir / "study.csv").string()},
                                               ALIASLAB_SOURCE_DIR, (dir / "logs").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::istringstream lines(r.out);
  std::string columns, line;
  std::getline(lines, columns);
  std::string expected;
  for (const std::string& c : spectrumKeyColumns()) expected += (expected.empty() ? "" : ",") + c;
  EXPECT_EQ(columns, expected);
  std::set<std::string> python, library;
  while (std::getline(lines, line)) python.insert(line);
  for (const std::string& l : readCsvLines(fullCsv())) library.insert(spectrumKeyOfCsvRow(splitCsvLine(l)));
  EXPECT_EQ(library.size(), 12u);  // 4 groups x (box 0.5, box 1, tent 1)
  EXPECT_EQ(python, library);
}

TEST(SweepReuse, TracerRunsOncePerSampleSetWhateverTheNumberOfFilters) {
  StudyConfig c;
  c.scenes = {kScene};
  c.width = c.height = 16;
  c.samplers = {"jittered"};
  c.spp = {4};
  c.seeds = 3;
  c.refSpp = 64;
  c.targets = {"area"};
  c.threads = 2;
  c.images = false;
  c.progress = false;
  c.cache = (workDir() / "cache").string();
  c.filters = {"box"};
  c.radii = {1.0};
  c.out = (workDir() / "reuse1").string();
  const SweepSummary one = runSweep(c);
  c.filters = {"box", "tent", "gaussian", "mitchell"};
  c.radii = {0.5, 1.0, 1.5, 2.0};
  c.reconstruction = {"weighted", "classic"};
  c.out = (workDir() / "reuse2").string();
  const SweepSummary many = runSweep(c);
  EXPECT_EQ(many.rowsWritten, 32u);
  EXPECT_EQ(one.sampleSetsTraced, 3u);   // one per seed
  EXPECT_EQ(many.sampleSetsTraced, 3u);  // still one per seed with 32 configurations
  EXPECT_EQ(one.primaryRays, 16u * 16 * 4 * 3);
  EXPECT_EQ(many.primaryRays, one.primaryRays);
}

TEST(SweepEndToEnd, ZonePlateUniformHasNoNoiseAndMoreAliasingThanJittered) {
  const auto lines = readCsvLines(fullCsv());
  std::ifstream in(fullCsv());
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, csvHeader());
  std::map<std::string, std::vector<std::string>> row;  // sampler -> fields at spp 16, box r=1
  for (const auto& l : lines) {
    auto f = splitCsvLine(l);
    ASSERT_EQ(f.size(), csvColumns().size());
    // every cell filled but the alignment columns (empty: this study has no alignment offsets)
    for (size_t i = 0; i < f.size(); ++i)
      EXPECT_EQ(f[i].empty(), csvColumns()[i].rfind("align_", 0) == 0) << csvColumns()[i] << " in " << l;
    // thread CPU time of the row's own work (4 seeds: a finite standard error)
    EXPECT_GT(std::stod(f[csvColumn("cpu_ms")]), 0.0) << l;
    EXPECT_GE(std::stod(f[csvColumn("cpu_ms_se")]), 0.0) << l;
    if (f[4] == "16" && f[5] == "box" && f[6] == "1") row[f[3]] = f;
  }
  ASSERT_EQ(row.size(), 2u);
  const double uniformNoise = std::stod(row["uniform"][12]), jitteredNoise = std::stod(row["jittered"][12]);
  const double uniformAliasing = std::stod(row["uniform"][11]), jitteredAliasing = std::stod(row["jittered"][11]);
  EXPECT_EQ(uniformNoise, 0.0);
  EXPECT_GT(jitteredNoise, 0.0);
  EXPECT_GT(uniformAliasing, jitteredAliasing);
  EXPECT_EQ(row["uniform"][0], "zoneplate");
  EXPECT_EQ(row["uniform"][1], "24");
  EXPECT_EQ(row["uniform"][9], "4");
  EXPECT_EQ(row["uniform"][15], "256");
}

TEST(SweepBadInput, RefusedBeforeAnyWorkWithTheMessageAndNoCsv) {
  const fs::path file = workDir() / "a_file";
  std::ofstream(file) << "x";
  const struct {
    std::string args, message;
  } cases[] = {
      {"--samplers nosuch", "nosuch"},
      {"--radii=-1", "--radii"},
      {"--spp 0", "--spp"},
      {"--scenes /nonexistent/scene.txt", "/nonexistent/scene.txt"},
      {"--out " + (file / "sub").string(), "--out"},
  };
  int i = 0;
  for (const auto& c : cases) {
    const fs::path out = workDir() / ("bad" + std::to_string(i++));
    std::string output;
    std::string args = "--scenes " + kScene + " --size 8 8 --seeds 2 --ref-spp 32 --quiet --out " + out.string() +
                       " --cache " + (workDir() / "badcache").string() + " " + c.args;
    EXPECT_NE(run(args, &output), 0) << c.args;
    EXPECT_NE(output.find(c.message), std::string::npos) << c.args << ": " << output;
    EXPECT_FALSE(fs::exists(out / "study.csv")) << c.args;
    EXPECT_FALSE(fs::exists(workDir() / "badcache")) << c.args;  // no reference work either
  }
}

// One target (docs/science.md, "One target, four terms"): the target column, the four terms adding up to
// mse_target on every row, blur = 0 and mse_target = mse for the target's own filter, and blur equal to the
// mean squared difference of the two cached references less the variance of their difference (mean (D_G - D_T)^2
// of their half-differences), computed here from the EXR files.
TEST(SweepTarget, TermsAddUpAndBlurIsTheDistanceBetweenTheCachedReferences) {
  const fs::path out = workDir() / "target";
  ASSERT_EQ(run("--scenes " + kScene + " --size 24 24 --samplers jittered --spp 4 --filters box,gaussian --radii 1 "
                "--seeds 4 --ref-spp 256 --threads 2 --quiet --no-images --target gaussian:1 --cache " +
                (workDir() / "cache").string() + " --out " + out.string()),
            0);
  const auto& cols = csvColumns();
  auto column = [&](const std::string& name) { return std::find(cols.begin(), cols.end(), name) - cols.begin(); };
  const auto cFilter = column("filter"), cRadius = column("radius"), cTarget = column("target"),
             cMse = column("mse"), cNoise = column("noise"), cAliasing = column("aliasing"),
             cMseTarget = column("mse_target"), cBlur = column("blur"), cCross = column("cross");
  // Reference images by (filter, radius) from the manifest.
  const fs::path manifest = out / "references" / "zoneplate.json";
  std::ifstream in(manifest);
  ASSERT_TRUE(in) << manifest;
  std::map<std::string, Image> refs, diffs;
  for (std::string line; std::getline(in, line);) {
    const size_t f = line.find("\"filter\": \""), r = line.find("\"radius\": "), im = line.find("\"image\": \"");
    if (f == std::string::npos || im == std::string::npos) continue;
    const std::string name = line.substr(f + 11, line.find('"', f + 11) - f - 11);
    const std::string radius = line.substr(r + 10, line.find(',', r) - r - 10);
    const std::string image = line.substr(im + 10, line.find('"', im + 10) - im - 10);
    refs[name + ":" + radius] = readImage((manifest.parent_path() / image).string());
    const std::string diff = image.substr(0, image.size() - 4) + ".diff.exr";  // <key>.exr beside <key>.diff.exr
    diffs[name + ":" + radius] = readImage((manifest.parent_path() / diff).string());
  }
  ASSERT_TRUE(refs.count("gaussian:1") && refs.count("box:1") && refs.count("box:0.5"));
  const auto lines = readCsvLines((out / "study.csv").string());
  ASSERT_EQ(lines.size(), 3u);  // box 0.5, box 1, gaussian 1
  for (const std::string& l : lines) {
    const auto f = splitCsvLine(l);
    SCOPED_TRACE(l);
    EXPECT_EQ(f[cTarget], "gaussian:1");
    const double mse = std::stod(f[cMse]), mseTarget = std::stod(f[cMseTarget]), blur = std::stod(f[cBlur]),
                 cross = std::stod(f[cCross]);
    const double sum = std::stod(f[cNoise]) + std::stod(f[cAliasing]) + blur + cross;
    EXPECT_NEAR(sum, mseTarget, 1e-7 * mseTarget);  // the CSV prints 9 significant digits
    const std::string key = f[cFilter] + ":" + f[cRadius];
    const double expected = meanSquaredDifference(refs.at(key), refs.at("gaussian:1")) -
                            meanSquaredDifference(diffs.at(key), diffs.at("gaussian:1"));
    EXPECT_NEAR(blur, expected, 1e-7 * std::abs(blur) + 1e-15);
    if (key == "gaussian:1") {
      EXPECT_EQ(blur, 0.0);
      EXPECT_EQ(cross, 0.0);
      EXPECT_NEAR(mseTarget, mse, 1e-8 * mse);
    } else {
      EXPECT_GT(blur, 0.0);
    }
  }
}

TEST(SweepTarget, DefaultTargetIsThePixelAreaWrittenBox05EqualToMseAreaWithStandardErrors) {
  const auto& cols = csvColumns();
  auto column = [&](const std::string& name) { return std::find(cols.begin(), cols.end(), name) - cols.begin(); };
  for (const std::string& l : readCsvLines(fullCsv())) {
    const auto f = splitCsvLine(l);
    EXPECT_EQ(f[column("target")], "box:0.5");
    EXPECT_EQ(f[column("mse_target")], f[column("mse_area")]) << l;
    // 4 seeds: every standard error defined; the uniform grid is the same for every seed (deterministic), so
    // its noise has none and its other standard errors are the references' part alone
    for (const char* se : {"mse_se", "noise_se", "aliasing_se", "mse_target_se"}) {
      const double v = std::stod(f[column(se)]);
      if (f[column("sampler")] == "uniform" && std::string(se) == "noise_se") EXPECT_EQ(v, 0.0) << se << " " << l;
      else EXPECT_GT(v, 0.0) << se << " " << l;
    }
    EXPECT_EQ(f[column("deterministic")], f[column("sampler")] == "uniform" ? "1" : "0") << l;
  }
}

TEST(SweepBadInput, AnUnusableTargetIsRefusedNamingTheOption) {
  for (const std::string target : {"nosuch:1", "gaussian", "box:-1", "box:x", ":1", "area,area", "area,nosuch:1",
                                   "area,box:0.5"}) {
    const fs::path out = workDir() / "badtarget";
    std::string output;
    EXPECT_EQ(run("--scenes " + kScene + " --size 8 8 --seeds 2 --ref-spp 32 --quiet --out " + out.string() +
                      " --cache " + (workDir() / "badtargetcache").string() + " --target " + target,
                  &output),
              2)
        << target;
    EXPECT_NE(output.find("--target"), std::string::npos) << target << ": " << output;
    EXPECT_FALSE(fs::exists(out / "study.csv")) << target;
    EXPECT_FALSE(fs::exists(workDir() / "badtargetcache")) << target;
  }
}

// Issue 16: manifests store scene paths relative to the repository, not the machine's absolute path.
TEST(ReferenceManifest, ScenePathIsRelativeToTheRepository) {
  using aliaslab::manifestScenePath;
  EXPECT_EQ(manifestScenePath(std::string(ALIASLAB_SOURCE_DIR) + "/scenes/zoneplate.txt"), "scenes/zoneplate.txt");
  EXPECT_EQ(manifestScenePath(std::string(ALIASLAB_SOURCE_DIR) + "/tests/../scenes/fence.txt"), "scenes/fence.txt");
  EXPECT_EQ(manifestScenePath("/elsewhere/mine.txt"), "/elsewhere/mine.txt");  // outside: as given
}

// Issue 28: objects built once. Every configuration of one (filter, radius) shares one Filter, made by
// expandStudy; the target is parsed once with its CSV label; validation returns the plan with each scene's size
// read from its render line.
TEST(StudyPlan, EachFilterIsBuiltOnceAndSharedByItsConfigurations) {
  StudyConfig c;
  c.scenes = {kScene};
  c.samplers = {"uniform", "jittered"};
  c.spp = {4, 16};
  c.filters = {"box", "gaussian"};
  c.radii = {1.0, 2.0};
  c.reconstruction = {"weighted", "classic", "supersample"};
  std::map<FilterSpec, std::set<const Filter*>> made;
  FilterCache filters;
  for (const SampleSetGroup& g : expandStudy(c, filters))
    for (const Configuration& cfg : g.configs) {
      ASSERT_TRUE(cfg.filter.filter);
      EXPECT_FLOAT_EQ(cfg.filter.filter->radius(), static_cast<float>(cfg.filter.spec.second));
      made[cfg.filter.spec].insert(cfg.filter.filter.get());
    }
  EXPECT_EQ(made.size(), 5u);  // box 0.5 (classic box), box 1, box 2, gaussian 1, gaussian 2
  for (const auto& [spec, filters] : made) EXPECT_EQ(filters.size(), 1u) << spec.first << " " << spec.second;
}

TEST(StudyPlan, TargetParsedOnceWithItsLabel) {
  FilterCache filters;
  const Target area = parseTarget("area", filters);
  EXPECT_EQ(area.filter.spec, (FilterSpec{"box", 0.5}));
  EXPECT_EQ(area.label, "box:0.5");
  const Target g = parseTarget("gaussian:1.5", filters);
  EXPECT_EQ(g.filter.spec, (FilterSpec{"gaussian", 1.5}));
  EXPECT_EQ(g.label, "gaussian:1.5");
  EXPECT_EQ(g.filter.filter, filters.get({"gaussian", 1.5}).filter);  // the cache's object, not a copy
}

// Issue 46: one FilterCache, owned by the plan, makes the rows', the targets' and the area's filters: a target that
// is also a row's (filter, radius), the area target, the plan's area and the supersample rows share one object.
TEST(StudyPlan, RowsTargetsAndTheAreaShareTheFilterObjects) {
  StudyConfig c;
  c.scenes = {kScene};
  c.samplers = {"uniform"};
  c.spp = {4};
  c.filters = {"box", "gaussian"};
  c.radii = {1.5};
  c.reconstruction = {"weighted", "supersample"};
  c.targets = {"area", "gaussian:1.5"};
  c.maxSize = 16;
  c.out = (workDir() / "shared").string();
  c.cache = (workDir() / "cache").string();
  const StudyPlan plan = validateStudy(c);
  ASSERT_EQ(plan.targets.size(), 2u);
  const Filter* area = plan.area.filter.get();
  EXPECT_EQ(plan.targets[0].filter.filter.get(), area);
  std::map<FilterSpec, std::set<const Filter*>> rows;
  for (const SampleSetGroup& g : plan.groups)
    for (const Configuration& cfg : g.configs) rows[cfg.filter.spec].insert(cfg.filter.filter.get());
  EXPECT_EQ(rows.at(kAreaSpec), std::set<const Filter*>{area});  // classic box and the supersample row
  EXPECT_EQ(rows.at(FilterSpec("gaussian", 1.5)), std::set<const Filter*>{plan.targets[1].filter.filter.get()});
}

// References take the filter objects: what they splat and describe is the object they are given, not one rebuilt
// from its (name, radius) (here a Gaussian with another sigma under the natural Gaussian's key).
TEST(StudyPlan, ReferencesSplatTheFilterObjectTheyAreGiven) {
  const auto scene = loadStudyScene(kScene, 8, 6);
  ReferenceOptions o;
  o.spp = 8, o.batchSpp = 4, o.threads = 1, o.progress = false;
  const StudyFilter wide{{"gaussian", 1.5}, makeFilter("gaussian", 1.5f, {{"sigma", 0.9}})};
  FilterCache filters;
  const StudyFilter natural = filters.get({"gaussian", 1.5});
  const ReferenceSet a = renderReferences(*scene, {wide}, o), b = renderReferences(*scene, {natural}, o);
  EXPECT_EQ(a.images[0].filter, b.images[0].filter);  // the same CSV key
  EXPECT_EQ(a.images[0].describe, wide.filter->describe());
  EXPECT_NE(a.images[0].key, b.images[0].key);
  double diff = 0;
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) diff += (a.images[0].image.get(x, y) - b.images[0].image.get(x, y)).cwiseAbs().sum();
  EXPECT_GT(diff, 0.0);
}

TEST(StudyPlan, ValidationReadsSceneSizesFromTheRenderLine) {
  StudyConfig c;
  c.scenes = {kScene};
  c.maxSize = 48;
  c.out = (workDir() / "plan").string();
  c.cache = (workDir() / "cache").string();
  const StudyPlan plan = validateStudy(c);
  const SceneSize s = plan.sceneSizes.at(kScene);
  const auto scene = loadStudyScene(kScene, 0, 0, 48);  // the full load (BVH, tracer) agrees
  EXPECT_EQ(s.width, scene->width);
  EXPECT_EQ(s.height, scene->height);
  EXPECT_EQ(s.width, 48);
  ASSERT_EQ(plan.targets.size(), 3u);  // the default targets: area, the natural Gaussian, the band-limited Lanczos
  EXPECT_EQ(plan.targets[0].label, "box:0.5");
  EXPECT_EQ(plan.targets[1].label, "gaussian:1.5");
  EXPECT_EQ(plan.targets[2].label, "lanczos:3");
  FilterCache filters;
  EXPECT_EQ(plan.groups.size(), expandStudy(c, filters).size());
}
