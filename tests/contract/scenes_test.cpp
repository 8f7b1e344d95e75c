// The scenes in scenes/: every file parses, carries one valid `# render:`
// line, finds its meshes and renders finite values; the analytic pattern
// scenes reproduce their formulas pixel for pixel, which checks the
// camera -> plane -> pattern chain end to end.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "accel/aggregate.h"
#include "render/tracer.h"
#include "scene/scene.h"

namespace aliaslab {
namespace {

namespace fs = std::filesystem;
const fs::path kScenes = fs::path(ALIASLAB_SOURCE_DIR) / "scenes";

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> tokens(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

/// The scene file's tokens with `#` comments removed.
std::vector<std::string> sceneTokens(const std::string& name) {
  std::ifstream in(kScenes / (name + ".txt"));
  std::string code;
  for (std::string line; std::getline(in, line);) code += line.substr(0, line.find('#')) + "\n";
  return tokens(code);
}

/// Stems of every scenes/*.txt, sorted (the parameter list of the suite).
std::vector<std::string> sceneNames() {
  std::vector<std::string> names;
  if (fs::is_directory(kScenes))
    for (const auto& e : fs::directory_iterator(kScenes))
      if (e.path().extension() == ".txt") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

fs::path scenePath(const std::string& name) { return kScenes / (name + ".txt"); }

/// The `# render:` lines of a scene file, read here independently of
/// the scene parser (Scene::render): each as its list of tokens after "# render:".
std::vector<std::vector<std::string>> renderLines(const fs::path& path) {
  std::vector<std::vector<std::string>> lines;
  std::ifstream in(path);
  for (std::string text; std::getline(in, text);)
    if (text.rfind("# render:", 0) == 0) lines.push_back(tokens(text.substr(9)));
  return lines;
}

TEST(SceneSet, TheTenNamedScenesExist) {
  for (const char* name : {"sphere_triangle", "checker_horizon", "vase", "reflective_refractive", "glass_sphere",
                           "gem", "zoneplate", "sinc", "siemens", "fence"})
    EXPECT_TRUE(fs::exists(scenePath(name))) << name;
  EXPECT_TRUE(fs::exists(kScenes / "README.md"));
  EXPECT_TRUE(fs::exists(kScenes / "generate_meshes.py"));
}

TEST(SceneSet, VaseMeshHasAtLeast3000Triangles) {
  // Faces counted from the OBJ text, and as the loader builds them.
  const fs::path obj = kScenes / "meshes" / "vase.obj";
  std::ifstream in(obj);
  int faces = 0;
  for (std::string line; std::getline(in, line);) faces += line.rfind("f ", 0) == 0;
  EXPECT_GE(faces, 3000);
  const auto group = loadObj(obj.string(), nullptr);
  EXPECT_EQ(static_cast<int>(group->children.size()), faces);
}

class SceneFile : public testing::TestWithParam<std::string> {};

TEST_P(SceneFile, ParsesWithCameraAndObjects) {
  Scene scene = parseScene(scenePath(GetParam()).string());
  ASSERT_TRUE(scene.camera);
  ASSERT_TRUE(scene.root);
  EXPECT_FALSE(scene.root->children.empty());
}

TEST_P(SceneFile, OpensWithCommentsAndHasOneRenderLineWithModestSize) {
  const fs::path path = scenePath(GetParam());
  const std::string text = readText(path);
  EXPECT_EQ(text.rfind("# ", 0), 0u) << "a scene opens with comment lines saying what it tests";
  const auto lines = renderLines(path);
  ASSERT_EQ(lines.size(), 1u) << "exactly one '# render:' line";
  const auto& t = lines[0];
  ASSERT_GE(t.size(), 3u);
  ASSERT_EQ(t[0], "-size");
  const int w = std::stoi(t[1]), h = std::stoi(t[2]);
  EXPECT_GE(w, 9);
  EXPECT_GE(h, 9);
  EXPECT_LE(w, 400);
  EXPECT_LE(h, 256);  // the presented study's size (the zone plate is made for it)
  // Only classic tracing flags, each with its count of values.
  const std::map<std::string, int> arity = {{"-shadows", 0}, {"-shade_back", 0}, {"-bounces", 1}, {"-weight", 1},
                                            {"-grid", 3}};
  for (size_t k = 3; k < t.size(); k += 1 + arity.at(t[k])) {
    ASSERT_TRUE(arity.count(t[k])) << "unexpected flag " << t[k];
    ASSERT_LT(k + arity.at(t[k]), t.size()) << t[k] << " needs " << arity.at(t[k]) << " values";
    for (int v = 1; v <= arity.at(t[k]); ++v) EXPECT_NO_THROW((void)std::stod(t[k + v])) << t[k];
  }
  // The scene parser reads the same line the same way.
  const RenderSettings r = parseScene(path.string()).render;
  EXPECT_TRUE(r.found);
  EXPECT_EQ(r.width, w);
  EXPECT_EQ(r.height, h);
}

TEST_P(SceneFile, EveryReferencedMeshExists) {
  const fs::path path = scenePath(GetParam());
  const auto t = sceneTokens(GetParam());
  for (size_t k = 0; k + 1 < t.size(); ++k) {
    if (t[k] == "obj_file") {
      EXPECT_TRUE(fs::exists(kScenes / t[k + 1])) << t[k + 1];
    }
  }
  for (const std::string& dep : parseScene(path.string()).dependencies) EXPECT_TRUE(fs::exists(dep)) << dep;
}

TEST_P(SceneFile, TinyRenderIsFiniteNonNegativeAndFramesGeometry) {
  const fs::path path = scenePath(GetParam());
  Scene scene = parseScene(path.string());
  const RenderSettings& line = scene.render;
  const int w = 24, h = std::max(1, static_cast<int>(std::lround(24.0 * line.height / line.width)));
  const auto aggregate = makeBruteForce(*scene.root);
  const Tracer tracer(scene, *aggregate, traceOptionsOf(line));
  int hits = 0;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const Color c = tracer.radianceAt(i + 0.5f, j + 0.5f, w, h);
      ASSERT_TRUE(c.allFinite()) << "pixel " << i << "," << j;
      ASSERT_GE(c.minCoeff(), 0.f) << "pixel " << i << "," << j;
      Hit hit;
      const Ray ray = scene.camera->generateRay(filmToScreen(i + 0.5f, j + 0.5f, w, h));
      hits += aggregate->intersect(ray, scene.camera->tMin(), hit);
    }
  EXPECT_GE(hits, w * h / 25) << "the camera should look at the scene, not past it";
}

INSTANTIATE_TEST_SUITE_P(All, SceneFile, testing::ValuesIn(sceneNames()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

// Analytic patterns ------------------------------------------------------------

/// Value after `key` (first occurrence) in the scene's tokens.
double numberAfter(const std::vector<std::string>& t, const std::string& key, int offset = 1) {
  const auto it = std::find(t.begin(), t.end(), key);
  EXPECT_NE(it, t.end()) << key;
  return it == t.end() ? NAN : std::stod(*(it + offset));
}

/// Renders the pattern scene at its default size, one sample at each pixel
/// centre, and compares every channel with `expected(x, y)` evaluated in
/// double at the pixel centre's world (= texture) coordinates, computed here
/// from the camera's centre and size as the format defines them. Pixels for
/// which `skip(x, y)` is true are not compared. Returns the pixels compared.
int comparePattern(const std::string& name, const std::function<double(double, double)>& expected, double tol,
                   const std::function<bool(double, double)>& skip = nullptr) {
  const fs::path path = scenePath(name);
  const auto t = sceneTokens(name);
  EXPECT_EQ(std::count(t.begin(), t.end(), "Transform"), 0) << "texture space must be world space";
  EXPECT_EQ(numberAfter(t, "direction", 3), -1.0);  // looking down -z at the plane z = 0
  const double cx = numberAfter(t, "center", 1), cy = numberAfter(t, "center", 2), size = numberAfter(t, "size");
  Scene scene = parseScene(path.string());
  const RenderSettings& line = scene.render;
  const int w = line.width, h = line.height, side = std::max(w, h);
  const auto aggregate = makeBruteForce(*scene.root);
  const Tracer tracer(scene, *aggregate, traceOptionsOf(line));
  int compared = 0;
  double worst = 0;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double x = cx + ((i + 0.5) - 0.5 * w) / side * size;
      const double y = cy + ((j + 0.5) - 0.5 * h) / side * size;
      if (skip && skip(x, y)) continue;
      const Color c = tracer.radianceAt(i + 0.5f, j + 0.5f, w, h);
      const double want = expected(x, y);
      for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(c[ch] - want));
      ++compared;
    }
  EXPECT_LE(worst, tol) << name;
  return compared;
}

TEST(PatternScenes, ZonePlatePixelsAreHalfPlusHalfSinOfKRSquared) {
  const double k = numberAfter(sceneTokens("zoneplate"), "frequency");
  const int n = comparePattern("zoneplate", [k](double x, double y) { return 0.5 + 0.5 * std::sin(k * (x * x + y * y)); },
                               1e-4);
  const RenderSettings line = parseScene(scenePath("zoneplate").string()).render;
  EXPECT_EQ(n, line.width * line.height);
}

TEST(PatternScenes, ZonePlatePassesNyquistInsideTheFrame) {
  // Local frequency k r / pi cycles per unit, times the pixel size, exceeds
  // 0.5 cycles/pixel at the frame corner (r = size / sqrt 2): it aliases.
  const auto t = sceneTokens("zoneplate");
  const double k = numberAfter(t, "frequency"), size = numberAfter(t, "size");
  const RenderSettings line = parseScene(scenePath("zoneplate").string()).render;
  const double pixel = size / std::max(line.width, line.height);
  const double cornerCyclesPerPixel = k * (size / std::sqrt(2.0)) / std::numbers::pi * pixel;
  const double edgeCyclesPerPixel = k * (size / 2) / std::numbers::pi * pixel;
  EXPECT_GT(cornerCyclesPerPixel, 0.5);
  EXPECT_GT(edgeCyclesPerPixel, 0.5);  // past Nyquist already at the edge midpoints
  // ... while a central disc of radius r = pi / (2 k pixel), at least a
  // third of the half-width, stays below it: both regimes are in view.
  EXPECT_GT(std::numbers::pi / (2 * k * pixel), size / 6);
}

TEST(PatternScenes, SincPixelsAreHalfPlusHalfSeparableSinc) {
  const double f = numberAfter(sceneTokens("sinc"), "frequency");
  const auto sinc = [](double t) { return t == 0 ? 1.0 : std::sin(std::numbers::pi * t) / (std::numbers::pi * t); };
  comparePattern("sinc", [&](double x, double y) { return 0.5 + 0.5 * sinc(f * x) * sinc(f * y); }, 1e-4);
}

TEST(PatternScenes, SiemensPixelsAreZeroOrOneBySpokeParity) {
  // Pixels within float rounding of a spoke edge (or the centre) are skipped.
  const double f = numberAfter(sceneTokens("siemens"), "frequency");
  const int n = comparePattern(
      "siemens", [f](double x, double y) { return std::sin(f * std::atan2(y, x)) >= 0 ? 1.0 : 0.0; }, 0.0,
      [f](double x, double y) { return std::abs(std::sin(f * std::atan2(y, x))) < 1e-4 || x * x + y * y < 1e-8; });
  EXPECT_GT(n, 128 * 128 * 9 / 10);
}

}  // namespace
}  // namespace aliaslab
