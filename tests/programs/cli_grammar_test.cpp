// One command-line grammar across every executable of experiments/ (see
// experiments/common/cli.h): each program's --help is parsed and checked for CLI11
// artefacts, the naming rules (plural names take comma lists, singular ones
// one value; --out a folder, --output a file), shown defaults of numeric
// options, and --version; the comma lists are then used for real.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_process.h"

namespace fs = std::filesystem;

namespace {

struct ProgramRun {
  int code;
  std::string out, err;
};

const fs::path kTmp = fs::temp_directory_path() / "aliaslab_cli_grammar_test";

ProgramRun run(const std::string& program, const std::string& args) {
  fs::create_directories(kTmp);
  const fs::path out = kTmp / (program + ".out"), err = kTmp / (program + ".err");
  const auto r = aliaslab::testing::runShell(std::string(ALIASLAB_BIN_DIR) + "/" + program + " " + args,
                                             out.string(), err.string());
  return {r.exitCode, r.out, r.err};
}

/// Every executable: the folders of experiments/ holding a .cpp, but common/ (the shared front end), as
/// experiments/CMakeLists.txt's rule says.
std::vector<std::string> programs() {
  std::vector<std::string> names;
  for (const auto& d : fs::directory_iterator(fs::path(ALIASLAB_SOURCE_DIR) / "experiments")) {
    if (!d.is_directory() || d.path().filename() == "common") continue;
    for (const auto& f : fs::directory_iterator(d.path()))
      if (f.path().extension() == ".cpp") {
        names.push_back(d.path().filename().string());
        break;
      }
  }
  std::sort(names.begin(), names.end());
  return names;
}

struct HelpOption {
  std::vector<std::string> names;  ///< "--samplers", "-h", ...
  std::string opts, text;          ///< the placeholder part and the whole block (with the description)
};

/// The option blocks of a --help text: a line "  -x, --name PLACEHOLDER  description" and its continuation lines.
std::vector<HelpOption> parseHelp(const std::string& help) {
  std::vector<HelpOption> options;
  std::istringstream in(help);
  std::string line;
  const std::regex head(R"(^\s+(-[^ ,]+(, -[^ ,]+)*)(.*)$)");
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, head)) {
      HelpOption o;
      std::stringstream names(m[1].str());
      for (std::string n; std::getline(names, n, ',');) o.names.push_back(n.substr(n.find('-')));
      const std::string rest = m[3].str();
      const size_t gap = rest.find("  ");  // placeholder, then two or more spaces before the description
      o.opts = rest.substr(0, gap);
      o.text = line;
      options.push_back(o);
    } else if (!options.empty() && line.size() > 20 && line.find_first_not_of(' ') >= 20) {
      options.back().text += " " + line.substr(line.find_first_not_of(' '));
    }
  }
  return options;
}

TEST(CliGrammar, EveryExecutableIsChecked) {
  const auto names = programs();
  for (const char* p : {"raytracer", "sweep", "convergence", "pointsets", "filterprofile", "reference", "imgdiff", "inspect"})
    EXPECT_NE(std::find(names.begin(), names.end(), p), names.end()) << p;
}

class EachProgram : public testing::TestWithParam<std::string> {};

TEST_P(EachProgram, HelpFollowsTheGrammar) {
  const std::string p = GetParam();
  const ProgramRun r = run(p, "--help");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string& h = r.out;
  // CLI11 artefacts
  for (const char* bad : {R"(\{(true|false)\})", R"((INT|UINT|FLOAT|TEXT):)", R"( in \[)",
                          R"((INT|UINT|FLOAT|TEXT)=)", R"((INT|UINT|FLOAT|TEXT) x [0-9])"})
    EXPECT_FALSE(std::regex_search(h, std::regex(bad))) << p << " --help shows '" << bad << "':\n" << h;
  const auto options = parseHelp(h);
  ASSERT_GE(options.size(), 2u) << h;  // at least --help and --version
  bool version = false;
  for (const HelpOption& o : options) {
    for (const std::string& n : o.names) {
      version = version || n == "--version";
      // long names lower case with dashes; underscores only in the raytracer's classic course flags
      const std::regex good(p == "raytracer" ? "^(-h|--[a-z0-9][a-z0-9_-]*)$" : "^(-h|--[a-z0-9][a-z0-9-]*)$");
      EXPECT_TRUE(std::regex_match(n, good)) << p << ": option name " << n;
      const bool list = o.opts.find(",...") != std::string::npos;
      // no space-separated lists: one comma-separated value
      EXPECT_FALSE(std::regex_search(o.opts, std::regex(R"((INT|UINT|FLOAT|TEXT) \.\.\.)")))
          << p << " " << n << " takes a space-separated list: " << o.text;
      // one name per concept: singular names one value, plural names a comma list
      for (const char* one : {"--sampler", "--filter", "--scene"}) {
        if (n == one) {
          EXPECT_FALSE(list) << p << " " << n << " (singular) takes a list: " << o.text;
        }
        if (n == std::string(one) + "s") {
          EXPECT_TRUE(list) << p << " " << n << " (plural) takes one value: " << o.text;
        }
      }
      if (n == "--out") {
        EXPECT_NE(o.text.find("folder"), std::string::npos) << p << ": --out names a folder: " << o.text;
      }
      if (n == "--output") {
        EXPECT_NE(o.text.find("file"), std::string::npos) << p << ": --output names a file: " << o.text;
      }
      // numeric options show their default or range (the raytracer states its own in words)
      const bool numeric = o.opts.find("INT") != std::string::npos || o.opts.find("FLOAT") != std::string::npos;
      if (numeric && p != "raytracer" && o.text.find("REQUIRED") == std::string::npos) {
        EXPECT_NE(o.text.find("default"), std::string::npos) << p << " " << n << " shows no default: " << o.text;
      }
    }
  }
  EXPECT_TRUE(version) << p << " has no --version:\n" << h;
}

TEST_P(EachProgram, VersionPrintsRevisionAndBuildType) {
  const std::string p = GetParam();
  const ProgramRun r = run(p, "--version");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("^" + p + R"( \(aliaslab\) git [0-9a-f]{7,}(-dirty)?, \S+ build)")))
      << r.out;
}

INSTANTIATE_TEST_SUITE_P(Experiments, EachProgram, testing::ValuesIn(programs()),
                         [](const testing::TestParamInfo<std::string>& i) { return i.param; });

TEST(CliGrammar, CommaListsWorkInTheStudies) {
  const std::string out = (kTmp / "lists").string();
  ProgramRun r = run("pointsets", "--counts 16,64 --samplers random,sobol --sets 1 --no-chart --out " + out + "/ps");
  EXPECT_EQ(r.code, 0) << r.err;
  r = run("convergence", "--samplers random,sobol --max-n 16 --realisations 2 --no-chart --out " + out + "/cv");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(aliaslab::testing::readText(out + "/cv/convergence.csv").find("sobol"), std::string::npos);
}

}  // namespace
