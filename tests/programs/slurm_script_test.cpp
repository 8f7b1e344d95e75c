// experiments/sweep/slurm_sweep.sh (and shard_args.sh, which parallel_sweep.sh shares) fail loudly and submit
// only what can run, against stand-in sbatch programs on PATH (no Slurm needed; nothing is run by them):
//   - sbatch missing, or refusing a job: non-zero exit, sbatch's own message, no "submitted:" line;
//   - a preset's own folder is the default output (presented -> results/presented, never results/study);
//   - TASKS outside 0..N-1 refused before anything is submitted; N and TASKS read as decimals ("08" is 8).
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
const std::string kScript = std::string(ALIASLAB_SOURCE_DIR) + "/experiments/sweep/slurm_sweep.sh";
const std::string kSweep = std::string(ALIASLAB_BIN_DIR) + "/sweep";
const fs::path& dir() { return aliaslab::testing::scratchDir("aliaslab_slurm_script_test"); }

std::string slurp(const fs::path& p) { return aliaslab::testing::readText(p.string()); }

// A folder for PATH holding the tools the script uses (links to the system's) and, unless `sbatch` is empty,
// an sbatch script with that body. It logs its arguments to <folder>/submitted.log.
fs::path fakePath(const std::string& name, const std::string& sbatch) {
  const fs::path bin = dir() / name;
  fs::create_directories(bin);
  for (const char* tool : {"bash", "dirname", "realpath", "mkdir", "seq", "cat", "tr", "rm", "touch"})
    for (const char* where : {"/usr/bin/", "/bin/"})
      if (fs::exists(std::string(where) + tool) && !fs::exists(bin / tool)) {
        fs::create_symlink(std::string(where) + tool, bin / tool);
        break;
      }
  if (!sbatch.empty()) {
    std::ofstream(bin / "sbatch") << "#!/bin/bash\necho \"$*\" >> \"$(dirname \"$0\")/submitted.log\"\n" << sbatch;
    fs::permissions(bin / "sbatch", fs::perms::owner_all);
  }
  return bin;
}

const std::string kAccepts = "echo $((1000 + RANDOM))\n";

struct Result {
  int code;
  std::string out, err;
};
// Runs the script in a fresh working folder `cwd` with PATH = bin only.
Result script(const fs::path& bin, const std::string& cwd, const std::string& args, const std::string& env = "") {
  const fs::path work = dir() / cwd;
  fs::create_directories(work);
  const fs::path o = dir() / "run.out", e = dir() / "run.err";
  const std::string cmd = "cd " + work.string() + " && env -i PATH=" + bin.string() + " SWEEP=" + kSweep + " " + env +
                          " /bin/bash " + kScript + " " + args + " > " + o.string() + " 2> " + e.string();
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(o), slurp(e)};
}

TEST(SlurmScript, MissingSbatchFailsLoudly) {
  const Result r = script(fakePath("none", ""), "none", "2 --preset default");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("sbatch not found"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("submitted"), std::string::npos) << r.out;
}

TEST(SlurmScript, ARefusedSubmissionFailsWithSbatchsMessage) {
  const fs::path bin = fakePath("refuses", "echo 'sbatch: error: Batch job submission failed: Invalid partition name "
                                           "specified' >&2\nexit 1\n");
  const Result r = script(bin, "refuses", "2 --preset default");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("Invalid partition name specified"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("sbatch refused the job (exit 1)"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("submitted"), std::string::npos) << r.out;
  // the first refusal stops the script: one submission tried
  EXPECT_EQ(slurp(bin / "submitted.log").find('\n'), slurp(bin / "submitted.log").size() - 1);
  // a second job refused (the array, after the references were accepted) stops it too
  const fs::path second = fakePath("refuses_second", "[[ $* == *--array* ]] && { echo 'sbatch: error: "
                                                      "QOSMaxSubmitJobPerUserLimit' >&2; exit 1; }\n" + kAccepts);
  const Result s = script(second, "refuses_second", "2 --preset default");
  EXPECT_EQ(s.code, 1);
  EXPECT_NE(s.err.find("QOSMaxSubmitJobPerUserLimit"), std::string::npos) << s.err;
  EXPECT_EQ(s.out.find("submitted"), std::string::npos) << s.out;
}

TEST(SlurmScript, APresetsOwnFolderIsTheDefaultOutput) {
  for (const std::string form : {"--preset presented", "--preset=presented"}) {
    const fs::path bin = fakePath("presented" + std::to_string(form.size()), kAccepts);
    const std::string cwd = "presented" + std::to_string(form.size());
    const Result r = script(bin, cwd, "2 " + form);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("-> results/presented/study.csv"), std::string::npos) << r.out;
    const std::string log = slurp(bin / "submitted.log");
    EXPECT_NE(log.find("--merge results/presented/study.csv"), std::string::npos) << log;
    EXPECT_EQ(log.find("results/study"), std::string::npos) << log;
    EXPECT_FALSE(fs::exists(dir() / cwd / "results" / "study"));
  }
  const Result d = script(fakePath("default", kAccepts), "default", "2 --preset default");
  EXPECT_NE(d.out.find("-> results/study/study.csv"), std::string::npos) << d.out;
  // --config may name a preset or a folder the script cannot see: --out is then required.
  const Result c = script(fakePath("config", kAccepts), "config", "2 --config my.toml");
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("give --out"), std::string::npos) << c.err;
}

TEST(SlurmScript, TasksOutsideTheShardsAreRefusedAndNumbersAreDecimal) {
  for (const std::string tasks : {"7", "0-4", "2,9", "3-1", "x"}) {
    const fs::path bin = fakePath("tasks_" + std::to_string(tasks.size()) + tasks.substr(0, 1), kAccepts);
    const Result r = script(bin, "tasks", "4 --preset default --out t", "TASKS=" + tasks);
    EXPECT_EQ(r.code, 2) << tasks << ": " << r.out;
    EXPECT_NE(r.err.find("TASKS='" + tasks + "'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("within 0..3"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(bin / "submitted.log")) << tasks << ": submitted anyway";
  }
  const fs::path ok = fakePath("tasks_ok", kAccepts);
  const Result r = script(ok, "tasks", "4 --preset default --out t", "TASKS=1,03");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(slurp(ok / "submitted.log").find("--array=1,03"), std::string::npos);
  // "08" is eight shards, not a bad octal number
  const fs::path eight = fakePath("eight", kAccepts);
  const Result e = script(eight, "eight", "08 --preset default --out e");
  EXPECT_EQ(e.code, 0) << e.err;
  EXPECT_EQ(e.err.find("value too great"), std::string::npos) << e.err;
  EXPECT_NE(slurp(eight / "submitted.log").find("--array=0-7"), std::string::npos);
  EXPECT_NE(slurp(eight / "submitted.log").find("study.shard-7-of-8.csv"), std::string::npos);
}

}  // namespace
