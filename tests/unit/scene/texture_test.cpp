// Procedural materials and Perlin noise against values derived by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/hash.h"
#include "scene/material.h"

namespace aliaslab {
namespace {

constexpr float kTol = 1e-5f;

void expectColor(const Color& got, const Color& want, float tol = kTol) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tol) << "channel " << c;
}

// Procedural materials -------------------------------------------------------

TEST(Procedural, CheckerboardParityOfFloorSum) {
  auto a = makePhong({.diffuse = Color(1, 0, 0), .indexOfRefraction = 1.f});
  auto b = makePhong({.diffuse = Color(0, 1, 0), .reflective = Color::Ones(), .indexOfRefraction = 2.f});
  auto checker = makeCheckerboard(Mat4::Identity(), a.get(), b.get());
  struct Case { Vec3 p; bool second; };
  for (const Case& c : {Case{{0.5f, 0.5f, 0.5f}, false}, Case{{1.5f, 0.5f, 0.5f}, true},
                        Case{{-0.5f, 0.5f, 0.5f}, true}, Case{{-0.5f, -0.5f, 0.5f}, false},
                        Case{{2.1f, 3.2f, -4.7f}, false},     // 2 + 3 - 5 = 0
                        Case{{-0.1f, -0.1f, -0.1f}, true}}) {  // -3
    const bool second = c.second;
    expectColor(checker->diffuse(c.p), second ? Color(0, 1, 0) : Color(1, 0, 0));
    expectColor(checker->reflective(c.p), second ? Color::Ones() : Color::Zero());
    EXPECT_EQ(checker->indexOfRefraction(c.p), second ? 2.f : 1.f);
  }
  // Texture transform: scale 2 maps world 0.75 to texture 1.5 (odd cell).
  Mat4 scale = Mat4::Identity();
  scale.diagonal().head<3>().setConstant(2.f);
  auto scaled = makeCheckerboard(scale, a.get(), b.get());
  expectColor(scaled->diffuse(Vec3(0.75f, 0.1f, 0.1f)), Color(0, 1, 0));
}

// The course's formulas (SCENE_FORMAT.md, Noise and Marble): T = sum_{k<n} noise(2^k q) / 2^k,
// Noise w = clamp(T + 0.5, 0, 1), Marble w = (sin(f x + a T) + 1) / 2, colour w * m1 + (1 - w) * m2.
// T is recomputed here from perlinNoise, independently of the material code.
float courseT(const Vec3& q, int octaves) {
  double t = 0;
  for (int k = 0; k < octaves; ++k) {
    const float s = std::ldexp(1.f, k);
    t += perlinNoise(s * q.x(), s * q.y(), s * q.z()) / s;
  }
  return static_cast<float>(t);
}

// Every query blends w * first + (1 - w) * second with the course's weight.
TEST(Procedural, MarbleAndNoiseBlendEveryQuery) {
  auto a = makePhong({.diffuse = Color(1, 0, 0), .specular = Color::Zero(), .transparent = Color::Zero(),
                      .indexOfRefraction = 1.f});
  auto b = makePhong({.diffuse = Color(0, 0, 1), .transparent = Color::Ones(), .indexOfRefraction = 2.f});
  const Vec3 p(0.3f, 0.7f, 0.1f);
  const float n = perlinNoise(p.x(), p.y(), p.z()) + perlinNoise(2 * p.x(), 2 * p.y(), 2 * p.z()) / 2;
  const float w = (std::sin(3.f * p.x() + 2.f * n) + 1) / 2;  // to the FIRST material
  auto marble = makeMarble(Mat4::Identity(), a.get(), b.get(), 2, 3.f, 2.f);
  expectColor(marble->diffuse(p), Color(w, 0, 1 - w));
  expectColor(marble->transparent(p), Color::Constant(1 - w));
  EXPECT_NEAR(marble->indexOfRefraction(p), w * 1 + (1 - w) * 2, kTol);
  const Color shaded = marble->shade(p, Vec3::UnitY(), Vec3::UnitY(), Vec3::UnitY(), Color::Ones());
  expectColor(shaded, Color(w, 0, 1 - w));

  // Noise with one octave: at (0.25, 0, 0) noise = 0.146484375 (see the Perlin test), so
  // w = 0.646484375 to the first material.
  auto noise = makeNoise(Mat4::Identity(), a.get(), b.get(), 1);
  expectColor(noise->diffuse(Vec3(0.25f, 0, 0)), Color(0.646484375f, 0, 0.353515625f));
  // At a lattice point noise is 0: T + 0.5 = 0.5, an even blend.
  expectColor(noise->diffuse(Vec3(3, -2, 5)), Color(0.5f, 0, 0.5f));
}

// Noise at many points, both clamp ends included: w = clamp(T + 0.5, 0, 1) to the first material.
TEST(Procedural, NoiseWeightMatchesTheCourseFormulaIncludingClamping) {
  auto a = makePhong({.diffuse = Color(1, 0, 0)}), b = makePhong({.diffuse = Color(0, 1, 0)});
  Mat4 m = Mat4::Identity();
  m.diagonal().head<3>().setConstant(3.f);  // texture space = 3 * world (as scenes/vase.txt's floor)
  m(1, 3) = 0.37f;
  auto noise = makeNoise(m, a.get(), b.get(), 4);
  int clampedHigh = 0, clampedLow = 0, inside = 0;
  HashRng rng(11);
  for (int k = 0; k < 4000; ++k) {
    const Vec3 p(8 * rng.nextFloat() - 4, 8 * rng.nextFloat() - 4, 8 * rng.nextFloat() - 4);
    const Vec3 q = 3.f * p + Vec3(0, 0.37f, 0);
    const float t = courseT(q, 4);
    const float w = std::clamp(t + 0.5f, 0.f, 1.f);
    const Color got = noise->diffuse(p);
    ASSERT_NEAR(got[0], w, 2e-5f) << "T = " << t;
    ASSERT_NEAR(got[1], 1 - w, 2e-5f) << "T = " << t;
    clampedHigh += t > 0.5f, clampedLow += t < -0.5f, inside += std::abs(t) < 0.4f;
  }
  EXPECT_GT(clampedHigh, 0) << "no point exercised the upper clamp";
  EXPECT_GT(clampedLow, 0) << "no point exercised the lower clamp";
  EXPECT_GT(inside, 100);
}

// Marble at chosen points where the weight is known in closed form: at lattice points of every octave
// (integer q) T = 0, so w = (sin(f x) + 1) / 2 exactly.
TEST(Procedural, MarbleWeightAtLatticePointsAndAgainstTheFormula) {
  auto a = makePhong({.diffuse = Color(1, 0, 0)}), b = makePhong({.diffuse = Color(0, 1, 0)});
  const float f = 0.5f * kPi;  // f x = pi/2 at x = 1: sin = 1, w = 1 (pure first)
  auto marble = makeMarble(Mat4::Identity(), a.get(), b.get(), 3, f, 7.f);
  expectColor(marble->diffuse(Vec3(1, 4, -2)), Color(1, 0, 0));   // sin(pi/2) = 1
  expectColor(marble->diffuse(Vec3(3, 0, 5)), Color(0, 1, 0));    // sin(3pi/2) = -1
  expectColor(marble->diffuse(Vec3(2, -1, 1)), Color(0.5f, 0.5f, 0), 1e-5f);  // sin(pi) = 0
  HashRng rng(5);
  for (int k = 0; k < 500; ++k) {
    const Vec3 p(4 * rng.nextFloat() - 2, 4 * rng.nextFloat() - 2, 4 * rng.nextFloat() - 2);
    const float w = (std::sin(f * p.x() + 7.f * courseT(p, 3)) + 1) / 2;
    const Color got = marble->diffuse(p);
    ASSERT_NEAR(got[0], w, 1e-4f);
    ASSERT_NEAR(got[1], 1 - w, 1e-4f);
  }
}

// Aliasing test patterns at points where the weight is known exactly.
TEST(Procedural, PatternWeightsAtKnownPoints) {
  auto a = makePhong({.diffuse = Color::Zero()}), b = makePhong({.diffuse = Color::Ones()});
  auto w = [&](PatternKind kind, float f, float x, float y) {
    return makePattern(Mat4::Identity(), a.get(), b.get(), kind, f)->diffuse(Vec3(x, y, 0))[0];
  };
  const float f = 4.f;
  EXPECT_NEAR(w(PatternKind::ZonePlate, f, std::sqrt(kPi / (2 * f)), 0), 1.f, kTol);  // sin(pi/2)
  EXPECT_NEAR(w(PatternKind::ZonePlate, f, 0, std::sqrt(3 * kPi / (2 * f))), 0.f, kTol);  // sin(3pi/2)
  EXPECT_NEAR(w(PatternKind::Sinc, f, 0, 0), 1.f, kTol);            // sinc(0) = 1
  EXPECT_NEAR(w(PatternKind::Sinc, f, 1 / f, 0.1f), 0.5f, kTol);    // sinc(1) = 0
  EXPECT_EQ(w(PatternKind::Stripes, f, 0.25f / f, 7), 1.f);         // sin(pi/2) > 0
  EXPECT_EQ(w(PatternKind::Stripes, f, 0.75f / f, 7), 0.f);         // sin(3pi/2) < 0
  EXPECT_EQ(w(PatternKind::Siemens, f, std::cos(0.17f), std::sin(0.17f)), 1.f);  // sin(4 * 0.17) > 0
  EXPECT_EQ(w(PatternKind::Siemens, f, std::cos(0.9f), std::sin(0.9f)), 0.f);    // sin(3.6) < 0
  // grating 0.5 + 0.5 cos(2 pi f (x cos a + y sin a)): angle 0 is along x, angle 90 along y
  auto g = [&](float angle, float x, float y) {
    return makePattern(Mat4::Identity(), a.get(), b.get(), PatternKind::Grating, f, angle)->diffuse(Vec3(x, y, 0))[0];
  };
  EXPECT_NEAR(g(0, 0, 0.3f), 1.f, kTol);
  EXPECT_NEAR(g(0, 0.5f / f, 0.3f), 0.f, kTol);
  EXPECT_NEAR(g(0, 0.125f / f, 5), 0.5f + 0.5f * std::cos(kPi / 4), kTol);
  EXPECT_NEAR(g(90, 0.3f, 0.5f / f), 0.f, kTol);
  EXPECT_NEAR(g(60, 1 / f, 0), 0.f, kTol);  // cos(2 pi * 0.5) = -1
}

// The grating's footprint average (an axis-aligned box) against a midpoint rule over the box.
TEST(Procedural, GratingFootprintIsTheBoxAverage) {
  auto a = makePhong({.diffuse = Color::Zero()}), b = makePhong({.diffuse = Color::Ones()});
  const float f = 3.f, angle = 25.f;
  const auto g = makePattern(Mat4::Identity(), a.get(), b.get(), PatternKind::Grating, f, angle);
  const double c = std::cos(angle * kPi / 180), s = std::sin(angle * kPi / 180);
  for (const auto& [x, y, hx, hy] : {std::array<double, 4>{0.1, -0.2, 0.05, 0.08}, {0.37, 0.5, 0.2, 0.01}}) {
    const int n = 400;
    double sum = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double u = x + hx * (2 * (i + 0.5) / n - 1), v = y + hy * (2 * (j + 0.5) / n - 1);
        sum += 0.5 + 0.5 * std::cos(2 * kPi * f * (u * c + v * s));
      }
    const SurfacePoint p(Vec3(float(x), float(y), 0), Vec3(float(2 * hx), 0, 0), Vec3(0, float(2 * hy), 0));
    EXPECT_NEAR(g->diffuse(p)[0], sum / (n * n), 1e-4) << x << " " << y;
  }
}

// Perlin noise -----------------------------------------------------------------

TEST(Perlin, ZeroAtLatticePoints) {
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y)
      for (int z = -3; z <= 3; ++z) EXPECT_EQ(perlinNoise(x * 7.f, y * 5.f, z * 3.f), 0.f);
}

// At (0.25, 0, 0): X = Y = Z = 0, A = p[0] = 151, AA = p[151] = 17, p[17] = 36
// (gradient 4: x + z = 0.25); B = p[1] = 160, BA = p[160] = 119, p[119] = 86
// (gradient 6: (x - 1) - z = -0.75); v = w = 0 keep only the x lerp with
// fade(0.25) = 0.25^3 (10 - 15/4 + 6/16) = 0.103515625:
// 0.25 + 0.103515625 (-0.75 - 0.25) = 0.146484375.
TEST(Perlin, HandEvaluatedValueAndReferenceValue) {
  EXPECT_FLOAT_EQ(perlinNoise(0.25f, 0.f, 0.f), 0.146484375f);
  // The value Perlin's reference implementation gives for (3.14, 42, 7).
  EXPECT_NEAR(perlinNoise(3.14f, 42.f, 7.f), 0.136919958784f, 1e-5f);
  // An independent double-precision transcription of the reference (Python),
  // at points whose fractions are exact in binary so float input is exact.
  EXPECT_NEAR(perlinNoise(0.25f, 0.5f, 0.75f), -0.2697153091430664f, 1e-6f);
  EXPECT_NEAR(perlinNoise(-1.5f, 2.25f, 0.5f), -0.1551513671875f, 1e-6f);
}

TEST(Perlin, RangePeriodAndContinuity) {
  HashRng rng(7);
  float lo = 0, hi = 0;
  for (int k = 0; k < 20000; ++k) {
    const float x = 40 * rng.nextFloat() - 20, y = 40 * rng.nextFloat() - 20, z = 40 * rng.nextFloat() - 20;
    const float v = perlinNoise(x, y, z);
    lo = std::min(lo, v), hi = std::max(hi, v);
    EXPECT_NEAR(perlinNoise(x + 256, y, z), v, 1e-4f);            // period 256
    EXPECT_NEAR(perlinNoise(x + 1e-3f, y, z), v, 1e-2f);          // continuous
  }
  EXPECT_GE(lo, -1.f);
  EXPECT_LE(hi, 1.f);
  EXPECT_LT(lo, -0.4f);  // not degenerate
  EXPECT_GT(hi, 0.4f);
}

// MaterialAt evaluates the blend weights once per point and must answer
// every query bit for bit as the material itself does: nested blends of
// Phong materials whose shade() is non-linear in their parameters (different
// exponents), pure ends (checkerboard) and partial weights (marble, wood),
// and a chain deeper than MaterialAt keeps (the fallback to direct queries).
TEST(MaterialAt, EqualsDirectQueriesBitForBit) {
  auto a = makePhong({.diffuse = Color(0.9f, 0.1f, 0.2f), .specular = Color(0.5f, 0.5f, 0.5f), .exponent = 7.f,
                      .reflective = Color(0.1f, 0.f, 0.f), .indexOfRefraction = 1.3f});
  auto b = makePhong({.diffuse = Color(0.1f, 0.8f, 0.3f), .specular = Color(0.2f, 0.9f, 0.1f), .exponent = 60.f,
                      .transparent = Color(0.f, 0.4f, 0.4f), .indexOfRefraction = 1.7f});
  Mat4 scale = Mat4::Identity();
  scale.diagonal().head<3>().setConstant(3.f);
  auto checker = makeCheckerboard(scale, a.get(), b.get());
  auto marble = makeMarble(Mat4::Identity(), checker.get(), b.get(), 4, 2.f, 3.f);
  auto wood = makeWood(scale, marble.get(), a.get(), 3, 5.f, 1.f);
  std::vector<std::unique_ptr<Material>> chain;
  const Material* deep = a.get();
  for (int k = 0; k < 40; ++k) {
    chain.push_back(makeNoise(Mat4::Identity(), deep, k % 2 ? a.get() : b.get(), 2));
    deep = chain.back().get();
  }
  const Vec3 n = Vec3(0.2f, 1.f, 0.1f).normalized(), toViewer = Vec3(0.f, 1.f, 0.3f).normalized();
  const Color light(0.8f, 0.9f, 1.f);
  auto same = [](const Color& x, const Color& y) { return (x == y).all(); };
  int partial = 0;
  for (const Material* m : std::vector<const Material*>{a.get(), checker.get(), marble.get(), wood.get(), deep})
    for (int i = 0; i < 500; ++i) {
      const Vec3 p(4.f * toUnitFloat(hashWords(i, 1, 0)) - 2.f, 4.f * toUnitFloat(hashWords(i, 2, 0)) - 2.f,
                   4.f * toUnitFloat(hashWords(i, 3, 0)) - 2.f);
      const Vec3 toLight = Vec3(toUnitFloat(hashWords(i, 4, 0)) - 0.5f, 1.f, 0.3f).normalized();
      const MaterialAt at(*m, p);
      ASSERT_TRUE(same(at.shade(n, toViewer, toLight, light), m->shade(p, n, toViewer, toLight, light))) << i;
      ASSERT_TRUE(same(at.diffuse(), m->diffuse(p))) << m->describe() << " at " << i;
      ASSERT_TRUE(same(at.reflective(), m->reflective(p)));
      ASSERT_TRUE(same(at.transparent(), m->transparent(p)));
      ASSERT_EQ(at.indexOfRefraction(), m->indexOfRefraction(p));
      const Color d = m->diffuse(p);
      partial += !same(d, a->diffuse(p)) && !same(d, b->diffuse(p));
    }
  EXPECT_GT(partial, 100);  // the blends really mix at many of the points
}

}  // namespace
}  // namespace aliaslab
