// The library speaks its own terms (issue 28, item 4): no source under lib/
// names a command-line flag. Errors carry neutral keys ("radius", "ref-spp")
// and messages write other parameters as "{key}"; each front end maps keys to
// its flags (experiments/common/front_end.h). This test reads every lib/ source,
// takes its string literals (comments skipped) and fails on a literal that
// starts with "-" or "--" and a letter, or holds " --word" / " -word" inside.
// What looks like a flag but is not one is allowed below, each with a reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "aliaslab_paths.h"

namespace fs = std::filesystem;

namespace {

struct Literal {
  int line;
  std::string text;
};

// The string literals of C++ source `src` (ordinary and raw); comments, character literals and preprocessor
// lines (#include, #pragma GCC diagnostic "-W...": compiler flags, not ours) skipped.
std::vector<Literal> stringLiterals(const std::string& src) {
  std::vector<Literal> out;
  int line = 1;
  bool lineStart = true;
  for (size_t i = 0; i < src.size(); ++i) {
    const char c = src[i];
    if (lineStart && c == '#') {
      while (i < src.size() && src[i] != '\n') ++i;
      --i;
      continue;
    }
    lineStart = c == '\n' || (lineStart && (c == ' ' || c == '\t'));
    if (c == '\n') ++line;
    else if (c == '/' && i + 1 < src.size() && src[i + 1] == '/') {
      while (i < src.size() && src[i] != '\n') ++i;
      --i;
    } else if (c == '/' && i + 1 < src.size() && src[i + 1] == '*') {
      const size_t end = src.find("*/", i + 2);
      line += static_cast<int>(std::count(src.begin() + i, src.begin() + std::min(end, src.size()), '\n'));
      i = end == std::string::npos ? src.size() : end + 1;
    } else if (c == 'R' && i + 1 < src.size() && src[i + 1] == '"' &&
               (i == 0 || !(std::isalnum(static_cast<unsigned char>(src[i - 1])) || src[i - 1] == '_'))) {
      const size_t open = src.find('(', i + 2);
      const std::string close = ")" + src.substr(i + 2, open - i - 2) + "\"";
      const size_t end = src.find(close, open);
      out.push_back({line, src.substr(open + 1, end - open - 1)});
      line += static_cast<int>(std::count(src.begin() + i, src.begin() + end, '\n'));
      i = end + close.size() - 1;
    } else if (c == '"' || c == '\'') {
      std::string text;
      size_t j = i + 1;
      for (; j < src.size() && src[j] != c; ++j) {
        if (src[j] == '\\') text += src[j++];
        text += src[j];
      }
      if (c == '"') out.push_back({line, text});
      i = j;
    }
  }
  return out;
}

// A literal that reads as a command-line flag: "-grid", "--samplers", "... --out or ...", "(-size W H)".
bool namesFlag(const std::string& text) {
  static const std::regex flag(R"((^|[\s(/,'])--?[A-Za-z][A-Za-z_-])");
  return std::regex_search(text, flag);
}

struct Allowed {
  const char* file;     // path under lib/
  const char* literal;  // the literal's text exactly
  const char* reason;
};

// Not flags: each entry says what the text is.
const Allowed kNotFlags[] = {
    // The `# render:` line of a scene file is a file format whose keywords are the course's flags; it is parsed
    // in lib/scene (scene/render_settings.cpp) and its tracing flags written for manifests and hashes in
    // study/study_scene.cpp (no command line involved).
    {"study/study_scene.cpp", "-shadows ", "render-line keyword (scene file format)"},
    {"study/study_scene.cpp", " -weight ", "render-line keyword (scene file format)"},
    {"study/study_scene.cpp", "-bounces ", "render-line keyword (scene file format)"},
    {"study/study_scene.cpp", " -shade_back", "render-line keyword (scene file format)"},
    {"study/study_scene.cpp", "no '# render: -size W H' line and no {size} given", "a scene file's render line"},
    {"scene/render_settings.cpp", "-size", "render-line keyword (scene file format)"},
    {"scene/render_settings.cpp", "-shadows", "render-line keyword (scene file format)"},
    {"scene/render_settings.cpp", "-shade_back", "render-line keyword (scene file format)"},
    {"scene/render_settings.cpp", "-bounces", "render-line keyword (scene file format)"},
    {"scene/render_settings.cpp", "-weight", "render-line keyword (scene file format)"},
    {"scene/render_settings.cpp", "-grid", "render-line keyword (scene file format)"},
    {"scene/render_settings.cpp", "-size must be positive", "a scene file's render line"},
    {"scene/render_settings.cpp", "-bounces must be in 0..", "a scene file's render line"},
    {"scene/render_settings.cpp", "-grid resolutions must be >= 0 (0 = automatic)", "a scene file's render line"},
    {"scene/render_settings.cpp", "' (expected -size, -shadows, -bounces, -weight, -shade_back, -grid)",
     "a scene file's render line"},
    {"scene/render_settings.cpp", "missing -size W H", "a scene file's render line"},
    // File names of the contact images: <sampler>-spp<N>-<filter>-r<radius>-<mode>[-prefilter-<p>]-error.png.
    {"study/sweep/contact.cpp", "-spp", "part of an image file name"},
    {"study/sweep/contact.cpp", "-prefilter-", "part of an image file name"},
    {"study/sweep/contact.cpp", "-error.png", "part of an image file name"},
    {"study/sweep/contact.cpp", "-noise.png", "part of an image file name"},
    {"study/sweep/contact.cpp", "-density.png", "part of an image file name"},
    // The shard CSVs' file names: study.shard-<i>-of-<N>.csv.
    {"study/config.cpp", "-of-", "part of a shard CSV's file name"},
    {"study/records/merge.cpp", "-of-", "part of a shard CSV's file name"},
};


bool listed(const Allowed* begin, const Allowed* end, const std::string& file, const std::string& literal) {
  return std::any_of(begin, end, [&](const Allowed& a) { return file == a.file && literal == a.literal; });
}

struct Hit {
  std::string file;
  int line;
  std::string literal;
};

std::vector<Hit> flagLiterals() {
  const fs::path lib = fs::path(ALIASLAB_SOURCE_DIR) / "lib";
  std::vector<Hit> hits;
  for (const auto& e : fs::recursive_directory_iterator(lib)) {
    const std::string ext = e.path().extension().string();
    if (!e.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string file = e.path().lexically_relative(lib).generic_string();
    for (const Literal& l : stringLiterals(text.str()))
      if (namesFlag(l.text)) hits.push_back({file, l.line, l.text});
  }
  return hits;
}

}  // namespace

TEST(LibraryTerms, LexerFindsLiteralsNotComments) {
  const auto lits = stringLiterals("// \"--no\"\n  #pragma x \"-Wno\"\nf(\"--yes\", '\"', R\"x(raw \"--r\")x\"); /* \"--c\" */ g(\"a\\\"b\");");
  ASSERT_EQ(lits.size(), 3u);
  EXPECT_EQ(lits[0].text, "--yes");
  EXPECT_EQ(lits[0].line, 3);
  EXPECT_EQ(lits[1].text, "raw \"--r\"");
  EXPECT_EQ(lits[2].text, "a\\\"b");
  EXPECT_TRUE(namesFlag("--samplers"));
  EXPECT_TRUE(namesFlag("-grid"));
  EXPECT_TRUE(namesFlag("give another --out"));
  EXPECT_FALSE(namesFlag("give another {out}"));
  EXPECT_FALSE(namesFlag("-1.5"));
  EXPECT_FALSE(namesFlag("exp(-x^2 - y^2)"));
  EXPECT_FALSE(namesFlag("non-finite"));
}

TEST(LibraryTerms, NoLibrarySourceNamesACommandLineFlag) {
  const std::vector<Hit> hits = flagLiterals();
  ASSERT_FALSE(hits.empty() && !fs::is_directory(fs::path(ALIASLAB_SOURCE_DIR) / "lib")) << "lib/ not found";
  for (const Hit& h : hits) {
    if (listed(std::begin(kNotFlags), std::end(kNotFlags), h.file, h.literal)) continue;
    ADD_FAILURE() << "lib/" << h.file << ":" << h.line << " names a command-line flag: \"" << h.literal
                  << "\". Throw OptionError with the parameter's neutral key and map it to the flag in the front "
                     "end's FrontEnd (experiments/common/front_end.h); in a message, write the key in braces";
  }
}

TEST(LibraryTerms, EveryAllowedLiteralStillExists) {  // the lists shrink with the code
  const std::vector<Hit> hits = flagLiterals();
  auto present = [&](const Allowed& a) {
    return std::any_of(hits.begin(), hits.end(), [&](const Hit& h) { return h.file == a.file && h.literal == a.literal; });
  };
  for (const Allowed& a : kNotFlags) EXPECT_TRUE(present(a)) << "stale allow-list entry lib/" << a.file << ": " << a.literal;
}
