// The reference manifest's one writer and one reader (lib/study/reference/manifest.h): what is written reads back,
// the committed manifests are read and rewritten byte for byte (the layout is unchanged), the cache's fields and the
// inspect program's summary come from the same parse, and text that is not a manifest is refused naming its file.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "aliaslab_paths.h"
#include "core/error.h"
#include "core/files.h"
#include "core/format.h"
#include "study/filter_cache.h"
#include "study/reference/manifest.h"
#include "study/reference/manifest_summary.h"
#include "study/reference/reference.h"

namespace aliaslab {
namespace {

namespace fs = std::filesystem;

void expectSame(const ManifestFields& a, const ManifestFields& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].key, b[i].key);
    EXPECT_EQ(a[i].value, b[i].value) << a[i].key;
    EXPECT_EQ(a[i].quoted, b[i].quoted) << a[i].key;
  }
}

TEST(Manifest, AWrittenManifestReadsBack) {
  Manifest m;
  m.head = {{"scene", "a \"quoted\" name\\with a backslash"}, {"width", "48", false}, {"seed", "1592598566", false},
            {"film_offset", "[0.125, -0.25]", false}, {"seconds", "1.01957496", false}, {"empty", ""}};
  m.filters = {{{"filter", "box"}, {"radius", "0.5", false}, {"ref_error", "1.5e-07", false}, {"key", "0123abcd"}},
               {{"filter", "gaussian"}, {"radius", "1.5", false}, {"image", "x.exr"}}};
  const std::string text = writeManifest(m);
  const Manifest back = readManifest(text, "written.json");
  expectSame(back.head, m.head);
  ASSERT_EQ(back.filters.size(), 2u);
  for (size_t i = 0; i < 2; ++i) expectSame(back.filters[i], m.filters[i]);
  EXPECT_EQ(writeManifest(back), text);
  EXPECT_EQ(manifestValue(back.filters[1], "radius"), "1.5");
  EXPECT_EQ(manifestValue(back.filters[1], "ref_error"), "");  // absent
  // one line per field and per filter entry
  EXPECT_NE(text.find("\n  \"width\": 48,\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n    {\"filter\": \"gaussian\", \"radius\": 1.5, \"image\": \"x.exr\"}\n  ]\n}\n"),
            std::string::npos) << text;
}

// The committed study's manifests were written before the writer was one function: read and written again they
// are the same bytes, so the layout every manifest on disk has is the one the writer writes.
TEST(Manifest, CommittedManifestsReadAndRewriteByteForByte) {
  int seen = 0;
  for (const char* dir : {"results/study/references", "results/study/references/alignment"}) {
    const fs::path folder = fs::path(ALIASLAB_SOURCE_DIR) / dir;
    if (!fs::is_directory(folder)) continue;
    for (const auto& e : fs::directory_iterator(folder)) {
      if (e.path().extension() != ".json") continue;
      const std::string text = readFileBytes(e.path().string());
      const Manifest m = readManifest(text, e.path().string());
      EXPECT_FALSE(m.filters.empty()) << e.path();
      EXPECT_EQ(writeManifest(m), text) << e.path();
      ++seen;
    }
  }
  if (seen == 0) GTEST_SKIP() << "no committed manifests in this checkout";
}

TEST(Manifest, AReferenceSetsManifestCarriesItsValuesAndTheSummaryReadsThem) {
  const auto scene = loadStudyScene(std::string(ALIASLAB_SOURCE_DIR) + "/scenes/fence.txt", 8, 6);
  ReferenceOptions o;
  o.spp = 8, o.batchSpp = 4, o.threads = 1, o.progress = false;
  FilterCache filters;
  const ReferenceSet set = renderReferences(*scene, filters.get({{"box", 0.5}, {"gaussian", 0.1}}), o);
  const std::string text = referenceManifest(*scene, set, {"a.exr", "b.exr"}, {"h0", "h1"}, {"d0", "d1"});
  const Manifest m = readManifest(text, "set.json");
  EXPECT_EQ(manifestValue(m.head, "scene"), "fence");
  EXPECT_EQ(manifestValue(m.head, "width"), "8");
  EXPECT_EQ(manifestValue(m.head, "spp"), "8");
  ASSERT_EQ(m.filters.size(), 2u);
  EXPECT_EQ(manifestValue(m.filters[1], "filter"), "gaussian");
  EXPECT_EQ(manifestValue(m.filters[1], "radius"), "0.1");  // the spec's radius, not the float's 0.100000001
  EXPECT_EQ(std::stod(manifestValue(m.filters[1], "ref_error")), std::stod(formatReal(set.images[1].error)));
  EXPECT_EQ(manifestValue(m.filters[1], "key"), set.images[1].key);
  EXPECT_EQ(manifestValue(m.filters[1], "image_hash"), "h1");
  EXPECT_EQ(manifestValue(m.filters[1], "diff_hash"), "d1");
  const auto summary = manifestSummary(text, "b.exr", "set.json");  // the entry of one image
  int filterLines = 0;
  for (const auto& [k, v] : summary) filterLines += k == "filter";
  EXPECT_EQ(filterLines, 1);
  EXPECT_EQ(summary.front(), (std::pair<std::string, std::string>{"scene", "fence"}));
}

TEST(Manifest, TextThatIsNotAManifestIsRefusedNamingItsFile) {
  for (const std::string bad : {"", "{", "{\"scene\": \"x\"", "{\"scene\" \"x\"}", "[1, 2]", "{\"a\": 1} trailing",
                                "{\"filters\": [{\"filter\": }]}"}) {
    try {
      readManifest(bad, "cache/0123.json");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find("cache/0123.json"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace aliaslab
