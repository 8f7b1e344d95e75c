// The `raytracer` command: images checked against the scene's geometry
// (flat colours at pixel centres, depth and normals of a sphere), the
// classic visualisations, determinism over thread counts, and every error
// path (exit code, message, no output file).
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "core/image.h"
#include "support/run_process.h"

using namespace aliaslab;
namespace fs = std::filesystem;

namespace {

const std::string kData = std::string(ALIASLAB_TEST_DATA) + "/parser/";
const std::string kScene = kData + "sphere_triangle.txt";  // 16x16: see the file's comment
const std::string kLit = kData + "lit_scene.txt";

struct Result {
  int code;
  std::string out, err;
};

class RaytracerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& ch : name)
      if (ch == '/') ch = '_';
    dir_ = fs::temp_directory_path() / ("aliaslab_raytracer_" + name);
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  Result run(const std::string& args) const {
    const auto r = aliaslab::testing::runShell(std::string(ALIASLAB_BIN_DIR) + "/raytracer " + args,
                                               path("stdout.txt"), path("stderr.txt"));
    return {r.exitCode, r.out, r.err};
  }

  fs::path dir_;
};

void expectColor(const Image& im, int x, int y, const Color& c, float tol) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(im.get(x, y)[k], c[k], tol) << "pixel " << x << "," << y << " channel " << k;
}

bool identical(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) return false;
  return std::equal(a.data(), a.data() + 3 * a.width() * a.height(), b.data());
}

constexpr float k8bit = 1.f / 255.f;

}  // namespace

TEST_F(RaytracerTest, FlatColoursAtPixelCentresInPngAndExr) {
  const Result r = run("-input " + kScene + " -size 16 16 -stats -output " + path("a.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("primary 256,"), std::string::npos) << r.out;  // one ray per pixel
  EXPECT_NE(r.out.find("shadow 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("accelerator: bvh"), std::string::npos) << r.out;
  ASSERT_EQ(run("-input " + kScene + " -size 16 16 --threads 1 -output " + path("a.exr")).code, 0);
  const Image png = readImage(path("a.png")), exr = readImage(path("a.exr"));
  ASSERT_EQ(png.width(), 16);
  ASSERT_EQ(png.height(), 16);
  // Pixel (8,8) centre is world (0.125, 0.125): the red sphere; (14,2) is
  // (1.625, -1.375), inside the green triangle; (0,0) misses everything.
  expectColor(exr, 8, 8, Color(1, 0, 0), 0.f);
  expectColor(exr, 14, 2, Color(0, 1, 0), 0.f);
  expectColor(exr, 0, 0, Color(0.2f, 0.4f, 0.6f), 0.f);
  expectColor(exr, 14, 13, Color(0.2f, 0.4f, 0.6f), 0.f);  // (1.625, 1.375): above the triangle
  expectColor(png, 8, 8, Color(1, 0, 0), k8bit);
  expectColor(png, 0, 0, Color(0.2f, 0.4f, 0.6f), k8bit);
}

TEST_F(RaytracerTest, DepthAndNormalsOfTheSphere) {
  const Result r =
      run("-input " + kScene + " -size 16 16 -depth 9 11 " + path("d.exr") + " -normals " + path("n.exr"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(path("a.png")));
  const Image d = readImage(path("d.exr")), n = readImage(path("n.exr"));
  // Ray at (x, y) = (0.125, 0.125) meets the unit sphere at z = sqrt(1 - 2 x^2), t = 10 - z.
  const float z = std::sqrt(1.f - 2.f * 0.125f * 0.125f), t = 10.f - z;
  expectColor(d, 8, 8, Color::Constant((11.f - t) / 2.f), 1e-4f);
  expectColor(n, 8, 8, Color(0.125f, 0.125f, z), 1e-4f);
  expectColor(d, 0, 0, Color::Zero(), 0.f);
  expectColor(n, 0, 0, Color::Zero(), 0.f);
}

TEST_F(RaytracerTest, ThreadCountAndAcceleratorDoNotChangeTheImage) {
  const std::string base = "-input " + kLit + " -size 40 24 -shadows -bounces 3 -shade_back ";
  ASSERT_EQ(run(base + "--threads 1 -output " + path("t1.exr")).code, 0);
  ASSERT_EQ(run(base + "--threads 2 -output " + path("t2.exr")).code, 0);
  ASSERT_EQ(run(base + "--threads 2 --brute-force -output " + path("bf.exr")).code, 0);
  ASSERT_EQ(run(base + "--threads 2 -grid 3 2 5 -output " + path("g.exr")).code, 0);
  const Image t1 = readImage(path("t1.exr"));
  std::set<float> reds;  // a real picture, not a blank
  for (int j = 0; j < t1.height(); ++j)
    for (int i = 0; i < t1.width(); ++i) reds.insert(t1.get(i, j)[0]);
  EXPECT_GT(reds.size(), 50u);
  EXPECT_TRUE(identical(t1, readImage(path("t2.exr"))));
  EXPECT_TRUE(identical(t1, readImage(path("bf.exr"))));
  EXPECT_TRUE(identical(t1, readImage(path("g.exr"))));
  // Sampled and filtered (classic flags) as well.
  const std::string sampled = base + "-jittered_samples 4 -tent_filter 1.2 ";
  ASSERT_EQ(run(sampled + "--threads 1 -output " + path("s1.exr")).code, 0);
  ASSERT_EQ(run(sampled + "--threads 2 -output " + path("s2.exr")).code, 0);
  EXPECT_TRUE(identical(readImage(path("s1.exr")), readImage(path("s2.exr"))));
}

TEST_F(RaytracerTest, RenderFilterTentPictureHasWeightsAtCellCorners) {
  // Phase 2 acceptance: 9x9 film, zoom 20, tent of radius 1.7 (classic support 2).
  const Result r = run("-input " + kScene + " -size 9 9 -render_filter " + path("f.png") + " 20 -tent_filter 1.7");
  ASSERT_EQ(r.code, 0) << r.err;
  const Image f = readImage(path("f.png"));
  ASSERT_EQ(f.width(), 181);
  ASSERT_EQ(f.height(), 181);
  // Image pixel (X, Y) is film position (X, Y) / 20; the centre pixel's centre is (4.5, 4.5).
  expectColor(f, 90, 90, Color::Ones(), k8bit);                          // offset 0: weight 1
  expectColor(f, 101, 90, Color::Constant(1.f - 0.55f / 1.7f), k8bit);   // offset 0.55
  expectColor(f, 5, 5, Color(0, 0, 0.5f), k8bit);                        // outside the support
  expectColor(f, 40, 77, Color(0, 0, 1), 0.f);                           // grid column
}

// Issue 16, silent surprises 1 and 4.
TEST_F(RaytracerTest, SeveralSamplesWithoutFilterAverageOverThePixel) {
  // --spp 16 and no --filter: the documented default, the pixel-area box (not the first sample).
  const std::string base = "-input " + kScene + " -size 16 16 --sampler jittered --spp 16 ";
  const Result plain = run(base + "-stats -output " + path("plain.exr"));
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_NE(plain.out.find("box r=0.5"), std::string::npos) << plain.out;
  ASSERT_EQ(run(base + "--filter box --radius 0.5 -output " + path("box.exr")).code, 0);
  const Image a = readImage(path("plain.exr")), b = readImage(path("box.exr"));
  EXPECT_TRUE(identical(a, b));
  // and it is an average: some edge pixel lies strictly between the flat colours
  int mixed = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const Color c = a.get(x, y);
      mixed += (c.maxCoeff() - c.minCoeff() > 1e-3f && c[0] > 0.01f && c[0] < 0.99f);
    }
  EXPECT_GT(mixed, 0);
}

TEST_F(RaytracerTest, ClassicSamplesWithoutFilterKeepTheCourseRuleAndSaySo) {
  const Result r = run("-input " + kScene + " -size 16 16 -jittered_samples 4 -output " + path("j.exr"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("first sample"), std::string::npos) << r.err;
}

TEST_F(RaytracerTest, FilterWithoutRadiusUsesItsNaturalRadius) {
  const std::string base = "-input " + kScene + " -size 16 16 --sampler jittered --spp 4 ";
  const Result r = run(base + "--filter tent -output " + path("t.exr"));
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(run(base + "--filter tent --radius 1 -output " + path("t1.exr")).code, 0);
  EXPECT_TRUE(identical(readImage(path("t.exr")), readImage(path("t1.exr"))));
  // the Gaussian's natural radius follows sigma: 3 sigma
  ASSERT_EQ(run(base + "--filter gaussian --filter-param sigma=0.4 -output " + path("g.exr")).code, 0);
  ASSERT_EQ(run(base + "--filter gaussian --filter-param sigma=0.4 --radius 1.2 -output " + path("g1.exr")).code, 0);
  EXPECT_TRUE(identical(readImage(path("g.exr")), readImage(path("g1.exr"))));
}

TEST_F(RaytracerTest, RenderFilterShowsTheCutGaussianThatIsUsed) {
  // --filter gaussian --radius 1 with sigma 1: the weighted reconstruction cuts at distance 1.
  const Result r = run("-input " + kScene + " -size 9 9 --filter gaussian --radius 1 --filter-param sigma=1 "
                       "-render_filter " + path("g.png") + " 20");
  ASSERT_EQ(r.code, 0) << r.err;
  const Image g = readImage(path("g.png"));
  const int band = 34;  // colour bar band below the 181 x 181 picture (core/picture_kit.h kColorBarHeight)
  ASSERT_EQ(g.height(), 181 + band);
  // centre (4.5, 4.5) is image pixel (90, 90): full weight, pure red
  expectColor(g, 90 + 1, band + 90 + 1, Color(1, 0, 0), 0.05f);
  // offset (1.2, 0.05) lies beyond the radius: weight 0, white (the uncut Gaussian would be 0.49)
  expectColor(g, 90 + 24, band + 91, Color(1, 1, 1), k8bit);
  // offset (0.6, 0.05) inside: exp(-0.18) = 0.84, red with some white: green = 1 - sqrt(0.84)
  expectColor(g, 90 + 12, band + 91, Color(1, 1 - std::sqrt(std::exp(-0.5f * (0.36f + 0.0025f))),
                                           1 - std::sqrt(std::exp(-0.5f * (0.36f + 0.0025f)))), 2 * k8bit);
}

// One filter dialect (issue 44): --filter gaussian is the studies' Gaussian, sigma = radius / 3 at any radius; the
// course's fixed-sigma Gaussian is --filter course-gaussian; the classic -gaussian_filter keeps the course's meaning.
TEST_F(RaytracerTest, FilterGaussianIsTheStudiesAndCourseGaussianTheCourses) {
  const int band = 34;  // colour bar band below the 181 x 181 picture (core/picture_kit.h kColorBarHeight)
  // green = 1 - sqrt(w) for a positive weight w (peak 1), as in RenderFilterShowsTheCutGaussianThatIsUsed
  auto green = [](float dx, float dy, float sigma) {
    return 1 - std::sqrt(std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma)));
  };
  // --radius 3: sigma 1, so at offset (1.2, 0.05) the weight is exp(-0.72) = 0.49 (the course's sigma 0.5: 0.056)
  ASSERT_EQ(run("-input " + kScene + " -size 9 9 --filter gaussian --radius 3 -render_filter " + path("g3.png") +
                " 20").code, 0);
  const Image g3 = readImage(path("g3.png"));
  expectColor(g3, 90 + 24, band + 91, Color(1, green(1.2f, 0.05f, 1.f), green(1.2f, 0.05f, 1.f)), 2 * k8bit);
  // --radius 1.5 (its natural radius, also without --radius): sigma 0.5
  ASSERT_EQ(run("-input " + kScene + " -size 9 9 --filter gaussian -render_filter " + path("g.png") + " 20").code, 0);
  const Image g = readImage(path("g.png"));
  expectColor(g, 90 + 12, band + 91, Color(1, green(0.6f, 0.05f, 0.5f), green(0.6f, 0.05f, 0.5f)), 2 * k8bit);
  // course-gaussian at --radius 3 keeps sigma 0.5 (square support, uncut inside it)
  ASSERT_EQ(run("-input " + kScene + " -size 9 9 --filter course-gaussian --radius 3 -render_filter " + path("c3.png") +
                " 20").code, 0);
  const Image c3 = readImage(path("c3.png"));
  expectColor(c3, 90 + 24, band + 91, Color(1, green(1.2f, 0.05f, 0.5f), green(1.2f, 0.05f, 0.5f)), 2 * k8bit);
  // the classic flag: the course's gather with the course's Gaussian, the same image as course-gaussian named
  const std::string base = "-input " + kScene + " -size 16 16 ";
  ASSERT_EQ(run(base + "-jittered_samples 4 -gaussian_filter 0.5 -output " + path("classic.exr")).code, 0);
  ASSERT_EQ(run(base + "--sampler jittered --spp 4 --filter course-gaussian --reconstruction classic -output " +
                path("named.exr")).code, 0);
  ASSERT_EQ(run(base + "--sampler jittered --spp 4 --filter gaussian --reconstruction weighted -output " +
                path("study.exr")).code, 0);
  EXPECT_TRUE(identical(readImage(path("classic.exr")), readImage(path("named.exr"))));
  EXPECT_FALSE(identical(readImage(path("classic.exr")), readImage(path("study.exr"))));
}

TEST_F(RaytracerTest, RenderFilterShowsNegativeLobesInBlue) {
  const Result r = run("-input " + kScene + " -size 9 9 --filter lanczos --radius 3 -render_filter " +
                       path("l.png") + " 20");
  ASSERT_EQ(r.code, 0) << r.err;
  const Image l = readImage(path("l.png"));
  // Lanczos-3 at offset (1.45, 0.05), in its first negative lobe: weight -0.14, shown as sqrt(0.14) = 0.38 blue
  const Color c = l.get(90 + 29, 34 + 91);
  EXPECT_GT(c[2], c[0] + 0.2f) << c.transpose();  // clearly blue, not black or white
}

TEST_F(RaytracerTest, RenderSamplesMarksCentreSamplesOnCheckerCells) {
  const Result r = run("-input " + kScene + " -size 16 16 -render_samples " + path("s.png") + " 4");
  ASSERT_EQ(r.code, 0) << r.err;
  const Image s = readImage(path("s.png"));
  ASSERT_EQ(s.width(), 64);
  expectColor(s, 34, 34, Color(1, 0, 0), k8bit);     // pixel (8,8)'s centre sample, red
  expectColor(s, 32, 32, Color::Constant(0.2f), k8bit);  // i + j even: grey cell
  expectColor(s, 36, 32, Color::Zero(), k8bit);       // pixel (9,8): black cell
}

// ---------------------------------------------------------------- errors

namespace {
struct BadRun {
  const char* name;
  std::string args;  ///< OUT is replaced by the output path, DIR by the test folder
  int code;
  const char* message;
};

const BadRun kBadRuns[] = {
    {"missing_input_file", "-input DIR/none.txt -size 8 8 -output OUT", 1, "cannot open the scene file"},
    {"malformed_scene", "-input DIR/bad.txt -size 8 8 -output OUT", 1, "bad.txt:3: expected a number for 'radius'"},
    {"missing_mesh", "-input " + kData + "missing_mesh_scene.txt -size 8 8 -output OUT", 1,
     "missing_mesh_scene.txt:6:"},
    {"zero_size", "-input " + kScene + " -size 0 8 -output OUT", 2, "-size"},
    {"size_not_a_number", "-input " + kScene + " -size abc 8 -output OUT", 2, "-size"},
    {"unsupported_extension", "-input " + kScene + " -size 8 8 -output DIR/a.jpg", 2, "unsupported image extension"},
    {"missing_output_folder", "-input " + kScene + " -size 8 8 -output DIR/no/a.png", 2, "does not exist"},
    {"negative_bounces", "-input " + kScene + " -size 8 8 -bounces -1 -output OUT", 2, "-bounces"},
    {"bad_grid", "-input " + kScene + " -size 8 8 -grid 0 2 2 -output OUT", 2, "-grid"},
    {"depth_range", "-input " + kScene + " -size 8 8 -depth 5 1 OUT", 2, "-depth"},
    {"unknown_flag", "-input " + kScene + " -size 8 8 -antialias -output OUT", 2, "antialias"},
    {"nothing_to_write", "-input " + kScene + " -size 8 8", 2, "nothing to write"},
    {"unknown_sampler", "-input " + kScene + " -size 8 8 --sampler best -output OUT", 2, "jittered"},
    {"classic_and_general_sampler", "-input " + kScene + " -size 8 8 -jittered_samples 4 --sampler random -output OUT",
     2, "cannot be combined"},
    {"two_classic_filters", "-input " + kScene + " -size 8 8 -box_filter 1 -tent_filter 1 -output OUT", 2,
     "cannot be combined"},
    {"bad_filter_param", "-input " + kScene + " -size 8 8 --filter gaussian --radius 2 --filter-param sigma -output OUT",
     2, "name=value"},
    {"render_filter_without_filter", "-input " + kScene + " -size 8 8 -render_filter OUT 10", 2, "needs a filter"},
};

class RaytracerErrors : public RaytracerTest, public ::testing::WithParamInterface<BadRun> {};
}  // namespace

TEST_P(RaytracerErrors, ExitsWithMessageAndWritesNothing) {
  const BadRun& b = GetParam();
  std::ofstream(path("bad.txt")) << "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 4 }\n"
                                    "Materials { numMaterials 1 Material { } }\n"
                                    "Group { numObjects 1 Sphere { center 0 0 0 radius x } }\n";
  std::string args = b.args;
  for (size_t p; (p = args.find("OUT")) != std::string::npos;) args.replace(p, 3, path("out.png"));
  for (size_t p; (p = args.find("DIR")) != std::string::npos;) args.replace(p, 3, dir_.string());
  const Result r = run(args);
  EXPECT_EQ(r.code, b.code) << r.err;
  EXPECT_NE(r.err.find(b.message), std::string::npos) << r.err;
  for (const auto& entry : fs::directory_iterator(dir_)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "bad.txt" || name == "stdout.txt" || name == "stderr.txt") << "left behind: " << name;
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, RaytracerErrors, ::testing::ValuesIn(kBadRuns),
                         [](const auto& info) { return std::string(info.param.name); });

// An adaptive sampler: exactly w x h x spp primary rays (-stats), the same image for 1 and 3 threads, and
// -render_samples showing more samples along the disc's edge than in the flat middle of the picture.
TEST_F(RaytracerTest, AdaptiveSamplerSpendsTheBudgetWhereTheEdgesAre) {
  const std::string scene = std::string(ALIASLAB_SOURCE_DIR) + "/scenes/sphere_triangle.txt";
  const std::string base = "-input " + scene + " -size 32 32 --sampler adaptive-contrast:jittered --spp 8 -stats ";
  const Result one = run(base + "--threads 1 -output " + path("a1.exr") + " -render_samples " + path("s.exr") + " 8");
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_NE(one.out.find("rays: primary 8192,"), std::string::npos) << one.out;  // 32 * 32 * 8
  EXPECT_NE(one.out.find("adaptive contrast (Mitchell) on jittered"), std::string::npos) << one.out;
  ASSERT_EQ(run(base + "--threads 3 -output " + path("a3.exr")).code, 0);
  EXPECT_TRUE(identical(readImage(path("a1.exr")), readImage(path("a3.exr"))));
  // marked sample pixels (not the 0.2 / 0 checkerboard) per 8 x 8 block: the busiest block has several times
  // the marks of the quietest one
  const Image s = readImage(path("s.exr"));
  ASSERT_EQ(s.width(), 256);
  int least = 1 << 30, most = 0;
  for (int by = 0; by < 32; ++by)
    for (int bx = 0; bx < 32; ++bx) {
      int marks = 0;
      for (int y = by * 8; y < by * 8 + 8; ++y)
        for (int x = bx * 8; x < bx * 8 + 8; ++x) {
          const Color c = s.get(x, y);
          marks += !((c == 0.f).all() || (c == 0.2f).all());
        }
      least = std::min(least, marks), most = std::max(most, marks);
    }
  EXPECT_GE(most, 3 * std::max(1, least)) << "least " << least << ", most " << most;
}

// -frames F -motion dx,dy: F images <stem>_NNNN.<ext>; frame t sees what pixel p + t (dx, dy) saw in frame 0;
// -frames 1 -motion 0,0 writes the classic image bit for bit; frames do not depend on the thread count.
TEST_F(RaytracerTest, FramesOfAMovingCamera) {
  ASSERT_EQ(run("-input " + kScene + " -size 16 16 -output " + path("still.exr")).code, 0);
  ASSERT_EQ(run("-input " + kScene + " -size 16 16 -frames 1 -motion 0,0 -output " + path("one.exr")).code, 0);
  EXPECT_TRUE(identical(readImage(path("still.exr")), readImage(path("one_0000.exr"))));
  const std::string moving = "-input " + kScene + " -size 16 16 -frames 3 -motion 1,0 --sampler jittered --spp 4";
  ASSERT_EQ(run(moving + " --threads 1 -output " + path("a.exr")).code, 0);
  ASSERT_EQ(run(moving + " --threads 2 -output " + path("b.exr")).code, 0);
  for (const char* t : {"0000", "0001", "0002"})
    EXPECT_TRUE(identical(readImage(path(std::string("a_") + t + ".exr")), readImage(path(std::string("b_") + t + ".exr"))));
  EXPECT_FALSE(fs::exists(path("a_0003.exr")));
  // A whole-pixel motion at pixel centres: frame 2's pixel x is frame 0's pixel x + 2 (all but edge pixels).
  ASSERT_EQ(run("-input " + kScene + " -size 16 16 -frames 3 -motion 1,0 -output " + path("c.exr")).code, 0);
  const Image f0 = readImage(path("c_0000.exr")), f2 = readImage(path("c_0002.exr"));
  int same = 0, all = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x + 2 < 16; ++x, ++all) same += f2.get(x, y).isApprox(f0.get(x + 2, y), 0.f) ? 1 : 0;
  EXPECT_GE(same, all - 4);
  EXPECT_FALSE(identical(f0, f2));
}

// -register writes frame t moved by +t (dx, dy) (the library's band-limited shift, measure/registration.h): with a
// whole-pixel motion the shift is exact, so registered frame 2 is frame 0 away from the 2 pixels entering at the
// left (and the few pixels the unregistered frames already differ at); unregistered, frame 2 differs from frame 0.
TEST_F(RaytracerTest, RegisteredFramesShowFrameZerosContent) {
  const std::string moving = "-input " + kScene + " -size 16 16 -frames 3 -motion 1,0 -output ";
  ASSERT_EQ(run(moving + path("r.exr") + " -register").code, 0);
  ASSERT_EQ(run(moving + path("c.exr")).code, 0);
  EXPECT_TRUE(identical(readImage(path("r_0000.exr")), readImage(path("c_0000.exr"))));  // frame 0 as rendered
  const Image f0 = readImage(path("c_0000.exr")), f2 = readImage(path("c_0002.exr")), r2 = readImage(path("r_0002.exr"));
  int same = 0, all = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 2; x < 16; ++x, ++all) same += (r2.get(x, y) - f0.get(x, y)).cwiseAbs().maxCoeff() < 1e-4f ? 1 : 0;
  EXPECT_GE(same, all - 4);
  EXPECT_FALSE(identical(f0, f2));
  const Result r = run("-input " + kScene + " -size 16 16 -register -output " + path("x.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("-register: needs -frames"), std::string::npos) << r.err;
}

TEST_F(RaytracerTest, FramesRefuseBadValues) {
  const std::string base = "-input " + kScene + " -size 16 16 -output " + path("x.png");
  for (const auto& [args, words] : std::vector<std::pair<std::string, std::string>>{
           {" -frames 0", "-frames: must be a whole number in 1..10000"},
           {" -motion 1,0", "-motion: needs -frames"},
           {" -frames 2 -motion 1,inf", "-motion"},
           {" -frames 2 -motion 1", "-motion"},
           {" -frames 2 -normals " + path("n.png"), "-frames: renders the colour image only"}}) {
    const Result r = run(base + args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_NE(r.err.find(words), std::string::npos) << args << ": " << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir_) || !fs::exists(path("x_0000.png")));
}
