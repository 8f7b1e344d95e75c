// The `# render:` line read by the scene parser as scene data (scene/render_settings.h, Scene::render): every
// keyword lands in its field, the line may sit anywhere, a scene without one has found == false, and a bad line is
// a ParseError naming the file and the line.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "render/tracer.h"
#include "scene/scene.h"

using namespace aliaslab;

namespace {
const std::string kBody =
    "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 4 }\n"
    "Materials { numMaterials 1 PhongMaterial { diffuseColor 1 0 0 } }\n"
    "Group { numObjects 1 Sphere { center 0 0 0 radius 1 } }\n";

// The message of the ParseError that parsing `text` (as "dir/s.txt") throws, "" when it parses.
std::string errorOf(const std::string& text) {
  try {
    parseSceneText(text, "dir/s.txt", "");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(RenderLine, EveryKeywordLandsInItsField) {
  const Scene s = parseSceneText("# a comment\n# render: -size 40 30 -shadows -bounces 5 -weight 0.01 -shade_back "
                                 "-grid 4 5 6\n" + kBody, "s.txt", "");
  const RenderSettings& r = s.render;
  EXPECT_TRUE(r.found);
  EXPECT_EQ(r.line, 2);
  EXPECT_EQ(r.width, 40);
  EXPECT_EQ(r.height, 30);
  EXPECT_TRUE(r.shadows);
  EXPECT_EQ(r.bounces, 5);
  EXPECT_FLOAT_EQ(r.weight, 0.01f);
  EXPECT_TRUE(r.shadeBack);
  EXPECT_EQ(r.grid[0], 4);
  EXPECT_EQ(r.grid[1], 5);
  EXPECT_EQ(r.grid[2], 6);
  const TraceOptions o = traceOptionsOf(r);
  EXPECT_TRUE(o.shadows && o.shadeBack);
  EXPECT_EQ(o.bounces, 5);
  EXPECT_FLOAT_EQ(o.weight, 0.01f);
  ASSERT_TRUE(s.root);  // the rest of the scene parses as before
  EXPECT_EQ(s.root->children.size(), 1u);
}

TEST(RenderLine, DefaultsWithoutFlagsAndNotFoundWithoutALine) {
  const RenderSettings plain = parseSceneText(kBody + "# render: -size 9 7\n", "s.txt", "").render;
  EXPECT_TRUE(plain.found);
  EXPECT_EQ(plain.line, 4);
  EXPECT_EQ(plain.width * 100 + plain.height, 907);
  EXPECT_FALSE(plain.shadows || plain.shadeBack);
  EXPECT_EQ(plain.bounces, 0);
  EXPECT_EQ(plain.grid[0] + plain.grid[1] + plain.grid[2], 0);
  const RenderSettings none = parseSceneText("# just a comment\n" + kBody, "s.txt", "").render;
  EXPECT_FALSE(none.found);
  EXPECT_EQ(none.width, 0);
}

TEST(RenderLine, LineNumbersCountLoneCrAndCrLfBreaks) {
  for (const std::string br : {"\r", "\r\n"}) {
    const std::string text = "# one" + br + "# two" + br + "# render: -size 8 8" + br + kBody;
    const RenderSettings r = parseSceneText(text, "s.txt", "").render;
    EXPECT_EQ(r.line, 3) << int(br.size());
    EXPECT_EQ(r.width, 8);
  }
}

TEST(RenderLine, BadKeywordsAndValuesNameTheFileAndTheLine) {
  const std::string head = "# scene\n# render: ";
  EXPECT_EQ(errorOf(head + "-size 8 8 -shadow\n" + kBody),
            "dir/s.txt:2: render line: unknown flag '-shadow' (expected -size, -shadows, -bounces, -weight, "
            "-shade_back, -grid)");
  EXPECT_EQ(errorOf(head + "-size 8\n" + kBody), "dir/s.txt:2: render line: -size needs a value");
  EXPECT_EQ(errorOf(head + "-size 8 x\n" + kBody),
            "dir/s.txt:2: render line: expected a number after -size, found 'x'");
  EXPECT_EQ(errorOf(head + "-size 0 8\n" + kBody), "dir/s.txt:2: render line: -size must be positive");
  EXPECT_EQ(errorOf(head + "-size 8 8 -bounces 300\n" + kBody), "dir/s.txt:2: render line: -bounces must be in 0..256");
  EXPECT_EQ(errorOf(head + "-size 8 8 -grid 1 -1 1\n" + kBody),
            "dir/s.txt:2: render line: -grid resolutions must be >= 0 (0 = automatic)");
  EXPECT_EQ(errorOf(head + "-weight nan -size 8 8\n" + kBody),
            "dir/s.txt:2: render line: expected a number after -weight, found 'nan'");
  EXPECT_EQ(errorOf(head + "-shadows\n" + kBody), "dir/s.txt:2: render line: missing -size W H");
  EXPECT_EQ(errorOf("\n\n\n" + kBody + "#render: -size 8 8\n# render: -size 8 8 8\n"),
            "dir/s.txt:8: render line: unknown flag '8' (expected -size, -shadows, -bounces, -weight, -shade_back, "
            "-grid)");
  EXPECT_EQ(errorOf(head + "-size 8 8\n" + kBody), "");
}
