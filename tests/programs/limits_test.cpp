// Issue 21 classes 2 and 3: numbers at the edge of float range and bounded
// work. The grid gives brute force's closest hit on scenes whose coordinates
// reach 1e19, 1e20 and 1e38 (it crashed); an image with NaN or infinite
// pixels is never written; "nan" is refused by every numeric option; nested
// materials stop at 256 levels naming file and line; the ray tree of one
// sample is capped; a size that cannot fit in memory fails before allocating.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "accel/aggregate.h"
#include "support/run_process.h"
#include "core/error.h"
#include "scene/scene.h"
#include "support/scratch_dir.h"

namespace fs = std::filesystem;
using namespace aliaslab;
using aliaslab::testing::runProcess;

namespace {

const std::string kBin = ALIASLAB_BIN_DIR;

fs::path dirFor(const std::string& name) {
  const fs::path d = aliaslab::testing::scratchDir("aliaslab_limits") / name;
  fs::create_directories(d / "logs");
  return d;
}

const char* kHead =
    "PerspectiveCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 angle 30 }\n"
    "Lights { numLights 1 DirectionalLight { direction -1 -1 -1 color 1 1 1 } }\n"
    "Materials { numMaterials 2 PhongMaterial { diffuseColor 1 0 0 } PhongMaterial { diffuseColor 0 1 0 } }\n";

// Closest hits of a fan of rays from the camera, grid against brute force (hit, t, primitive, material).
void expectGridEqualsBruteForce(const std::string& sceneText, const fs::path& dir) {
  std::ofstream(dir / "big.obj") << "v -1e38 -1e38 -5\nv 1e38 -1e38 -5\nv 0 1e38 -5\n"
                                    "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\nf 4 5 6\n";
  const Scene scene = parseSceneText(std::string(kHead) + sceneText, "big.txt", dir.string());
  const auto brute = makeBruteForce(*scene.root);
  for (int res : {0, 5}) {
    std::unique_ptr<Aggregate> grid;
    ASSERT_NO_THROW(grid = res ? makeGrid(*scene.root, res, res + 1, res + 2) : makeGrid(*scene.root));
    int hits = 0;
    for (int i = 0; i < 41; ++i)
      for (int j = 0; j < 41; ++j) {
        Ray ray;
        ray.origin = Vec3(0, 0, 10);
        ray.direction = Vec3(-0.3f + 0.015f * i, -0.3f + 0.015f * j, -1).normalized();
        Hit hb, hg;
        const bool fb = brute->intersect(ray, 1e-4f, hb), fg = grid->intersect(ray, 1e-4f, hg);
        ASSERT_EQ(fb, fg) << i << " " << j;
        EXPECT_EQ(hb.t, hg.t);
        EXPECT_EQ(hb.primitive, hg.primitive);
        EXPECT_EQ(hb.material, hg.material);
        hits += fb;
      }
    EXPECT_GT(hits, 40) << "the comparison is not vacuous";
  }
}

std::string mat(int m) { return "MaterialIndex " + std::to_string(m) + "\n"; }

}  // namespace

TEST(FloatRange, GridEqualsBruteForceWithASphereOfRadius1e19) {
  expectGridEqualsBruteForce("Group { numObjects 2 " + mat(0) + "Sphere { center 0 0 0 radius 1 }\n" + mat(1) +
                                 "Sphere { center 0 0 -2e19 radius 1e19 } }\n",
                             dirFor("r1e19"));
}

TEST(FloatRange, GridEqualsBruteForceWithACentreAt1e20) {
  expectGridEqualsBruteForce("Group { numObjects 2 " + mat(0) + "Sphere { center 0 0 0 radius 1 }\n" + mat(1) +
                                 "Sphere { center 1e20 0 0 radius 1 } }\n",
                             dirFor("c1e20"));
}

TEST(FloatRange, GridEqualsBruteForceWithObjVerticesAt1e38) {
  expectGridEqualsBruteForce("Group { numObjects 1 " + mat(0) + "TriangleMesh { obj_file big.obj } }\n",
                             dirFor("obj1e38"));
}

TEST(FloatRange, RaytracerRendersHugeScenesWithTheGridAsBruteForceDoes) {
  const fs::path d = dirFor("render");
  std::ofstream(d / "s.txt") << kHead << "Group { numObjects 2 " << mat(0) << "Sphere { center 0 0 0 radius 1 }\n"
                             << mat(1) << "Sphere { center 1e20 0 -1e19 radius 1e19 } }\n";
  const auto g = runProcess({kBin + "/raytracer", "-input", "s.txt", "-size", "24", "24", "-output", "g.png"},
                            d.string(), (d / "logs").string());
  ASSERT_FALSE(g.signaled) << "signal " << g.signal;
  ASSERT_EQ(g.exitCode, 0) << g.err;
  const auto b = runProcess(
      {kBin + "/raytracer", "-input", "s.txt", "-size", "24", "24", "-output", "b.png", "--brute-force"},
      d.string(), (d / "logs").string());
  ASSERT_EQ(b.exitCode, 0) << b.err;
  EXPECT_EQ(aliaslab::testing::readText((d / "g.png").string()), aliaslab::testing::readText((d / "b.png").string()));
}

TEST(FloatRange, NoImageWithNaNOrInfinitePixelsIsWritten) {
  const fs::path d = dirFor("overflow");
  std::ofstream(d / "s.txt")
      << "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 6 }\n"
         "Lights { numLights 1 DirectionalLight { direction 0 0 -1 color 3e38 3e38 3e38 } }\n"
         "Materials { numMaterials 1 PhongMaterial { diffuseColor 3e38 3e38 3e38 } }\n"
         "Group { numObjects 1 Sphere { center 0 0 0 radius 1 } }\n";
  const std::vector<std::vector<std::string>> outputs = {
      {"-output", "o.exr"}, {"-output", "o.png"}, {"-render_samples", "s.png", "2"}};
  for (const auto& out : outputs) {
    std::vector<std::string> argv{kBin + "/raytracer", "-input", "s.txt", "-size", "8", "8"};
    argv.insert(argv.end(), out.begin(), out.end());
    const auto r = runProcess(argv, d.string(), (d / "logs").string());
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("s.txt: 4 of 64 samples"), std::string::npos) << r.err;  // 1 spp: a sample a pixel
    EXPECT_NE(r.err.find("NaN or infinite"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(d / out[1])) << out[1];
  }
}

TEST(FloatRange, NanIsRefusedByEveryNumericOptionOfEveryProgram) {
  const fs::path d = dirFor("nan");
  struct Case {
    std::vector<std::string> argv;
    std::string option;
  };
  const std::string scene = ALIASLAB_SOURCE_DIR "/scenes/sphere_triangle.txt";
  const std::vector<Case> cases = {
      {{"filterprofile", "--max-frequency", "nan"}, "--max-frequency"},
      {{"pointsets", "--extent", "nan"}, "--extent"},
      {{"pointsets", "--extent", "inf"}, "--extent"},
      {{"convergence", "--fit-min", "nan"}, "--fit-min"},
      {{"sweep", "--scenes", scene, "--radii", "1,nan"}, "--radii"},
      {{"sweep", "--scenes", scene, "--radii", "-inf"}, "--radii"},
      {{"reference", "--scene", scene, "--radii", "nan"}, "--radii"},
      {{"raytracer", "-input", scene, "-size", "8", "8", "-output", "x.png", "-weight", "nan"}, "-weight"},
      {{"raytracer", "-input", scene, "-size", "8", "8", "-output", "x.png", "-gaussian_filter", "1e999"},
       "-gaussian_filter"},
  };
  for (Case c : cases) {
    const std::string program = c.argv[0];
    c.argv[0] = kBin + "/" + program;
    const auto r = runProcess(c.argv, d.string(), (d / "logs").string());
    EXPECT_EQ(r.exitCode, 2) << program << " " << c.option << "\n" << r.err;
    EXPECT_EQ(r.err.rfind(program + ": " + c.option + ": ", 0), 0u) << r.err;
  }
  EXPECT_FALSE(fs::exists(d / "x.png"));
}

namespace {
// Materials 0, 1 Phong; then each procedural material blends material i-1 with `second(i)`.
std::string materialChain(const std::string& kind, int count, bool doubling) {
  std::ostringstream s;
  s << "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 6 }\n"
    << "Materials { numMaterials " << count << "\nPhongMaterial { }\nPhongMaterial { }\n";  // lines 2-4
  for (int i = 2; i < count; ++i)  // material i on line i + 3
    s << kind << " { materialIndex " << i - 1 << " materialIndex " << (doubling ? i - 1 : 0)
      << (kind == "Noise" ? " octaves 1" : "") << " }\n";
  s << "}\nGroup { numObjects 1 MaterialIndex " << count - 1 << " Sphere { center 0 0 0 radius 1 } }\n";
  return s.str();
}
int parseLine(const std::string& text) {
  try {
    parseSceneText(text, "m.txt", ".");
  } catch (const ParseError& e) {
    return e.line();
  }
  return 0;
}
}  // namespace

TEST(BoundedWork, MaterialNestingStopsAt256LevelsNamingTheLine) {
  // 256 levels (Phong + 255 Checkerboards) parse; one more fails at the 257th level's line.
  EXPECT_EQ(parseLine(materialChain("Checkerboard", 257, false)), 0);
  EXPECT_EQ(parseLine(materialChain("Checkerboard", 258, false)), 257 + 3);
  // 50,000 levels (a stack overflow before) fail at the same line, at once.
  EXPECT_EQ(parseLine(materialChain("Checkerboard", 50000, false)), 257 + 3);
}

TEST(BoundedWork, MaterialsThatDoubleTheWorkPerLevelAreRefused) {
  // Blending material i-1 twice: material i costs 2^(i-1) Phong evaluations; 2^16 is the limit.
  EXPECT_EQ(parseLine(materialChain("Noise", 18, true)), 0);        // material 17: 2^16
  EXPECT_EQ(parseLine(materialChain("Noise", 30, true)), 18 + 3);   // material 18: 2^17
}

TEST(BoundedWork, ASizeThatCannotFitFailsBeforeAllocatingNamingTheMemory) {
  const fs::path d = dirFor("memory");
  const auto r = runProcess({kBin + "/sweep", "--scenes", ALIASLAB_SOURCE_DIR "/scenes/sphere_triangle.txt", "--size",
                             "16384", "16384", "--spp", "4096", "--out", "o", "--cache", "c", "--quiet"},
                            d.string(), (d / "logs").string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("sweep: --size: sphere_triangle at 16384 x 16384 and 4096 spp needs about"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("GB of memory"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(d / "o"));
}

TEST(BoundedWork, TheRayTreeOfOneSampleIsCappedAndSaysSo) {
  // Two touching glass spheres, reflective and transparent colour 1, -bounces 256 (the most): without a cap the work per
  // sample doubles every level (hours); with it the render ends, warns, and does not depend on the thread count.
  const fs::path d = dirFor("raytree");
  std::ofstream(d / "glass.txt")
      << "PerspectiveCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 angle 30 }\n"
         "Lights { numLights 1 DirectionalLight { direction -1 -1 -1 color 1 1 1 } }\n"
         "Materials { numMaterials 1 PhongMaterial { diffuseColor 0.1 0.1 0.1 reflectiveColor 1 1 1 "
         "transparentColor 1 1 1 indexOfRefraction 1.5 } }\n"
         "Group { numObjects 2 Sphere { center -1.05 0 0 radius 1 } Sphere { center 1.05 0 0 radius 1 } }\n";
  std::string images[2];
  for (int threads : {1, 2}) {
    const std::string out = "g" + std::to_string(threads) + ".png";  // (EXR headers carry a date)
    const auto r = runProcess({kBin + "/raytracer", "-input", "glass.txt", "-size", "24", "24", "-bounces", "256",
                               "-output", out, "--threads", std::to_string(threads)},
                              d.string(), (d / "logs").string());
    ASSERT_FALSE(r.signaled);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("reached the cap of 65536 reflected/refracted rays per sample"), std::string::npos) << r.err;
    images[threads - 1] = aliaslab::testing::readText((d / out).string());
  }
  EXPECT_FALSE(images[0].empty());
  EXPECT_EQ(images[0], images[1]);
}
