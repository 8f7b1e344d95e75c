// Issue 31: a scene file's lines may end in "\n", "\r\n" or a lone "\r" (old Mac files); all three parse to the
// same scene, and errors name the same lines. (Before, a CR-only file was one long comment: "missing camera".)
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "scene/scene.h"

using namespace aliaslab;

namespace {
// Line 1 a comment, line 2 the camera, lines 3-4 materials and one sphere.
const std::string kScene =
    "# render: -size 8 8\n"
    "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 4 }\n"
    "Materials { numMaterials 1 PhongMaterial { diffuseColor 1 0 0 } }\n"
    "Group { numObjects 1 Sphere { center 0 0 0 radius 1 } }\n";

std::string withBreaks(std::string text, const std::string& br) {
  std::string out;
  for (char c : text) out += c == '\n' ? br : std::string(1, c);
  return out;
}
}  // namespace

TEST(SceneLineEndings, LfCrLfAndLoneCrParseToTheSameScene) {
  for (const std::string br : {"\n", "\r\n", "\r"}) {
    const Scene s = parseSceneText(withBreaks(kScene, br), "scene.txt", "");
    ASSERT_TRUE(s.root) << "break " << int(br[0]);
    Hit hit;
    EXPECT_TRUE(s.root->intersect(Ray{Vec3(0, 0, 10), Vec3(0, 0, -1)}, 0.f, hit)) << "break " << int(br[0]);
    EXPECT_NEAR(hit.t, 9.f, 1e-5f);
  }
}

TEST(SceneLineEndings, ErrorsNameTheSameLineWithLoneCr) {
  const std::string bad = kScene + "Sphere { radius -1 }\n";  // line 5: outside the group
  for (const std::string br : {"\n", "\r"}) {
    try {
      parseSceneText(withBreaks(bad, br), "scene.txt", "");
      FAIL() << "parsed";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.line(), 5) << e.what();
    }
  }
}
