// The bad-input corpus (tests/badinput/cases.tsv): every malformed scene,
// OBJ file and command line makes the program exit non-zero (never by a
// signal) with a message naming the file and line or the option, and leaves
// no output file behind. Scene-file cases are also parsed in-process to
// check the exact exception class and line. Beside the corpus: every prefix
// of every bundled scene either parses or names the end of the prefix, and
// the nesting limit is exactly 256 levels.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "support/run_process.h"
#include "support/scratch_dir.h"
#include "core/error.h"
#include "core/image.h"
#include "scene/scene.h"

#include <sys/stat.h>
#include <cmath>

namespace fs = std::filesystem;
using namespace aliaslab;
using aliaslab::testing::runProcess;

namespace {

const std::string kDir = ALIASLAB_SOURCE_DIR "/tests/badinput";

struct Case {
  std::string name, program, errorClass;
  int exitCode = 0;
  std::string argv;
  std::vector<std::string> expect;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<std::string> split(const std::string& s, const std::string& sep) {
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t p; (p = s.find(sep, start)) != std::string::npos; start = p + sep.size())
    if (p > start) out.push_back(s.substr(start, p - start));
  if (start < s.size()) out.push_back(s.substr(start));
  return out;
}

std::vector<Case> loadCases() {
  std::vector<Case> cases;
  std::ifstream in(kDir + "/cases.tsv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto f = split(line, "\t");
    if (f.size() != 6) throw std::runtime_error("cases.tsv: 6 tab-separated fields expected: " + line);
    cases.push_back({f[0], f[1], f[2], std::stoi(f[3]), f[4], split(f[5], " | ")});
  }
  return cases;
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
  return s;
}

/// A scene with `levels` Groups (or Transforms) nested in the top-level Group, one per line from line 4.
std::string nestedScene(int levels, bool transforms) {
  std::ostringstream s;
  s << "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 6 }\n"
       "Materials { numMaterials 1 PhongMaterial { } }\nGroup { numObjects 1\n";
  for (int i = 0; i < levels; ++i) s << (transforms ? "Transform { Translate 0 0 0\n" : "Group { numObjects 1\n");
  s << "Sphere { center 0 0 0 radius 1 }\n";
  for (int i = 0; i <= levels; ++i) s << "}\n";
  return s.str();
}

/// A PNG of `path` (written 1 x 1) whose header then claims width x height: IHDR patched, its CRC recomputed.
void writePngClaiming(const fs::path& path, uint32_t width, uint32_t height) {
  aliaslab::writeImage(path.string(), aliaslab::Image(1, 1));
  std::string png = aliaslab::testing::readText(path.string());
  for (int k = 0; k < 4; ++k) png[16 + k] = char(width >> (24 - 8 * k)), png[20 + k] = char(height >> (24 - 8 * k));
  uint32_t crc = 0xFFFFFFFFu;  // CRC-32 of the chunk type and data (bytes 12..28), as PNG defines it
  for (size_t i = 12; i < 29; ++i) {
    crc ^= uint8_t(png[i]);
    for (int b = 0; b < 8; ++b) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  crc ^= 0xFFFFFFFFu;
  for (int k = 0; k < 4; ++k) png[29 + k] = char(crc >> (24 - 8 * k));
  std::ofstream(path, std::ios::binary) << png;
}

/// Scratch folders of this test run; @GEN@ holds the generated inputs.
const fs::path& scratch() {
  static const fs::path dir = [] {
    const fs::path d = aliaslab::testing::scratchDir("aliaslab_badinput");
    fs::create_directories(d / "gen");
    std::ofstream(d / "gen" / "deep_groups.txt") << nestedScene(100000, false);
    std::ofstream(d / "gen" / "deep_transforms.txt") << nestedScene(100000, true);
    // issue 31: images for imgdiff (one with a NaN pixel), FIFOs where regular files are expected
    aliaslab::Image a(4, 4), b(4, 4);
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) a.set(x, y, aliaslab::Color::Constant(0.25f * x)), b.set(x, y, aliaslab::Color::Constant(0.5f));
    aliaslab::writeImage((d / "gen" / "a.exr").string(), a);
    aliaslab::writeImage((d / "gen" / "b.exr").string(), b);
    a.set(1, 2, aliaslab::Color(NAN, 0.f, 0.f));
    aliaslab::writeImage((d / "gen" / "nan.exr").string(), a);
    writePngClaiming(d / "gen" / "huge_header.png", 100000, 100000);  // 1e10 pixels claimed, 1 stored
    for (const char* fifo : {"fifo.txt", "fifo.csv", "fifo.exr"}) ::mkfifo((d / "gen" / fifo).c_str(), 0644);
    std::ofstream(d / "gen" / "manifest.json") << nestedScene(0, false);  // a scene where reference writes its manifest
    return d;
  }();
  return dir;
}

std::vector<std::string> filesUnder(const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) files.push_back(e.path().filename().string());
  return files;
}

class BadInput : public ::testing::TestWithParam<Case> {};

TEST_P(BadInput, FailsCleanlyNamingWhereAndWritesNothing) {
  const Case& c = GetParam();
  const std::string bin = std::string(ALIASLAB_BIN_DIR) + "/" + c.program;
  if (!fs::exists(bin)) GTEST_SKIP() << bin << " is not built";
  const fs::path out = scratch() / c.name / "out", logs = scratch() / c.name / "logs";
  fs::create_directories(out);
  fs::create_directories(logs);

  // Run in the empty output folder.
  std::string args = replaceAll(c.argv, "@DIR@", kDir);
  args = replaceAll(args, "@SRC@", ALIASLAB_SOURCE_DIR);
  args = replaceAll(args, "@GEN@", (scratch() / "gen").string());
  args = replaceAll(args, "@OUT@", out.string());
  std::vector<std::string> argv{bin};
  for (const std::string& a : split(args, " ")) argv.push_back(a);
  const auto r = runProcess(argv, out.string(), logs.string());

  // Exit: non-zero, not a signal, the class's code; a message naming where.
  EXPECT_FALSE(r.signaled) << "killed by signal " << r.signal << "\n" << r.err;
  EXPECT_EQ(r.exitCode, c.exitCode) << r.err;
  EXPECT_NE(r.exitCode, 0);
  EXPECT_EQ(r.err.rfind(c.program + ": ", 0), 0u) << "message must start with the program name:\n" << r.err;
  for (const std::string& part : c.expect) EXPECT_NE(r.err.find(part), std::string::npos) << "missing '" << part << "' in:\n" << r.err;
  if (c.errorClass == "OptionError") {
    EXPECT_EQ(r.err.rfind(c.program + ": " + c.expect.at(0), 0), 0u) << "must open with the option:\n" << r.err;
  }
  for (const char* sanitizer : {"runtime error:", "AddressSanitizer", "LeakSanitizer"})
    EXPECT_EQ(r.err.find(sanitizer), std::string::npos) << r.err;

  // No output at all, not even a partial file.
  EXPECT_TRUE(filesUnder(out).empty()) << "left behind: " << ::testing::PrintToString(filesUnder(out));
  fs::remove_all(scratch() / c.name);
}

TEST_P(BadInput, SceneFileErrorsHaveTheExactClassAndLine) {
  const Case& c = GetParam();
  if (c.errorClass != "ParseError" && c.errorClass != "FileError") GTEST_SKIP() << "not a scene-file case";
  const auto argv = split(c.argv, " ");
  auto it = std::find(argv.begin(), argv.end(),
                      c.program == "sweep" ? "--scenes" : c.program == "reference" ? "--scene" : "-input");
  ASSERT_NE(it, argv.end());
  std::string input = replaceAll(*(it + 1), "@DIR@", kDir);
  input = replaceAll(input, "@SRC@", ALIASLAB_SOURCE_DIR);
  input = replaceAll(input, "@GEN@", (scratch() / "gen").string());
  try {
    parseScene(input);
    FAIL() << input << " parsed";
  } catch (const ParseError& e) {
    ASSERT_EQ(c.errorClass, "ParseError") << e.what();
    // "<name>.txt:<line>:" from the manifest gives the file and line.
    std::smatch m;
    const std::regex where(R"(([^/ ]+\.txt):(\d+):)");
    ASSERT_TRUE(std::regex_search(c.expect.at(0), m, where)) << c.expect.at(0);
    EXPECT_EQ(fs::path(e.file()).filename().string(), m[1].str());
    EXPECT_EQ(e.line(), std::stoi(m[2].str())) << e.what();
  } catch (const FileError& e) {
    EXPECT_EQ(c.errorClass, "FileError") << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, ::testing::ValuesIn(loadCases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

TEST(BadInputCorpus, HasAtLeastSixtyCasesWithUniqueNames) {
  const auto cases = loadCases();
  EXPECT_GE(cases.size(), 60u);
  std::set<std::string> names;
  for (const Case& c : cases) EXPECT_TRUE(names.insert(c.name).second) << c.name;
}

/// The line of the last token of `text` (comments skipped, but a `# render:` line is scene data, Scene::render),
/// counted independently of the parser.
int lastTokenLine(const std::string& text) {
  int line = 1, last = 1;
  bool comment = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '\n') ++line, comment = false;
    else if (ch == '#' && !comment && text.compare(i, 9, "# render:") == 0) comment = true, last = line;
    else if (ch == '#') comment = true;
    else if (!comment && !std::isspace(static_cast<unsigned char>(ch))) last = line;
  }
  return last;
}

TEST(BadInputTruncation, EveryPrefixOfEveryBundledSceneParsesOrNamesItsLastLine) {
  int cut = 0;
  for (const auto& e : fs::directory_iterator(ALIASLAB_SOURCE_DIR "/scenes")) {
    if (e.path().extension() != ".txt") continue;
    const std::string text = aliaslab::testing::readText(e.path().string());
    for (size_t n = 0; n < text.size(); ++n) {
      const std::string prefix = text.substr(0, n);
      // Unbalanced braces outside comments: the cut is inside a block.
      int depth = 0;
      bool comment = false;
      for (char ch : prefix) {
        if (ch == '\n') comment = false;
        else if (ch == '#') comment = true;
        else if (!comment) depth += (ch == '{') - (ch == '}');
      }
      try {
        parseSceneText(prefix, "cut.txt", e.path().parent_path().string());
        EXPECT_EQ(depth, 0) << e.path() << " cut at " << n << " parsed inside a block";
      } catch (const ParseError& err) {
        ++cut;
        EXPECT_EQ(err.file(), "cut.txt");
        EXPECT_GE(err.line(), 1);
        EXPECT_LE(err.line(), lastTokenLine(prefix)) << err.what();
        if (depth > 0) {
          EXPECT_NE(std::string(err.what()).find("unexpected end of file"), std::string::npos) << err.what();
          EXPECT_EQ(err.line(), lastTokenLine(prefix)) << err.what();
        }
      }
    }
  }
  EXPECT_GT(cut, 1000);
}

TEST(BadInputNesting, LimitIsExactly256LevelsForGroupsAndTransforms) {
  for (bool transforms : {false, true}) {
    // 255 nested levels inside the top-level Group put the sphere at depth 256.
    EXPECT_NO_THROW(parseSceneText(nestedScene(255, transforms), "deep.txt", ""));
    try {
      parseSceneText(nestedScene(256, transforms), "deep.txt", "");
      ADD_FAILURE() << "257 levels parsed";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.line(), 3 + 257) << e.what();  // the object at depth 257, on line 3 + 257
    }
  }
}

}  // namespace
