// imgdiff's numbers against numpy on constructed images, and LDR-FLIP
// (lib/measure/flip/flip.h) against properties from Andersson et al. 2020.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "core/cpu.h"
#include "core/image.h"
#include "measure/flip/flip.h"

using namespace aliaslab;
namespace fs = std::filesystem;

namespace {

const fs::path kDir = fs::temp_directory_path() / "aliaslab_imgdiff_test";

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// "name value" lines of a program's output.
std::map<std::string, double> parse(const std::string& text) {
  std::map<std::string, double> m;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string name, value;
    if (words >> name >> value) m[name] = value == "inf" ? INFINITY : std::stod(value);
  }
  return m;
}

Image uniform(int w, int h, const Color& c) { return Image(w, h, c); }

TEST(Imgdiff, MseRelmsePsnrBiasSpreadAgreeWithNumpy) {
  fs::create_directories(kDir);
  // A(x, y, c) = ((7x + 13y + 5c) mod 17) / 16, B = ((3x + 11y + 7c) mod 19) / 18 (float32 both sides)
  const int w = 37, h = 23;
  Image a(w, h), b(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        a.data()[3 * a.index(x, y) + c] = float((7 * x + 13 * y + 5 * c) % 17) / 16.f;
        b.data()[3 * b.index(x, y) + c] = float((3 * x + 11 * y + 7 * c) % 19) / 18.f;
      }
  writeImage((kDir / "a.exr").string(), a);
  writeImage((kDir / "b.exr").string(), b);
  const std::string cmd = std::string(ALIASLAB_BIN_DIR) + "/imgdiff " + (kDir / "a.exr").string() + " " +
                          (kDir / "b.exr").string() + " --output " + (kDir / "d.png").string() + " > " +
                          (kDir / "out.txt").string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const auto got = parse(slurp(kDir / "out.txt"));
  std::ofstream py(kDir / "ref.py");
  py << "import numpy as np\n"
        "y, x, c = np.meshgrid(np.arange(" << h << "), np.arange(" << w << "), np.arange(3), indexing='ij')\n"
        "a = ((7*x + 13*y + 5*c) % 17).astype(np.float32) / np.float32(16)\n"
        "b = ((3*x + 11*y + 7*c) % 19).astype(np.float32) / np.float32(18)\n"
        "d = a.astype(np.float64) - b.astype(np.float64)\n"
        "mse = np.mean(d**2)\n"
        "print('mse', repr(mse))\n"
        "print('relmse', repr(np.mean(d**2 / (b.astype(np.float64)**2 + 0.01))))\n"
        "print('psnr_db', repr(10*np.log10(1/mse)))\n"
        "print('bias', repr(np.mean(d)))\n"
        "print('spread', repr(np.std(d)))\n"
        "print('max_abs', repr(np.max(np.abs(d))))\n";
  py.close();
  const std::string pcmd = "/usr/bin/python3 " + (kDir / "ref.py").string() + " > " + (kDir / "np.txt").string();
  ASSERT_EQ(std::system(pcmd.c_str()), 0) << "needs /usr/bin/python3 with numpy";
  const auto want = parse(slurp(kDir / "np.txt"));
  ASSERT_EQ(want.size(), 6u);
  for (const auto& [name, value] : want) {
    ASSERT_TRUE(got.count(name)) << name;
    // imgdiff prints 9 significant digits (6 for psnr_db)
    EXPECT_NEAR(got.at(name), value, (name == "psnr_db" ? 1e-5 : 1e-8) * std::abs(value)) << name;
  }
  EXPECT_GT(got.at("flip"), 0.0);
  EXPECT_TRUE(fs::exists(kDir / "d.png"));
}

TEST(Imgdiff, RefusesImagesOfDifferentSizes) {
  fs::create_directories(kDir);
  writeImage((kDir / "s1.exr").string(), Image(4, 4));
  writeImage((kDir / "s2.exr").string(), Image(5, 4));
  const std::string cmd = std::string(ALIASLAB_BIN_DIR) + "/imgdiff " + (kDir / "s1.exr").string() + " " +
                          (kDir / "s2.exr").string() + " > /dev/null 2> " + (kDir / "err.txt").string();
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(slurp(kDir / "err.txt").find("differs"), std::string::npos);
}

// FLIP's filters are separable convolutions with clamped edges, vectorised (2 or 4 lanes, registers across the
// taps, rows padded with their edge values). Every output must be the textbook sum, bit for bit: k = -r .. r in
// order from 0, indices clamped, first along x, then along y. Planes narrower and shorter than the kernels
// included, so the padding covers whole rows.
TEST(Flip, ConvolutionIsTheTextbookSumBitForBit) {
  unsigned state = 12345;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 16777216.0;
  };
  auto textbook = [](const std::vector<double>& in, int w, int h, const std::vector<double>& kx,
                     const std::vector<double>& ky) {
    const int rx = static_cast<int>(kx.size()) / 2, ry = static_cast<int>(ky.size()) / 2;
    std::vector<double> mid(in.size()), out(in.size());
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        double s = 0;
        for (int k = -rx; k <= rx; ++k) s += kx[k + rx] * in[y * w + std::clamp(x + k, 0, w - 1)];
        mid[y * w + x] = s;
      }
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        double s = 0;
        for (int k = -ry; k <= ry; ++k) s += ky[k + ry] * mid[std::clamp(y + k, 0, h - 1) * w + x];
        out[y * w + x] = s;
      }
    return out;
  };
  int compared = 0;
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {3, 2}, {7, 5}, {16, 3}, {33, 17}, {64, 9}, {130, 4}})
    for (int rx : {0, 1, 4, 10})
      for (int ry : {0, 3, 9}) {
        std::vector<double> in(static_cast<size_t>(w) * h), kx(2 * rx + 1), ky(2 * ry + 1);
        for (double& v : in) v = 4 * next() - 1;
        for (double& v : kx) v = next() - 0.3;  // negative taps too, as the derivative kernels have
        for (double& v : ky) v = next() - 0.3;
        const std::vector<double> want = textbook(in, w, h, kx, ky);
        for (int lanes : {2, 4}) {
          const ScopedCpuFeatures only(CpuFeatures{lanes == 4, lanes == 4});  // 2: SSE2; 4: AVX where the CPU has it
          const std::vector<double> got = convolveClamped(in, w, h, kx, ky);
          ASSERT_EQ(got.size(), want.size());
          for (size_t i = 0; i < want.size(); ++i, ++compared)
            ASSERT_EQ(got[i], want[i]) << w << " x " << h << ", rx " << rx << ", ry " << ry << ", lanes " << lanes
                                       << ", pixel " << i;
        }
      }
  EXPECT_GT(compared, 10000);
  EXPECT_THROW(convolveClamped(std::vector<double>(6), 3, 2, std::vector<double>(2), std::vector<double>(1)),
               std::invalid_argument);
}

TEST(Flip, IdenticalImagesGiveZero) {
  Image a(24, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 24; ++x) a.set(x, y, Color(x / 24.f, y / 16.f, ((x + y) % 3) / 2.f));
  for (float v : flipMap(a, a)) EXPECT_EQ(v, 0.f);
}

TEST(Flip, GreenAgainstBlueIsTheMaximumOne) {
  // The paper normalises colour differences by the largest one in the gamut,
  // Hunt-adjusted HyAB(green, blue): two uniform images of those colours
  // (no features) give FLIP 1 everywhere.
  for (float v : flipMap(uniform(16, 16, Color(0, 1, 0)), uniform(16, 16, Color(0, 0, 1)))) EXPECT_NEAR(v, 1.f, 1e-5f);
  // every other pair of uniform colours stays below
  EXPECT_LT(meanFlip(uniform(8, 8, Color(0, 0, 0)), uniform(8, 8, Color(1, 1, 1))), 1.0);
  EXPECT_LT(meanFlip(uniform(8, 8, Color(1, 0, 0)), uniform(8, 8, Color(0, 1, 0))), 1.0);
}

TEST(Flip, GrowsWithTheColourDifferenceAndIsSymmetric) {
  double prev = 0;
  for (float d : {0.01f, 0.03f, 0.1f, 0.2f, 0.4f}) {
    const double f = meanFlip(uniform(8, 8, Color::Constant(0.3f + d)), uniform(8, 8, Color::Constant(0.3f)));
    EXPECT_GT(f, prev) << "d = " << d;
    prev = f;
  }
  Image a(20, 20), b(20, 20, Color::Constant(0.5f));
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) a.set(x, y, Color::Constant((x / 3 + y / 5) % 2 ? 0.8f : 0.2f));
  EXPECT_NEAR(meanFlip(a, b), meanFlip(b, a), 1e-6);
}

TEST(Flip, APreparedReferenceServesManyImagesUnchanged) {
  // The sweep prepares its target once (FlipReference) and compares every
  // seed's image with it, from many threads: the object must not change
  // between calls, and must agree with the symmetric two-image form.
  Image ref(20, 14), a(20, 14), b(20, 14, Color(0.9f, 0.1f, 0.2f));
  for (int y = 0; y < 14; ++y)
    for (int x = 0; x < 20; ++x) {
      ref.set(x, y, Color::Constant((x / 3 + y / 5) % 2 ? 0.8f : 0.2f));
      a.set(x, y, Color(x / 20.f, y / 14.f, 0.5f));
    }
  const FlipReference prepared(ref);
  const double first = prepared.mean(a);
  EXPECT_GT(prepared.mean(b), 0.0);
  EXPECT_EQ(prepared.mean(a), first);
  EXPECT_NEAR(first, meanFlip(ref, a), 1e-6);  // the map is symmetric: computed the other way round
  EXPECT_EQ(prepared.mean(ref), 0.0);
  EXPECT_THROW(prepared.mean(Image(19, 14)), std::invalid_argument);
}

}  // namespace
