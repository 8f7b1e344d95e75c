// Pre-filtering (docs/prefiltering.md): box-filtered textures against
// brute-force averages of the point-sampled texture over the same footprint,
// the limits of frequency clamping, the sine integral, ray-differential
// footprints against the analytic footprint of a plane seen by a pinhole and
// by an orthographic camera, and the end-to-end ordering in the sweep: at
// 1 spp, pre-filtering lowers aliasing on the horizon checkerboard against
// the same (un-prefiltered) target.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "accel/aggregate.h"
#include "core/hash.h"
#include "render/tracer.h"
#include "scene/camera.h"
#include "scene/material.h"
#include "scene/prefilter.h"
#include "scene/scene.h"
#include "support/scratch_dir.h"
#include "study/records/csv.h"

namespace aliaslab {
namespace {

namespace fs = std::filesystem;

// Black and white: a material's diffuse red channel is the weight of the second material.
struct Pair {
  std::unique_ptr<Material> black = makePhong({.diffuse = Color::Zero()});
  std::unique_ptr<Material> white = makePhong({.diffuse = Color::Ones()});
};

double second(const Material& m, const SurfacePoint& s) { return m.diffuse(s)[0]; }

/// Mean of the point-sampled material over the parallelogram p + a dx + b dy,
/// |a|, |b| <= 1/2: an nx x ny midpoint grid, summed in double.
double bruteForce(const Material& m, const Vec3& p, const Vec3& dx, const Vec3& dy, int nx, int ny) {
  double sum = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const float a = (i + 0.5f) / nx - 0.5f, b = (j + 0.5f) / ny - 0.5f;
      sum += second(m, Vec3(p + a * dx + b * dy));
    }
  return sum / (static_cast<double>(nx) * ny);
}

/// The same on an n x n grid.
double bruteForce(const Material& m, const Vec3& p, const Vec3& dx, const Vec3& dy, int n) {
  return bruteForce(m, p, dx, dy, n, n);
}

Mat4 scaleTranslate(float s, const Vec3& t) {
  Mat4 m = Mat4::Identity();
  m.diagonal().head<3>().setConstant(s);
  m.block<3, 1>(0, 3) = t;
  return m;
}

// Box-filtered checker ----------------------------------------------------------

// Axis-aligned footprints (the parallelogram is its own bounding box) whose
// corners and the checker's cell edges all lie on multiples of 1/16 in
// texture space: a midpoint grid of spacing 1/1024 then has every cell edge
// on a grid line, so the brute-force average of the point-sampled checker is
// exact up to float rounding, and the closed form must match it to 1e-4.
TEST(PrefilterChecker, BoxFilteredCheckerMatchesBruteForceAverageTo1e4) {
  Pair m;
  auto plain = makeCheckerboard(Mat4::Identity(), m.black.get(), m.white.get());
  Mat4 t = scaleTranslate(2.f, Vec3(0.25f, 0.25f, 0.125f));  // texture = 2 world + t
  auto textured = makeCheckerboard(t, m.black.get(), m.white.get());
  struct Case {
    const Material* material;
    Vec3 p, dx, dy;
    float worldSpacing;  // grid spacing in world units (1/1024 in texture space)
  };
  const float s = 1.f / 1024;
  const Case cases[] = {
      {plain.get(), {0.25f, 0.625f, 0.5f}, {1.5f, 0, 0}, {0, 0.75f, 0}, s},          // crosses x = 0
      {plain.get(), {1.0625f, -0.1875f, 0.5f}, {0.375f, 0, 0}, {0, 0.875f, 0}, s},   // x = 1 and y = 0
      {plain.get(), {-2.25f, 3.75f, 0.5f}, {2.5f, 0, 0}, {0, 1.75f, 0}, s},          // several cells
      {plain.get(), {0.25f, 0.5f, 0.5f}, {0.25f, 0, 0}, {0, 0.125f, 0}, s},          // inside one cell: 0
      {plain.get(), {5.5f, 0.5f, 0.5f}, {4.f, 0, 0}, {0, 1.f / 64, 0}, s},           // long and thin: 1/2
      {textured.get(), {0.125f, 0.3f, 0.25f}, {0.625f, 0, 0}, {0, 0, 0.4375f}, s / 2},  // xz plane, scale 2
  };
  for (const Case& c : cases) {
    const double filtered = second(*c.material, SurfacePoint(c.p, c.dx, c.dy));
    const int nx = static_cast<int>(std::lround(c.dx.norm() / c.worldSpacing));
    const int ny = static_cast<int>(std::lround(c.dy.norm() / c.worldSpacing));
    const double brute = bruteForce(*c.material, c.p, c.dx, c.dy, nx, ny);
    EXPECT_NEAR(filtered, brute, 1e-4) << "p " << c.p.transpose() << " dx " << c.dx.transpose() << " dy "
                                       << c.dy.transpose();
  }
}

// Generic positions: the midpoint grid (n x n) now misplaces up to half a
// grid column at each cell edge crossing the box, an error of at most
// 0.5 / n per crossing edge; the tolerance is that bound.
TEST(PrefilterChecker, BoxFilteredCheckerMatchesBruteForceAtGenericPositions) {
  Pair m;
  auto checker = makeCheckerboard(Mat4::Identity(), m.black.get(), m.white.get());
  HashRng rng(17);
  const int n = 2048;
  for (int k = 0; k < 4; ++k) {
    const Vec3 p(6 * rng.nextFloat() - 3, 6 * rng.nextFloat() - 3, 0.3f);
    const Vec3 dx(0.2f + 2 * rng.nextFloat(), 0, 0), dy(0, 0.2f + 2 * rng.nextFloat(), 0);
    const int edges = static_cast<int>(std::floor(p.x() + dx.x() / 2) - std::floor(p.x() - dx.x() / 2) +
                                       std::floor(p.y() + dy.y() / 2) - std::floor(p.y() - dy.y() / 2));
    EXPECT_NEAR(second(*checker, SurfacePoint(p, dx, dy)), bruteForce(*checker, p, dx, dy, n, n),
                0.5 * edges / n + 1e-6);
  }
}

// A skewed footprint is averaged over its axis-aligned bounding box (the
// documented approximation): the filtered value equals the brute-force average
// over that box (aligned to 1/16 as above), not over the parallelogram.
TEST(PrefilterChecker, SkewedFootprintIsAveragedOverItsBoundingBox) {
  Pair m;
  auto checker = makeCheckerboard(Mat4::Identity(), m.black.get(), m.white.get());
  const Vec3 p(0.75f, 0.375f, 0.5f), dx(0.5f, 0.5f, 0), dy(-0.25f, 0.375f, 0);  // box [0.375, 1.125] x [-0.0625, 0.8125]
  const Vec3 hw = 0.5f * (dx.cwiseAbs() + dy.cwiseAbs());
  const double box = bruteForce(*checker, p, Vec3(2 * hw.x(), 0, 0), Vec3(0, 2 * hw.y(), 0), 768, 896);
  EXPECT_NEAR(second(*checker, SurfacePoint(p, dx, dy)), box, 1e-4);
  // ... which differs from the parallelogram's own average (the approximation is visible).
  EXPECT_GT(std::abs(box - bruteForce(*checker, p, dx, dy, 1024, 1024)), 1e-2);
}

// In 3D (a footprint with extent along all three axes): n = 160 per axis, so
// the grid misplaces up to half a layer at each of the about ten crossing
// planes: tolerance 1e-2.
TEST(PrefilterChecker, ThreeDimensionalBoxMatchesBruteForce) {
  Pair m;
  auto checker = makeCheckerboard(Mat4::Identity(), m.black.get(), m.white.get());
  const Vec3 p(0.2f, -0.35f, 1.1f);
  const Vec3 d[3] = {{1.3f, 0, 0}, {0, 0.9f, 0}, {0, 0, 1.7f}};
  const int n = 160;
  double sum = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const float a = (i + 0.5f) / n - 0.5f, b = (j + 0.5f) / n - 0.5f, c = (k + 0.5f) / n - 0.5f;
        sum += second(*checker, Vec3(p + a * d[0] + b * d[1] + c * d[2]));
      }
  // A footprint has two axes: (1.3, 0, 0.85) and (0, 0.9, 0.85) have the bounding box of half-widths
  // (0.65, 0.45, 0.85), the box integrated above.
  const double filtered = second(*checker, SurfacePoint(p, Vec3(1.3f, 0, 0.85f), Vec3(0, 0.9f, 0.85f)));
  EXPECT_NEAR(filtered, sum / (double(n) * n * n), 1e-2);
}

// With a vanishing footprint the filtered checker is the point-sampled one.
TEST(PrefilterChecker, TinyFootprintGivesThePointValue) {
  Pair m;
  auto checker = makeCheckerboard(Mat4::Identity(), m.black.get(), m.white.get());
  HashRng rng(3);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p(10 * rng.nextFloat() - 5, 10 * rng.nextFloat() - 5, 10 * rng.nextFloat() - 5);
    EXPECT_EQ(second(*checker, SurfacePoint(p, Vec3(1e-5f, 0, 0), Vec3(0, 1e-5f, 0))), second(*checker, p))
        << p.transpose();
  }
}

// Frequency clamping --------------------------------------------------------------

TEST(PrefilterClamping, OctaveWeightKeepsFadesAndDrops) {
  EXPECT_EQ(octaveWeight(1.f, 0.f), 1.f);       // no footprint
  EXPECT_EQ(octaveWeight(1.f, 0.5f), 1.f);      // two footprints per wavelength: kept whole
  EXPECT_EQ(octaveWeight(1.f, 0.25f), 1.f);
  EXPECT_EQ(octaveWeight(1.f, 1.f), 0.f);       // one wavelength per footprint: dropped
  EXPECT_EQ(octaveWeight(1.f, 3.f), 0.f);
  EXPECT_NEAR(octaveWeight(1.f, std::sqrt(0.5f)), 0.5f, 1e-6f);  // halfway in log2
}

// With a footprint larger than every wavelength (octaves and carrier) the
// texture is constant: its mean, 1/2 (Perlin noise has mean 0; sin too).
TEST(PrefilterClamping, FootprintAboveEveryWavelengthGivesTheMean) {
  Pair m;
  auto noise = makeNoise(Mat4::Identity(), m.black.get(), m.white.get(), 5);
  auto marble = makeMarble(Mat4::Identity(), m.black.get(), m.white.get(), 5, 8.f, 3.f);
  auto wood = makeWood(Mat4::Identity(), m.black.get(), m.white.get(), 4, 10.f, 2.f);
  HashRng rng(9);
  for (int k = 0; k < 100; ++k) {
    const Vec3 p(6 * rng.nextFloat() - 3, 6 * rng.nextFloat() - 3, 6 * rng.nextFloat() - 3);
    const SurfacePoint wide(p, Vec3(2.f, 0.3f, 0), Vec3(0, 0.4f, 1.5f));  // width >= 1, x and radial extent > 2 pi / 8
    EXPECT_EQ(second(*noise, wide), 0.5);
    EXPECT_EQ(second(*marble, wide), 0.5);
    EXPECT_EQ(second(*wood, wide), 0.5);
  }
}

// With a footprint far below the finest octave (and the carrier) the texture
// is exactly the unfiltered one.
TEST(PrefilterClamping, FootprintFarBelowTheFinestOctaveIsExactlyUnfiltered) {
  Pair m;
  Mat4 t = scaleTranslate(3.f, Vec3(0, 0.37f, 0));
  auto noise = makeNoise(t, m.black.get(), m.white.get(), 5);       // finest wavelength 1/16 in texture space
  auto marble = makeMarble(t, m.black.get(), m.white.get(), 5, 8.f, 3.f);
  auto wood = makeWood(t, m.black.get(), m.white.get(), 5, 10.f, 2.f);
  HashRng rng(21);
  for (int k = 0; k < 300; ++k) {
    const Vec3 p(6 * rng.nextFloat() - 3, 6 * rng.nextFloat() - 3, 6 * rng.nextFloat() - 3);
    const SurfacePoint narrow(p, Vec3(4e-3f, 0, 1e-3f), Vec3(0, 3e-3f, -2e-3f));  // 3 x 4e-3 < 1/32
    for (const Material* mat : {noise.get(), marble.get(), wood.get()})
      EXPECT_EQ(second(*mat, narrow), second(*mat, p)) << mat->describe() << " at " << p.transpose();
  }
}

// Between the limits the noise loses contrast as the footprint grows: the
// variance of the weight over many points decreases monotonically.
TEST(PrefilterClamping, NoiseContrastFallsAsTheFootprintGrows) {
  Pair m;
  auto noise = makeNoise(Mat4::Identity(), m.black.get(), m.white.get(), 6);
  double previous = 1e9;
  for (float width : {0.f, 0.02f, 0.06f, 0.2f, 0.6f, 1.f}) {
    HashRng rng(4);
    double s = 0, s2 = 0;
    const int n = 4000;
    for (int k = 0; k < n; ++k) {
      const Vec3 p(20 * rng.nextFloat(), 20 * rng.nextFloat(), 20 * rng.nextFloat());
      const double w = second(*noise, SurfacePoint(p, Vec3(width, 0, 0), Vec3(0, width, 0)));
      s += w, s2 += w * w;
    }
    const double variance = s2 / n - (s / n) * (s / n);
    EXPECT_LT(variance, previous) << "width " << width;
    previous = variance;
  }
  EXPECT_LT(previous, 1e-12);  // width 1: every octave dropped
}

// Analytic patterns ---------------------------------------------------------------

TEST(PrefilterPatterns, SineIntegralMatchesNumericalIntegration) {
  for (double x : {0.3, 1.0, 3.14159, 7.5, 19.9, 20.1, 35.0, 120.0, -4.0}) {
    // Simpson's rule on sin(u)/u over [0, x], 200000 intervals (error ~1e-15 here).
    const int n = 200000;
    const double h = x / n;
    auto f = [](double u) { return u == 0 ? 1.0 : std::sin(u) / u; };
    double s = f(0) + f(x);
    for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * f(i * h);
    EXPECT_NEAR(sineIntegral(x), s * h / 3, 1e-8) << "x = " << x;
  }
}

// Stripes and sinc: exact box averages, against the brute-force average.
TEST(PrefilterPatterns, StripesAndSincMatchBruteForceOverTheBox) {
  Pair m;
  auto stripes = makePattern(Mat4::Identity(), m.black.get(), m.white.get(), PatternKind::Stripes, 4.f);
  auto sinc = makePattern(Mat4::Identity(), m.black.get(), m.white.get(), PatternKind::Sinc, 5.f);
  struct Case { Vec3 p, dx, dy; };
  // Stripe edges at multiples of 1/8 and box ends at multiples of 1/64: a grid of spacing 1/1024 along x
  // is exact for the step function (as for the checker); the sinc is smooth, 1024 x 1024 suffices.
  for (const Case& c : {Case{{0.125f, 0.3f, 0}, {0.4375f, 0, 0}, {0, 0.2f, 0}},
                        Case{{-1.03125f, 2.f, 0}, {1.375f, 0, 0}, {0, 0.5f, 0}},
                        Case{{0.046875f, -0.02f, 0}, {0.09375f, 0, 0}, {0, 0.13f, 0}}}) {
    const int nx = static_cast<int>(std::lround(c.dx.x() * 1024));
    EXPECT_NEAR(second(*stripes, SurfacePoint(c.p, c.dx, c.dy)), bruteForce(*stripes, c.p, c.dx, c.dy, nx, 8), 1e-4);
    EXPECT_NEAR(second(*sinc, SurfacePoint(c.p, c.dx, c.dy)), bruteForce(*sinc, c.p, c.dx, c.dy, 1024), 1e-4);
  }
}

// Zone plate and Siemens star: local linearisation of the phase. Where the
// phase is nearly linear across the footprint the band-limited value matches
// the brute-force box average; where the footprint holds many periods both
// are 1/2.
TEST(PrefilterPatterns, ZonePlateAndSiemensBandLimitedAsStated) {
  Pair m;
  auto zone = makePattern(Mat4::Identity(), m.black.get(), m.white.get(), PatternKind::ZonePlate, 20.f);
  auto star = makePattern(Mat4::Identity(), m.black.get(), m.white.get(), PatternKind::Siemens, 12.f);
  // Zone plate at r ~ 1: local frequency 2 f r / (2 pi) ~ 6 cycles per unit; footprint 0.05.
  const Vec3 p(0.8f, 0.6f, 0), dx(0.05f, 0, 0), dy(0, 0.05f, 0);
  EXPECT_NEAR(second(*zone, SurfacePoint(p, dx, dy)), bruteForce(*zone, p, dx, dy, 512), 2e-3);
  // Siemens star at r = 2 (period 2 pi r / 12 ~ 1.05), footprint 0.3 x 0.3.
  const Vec3 q(1.2f, 1.6f, 0), ex(0.3f, 0, 0), ey(0, 0.3f, 0);
  EXPECT_NEAR(second(*star, SurfacePoint(q, ex, ey)), bruteForce(*star, q, ex, ey, 2048), 1e-2);
  // Many periods inside the footprint: 1/2 within a few per cent.
  const Vec3 far(6.f, 1.f, 0), big(1.5f, 0, 0), bigY(0, 1.5f, 0);
  EXPECT_NEAR(second(*zone, SurfacePoint(far, big, bigY)), 0.5, 0.02);
  EXPECT_NEAR(bruteForce(*zone, far, big, bigY, 1024), 0.5, 0.02);
  EXPECT_NEAR(second(*star, SurfacePoint(Vec3(0.01f, 0.02f, 0), big, bigY)), 0.5, 0.02);
}

// Footprints ------------------------------------------------------------------

// A plane n.x = c seen from a pinhole at o: the hit through unnormalised direction
// v(s) is x(s) = o + c' v / (n.v), c' = c - n.o, so
// dx/ds = c' (dv (n.v) - v (n.dv)) / (n.v)^2, with v = D + (2sx - 1) tan(A/2) H + (2sy - 1) tan(A/2) U
// (camera.h) and ds/dfx = 1 / max(width, height).
TEST(PrefilterFootprint, PinholeFootprintOnAPlaneMatchesTheAnalyticFootprint) {
  const Vec3 center(0.3f, 1.2f, 4.f), dir(0.1f, -0.35f, -1.f), up(0, 1, 0);
  const float angle = 50.f;
  auto camera = makePerspectiveCamera(center, dir, up, angle);
  const Vec3 n = Vec3(0.1f, 1.f, 0.2f).normalized();
  const float c = -0.2f;
  const int width = 160, height = 120;
  // The camera's frame, as camera.h defines it.
  const Vec3 D = dir.normalized();
  const Vec3 U = (up - up.dot(D) * D).normalized();
  const Vec3 H = D.cross(U);
  const double tanHalf = std::tan(0.5 * angle * kPi / 180.0);
  for (const auto& [fx, fy] : {std::pair{80.5f, 60.5f}, std::pair{3.25f, 10.7f}, std::pair{150.5f, 40.1f},
                               std::pair{20.f, 59.9f}}) {
    const Vec2 s = filmToScreen(fx, fy, width, height);
    const Ray ray = camera->generateRay(s);
    const float t = (c - n.dot(ray.origin)) / n.dot(ray.direction);
    ASSERT_GT(t, 0.f);
    Vec3 dpdx, dpdy;
    footprintAt(primaryFootprint(*camera, fx, fy, width, height), ray, t, n, dpdx, dpdy);

    const Eigen::Vector3d v = (D + (2 * s.x() - 1) * tanHalf * H + (2 * s.y() - 1) * tanHalf * U).cast<double>();
    const Eigen::Vector3d nd = n.cast<double>();
    const double cp = c - nd.dot(center.cast<double>());
    const double side = std::max(width, height);
    auto analytic = [&](const Vec3& axis) {
      const Eigen::Vector3d dv = (2 * tanHalf / side) * axis.cast<double>();
      return Eigen::Vector3d(cp * (dv * nd.dot(v) - v * nd.dot(dv)) / (nd.dot(v) * nd.dot(v)));
    };
    const Eigen::Vector3d ax = analytic(H), ay = analytic(U);
    EXPECT_LT((dpdx.cast<double>() - ax).norm(), 1e-4 * ax.norm()) << fx << "," << fy;
    EXPECT_LT((dpdy.cast<double>() - ay).norm(), 1e-4 * ay.norm()) << fx << "," << fy;
    // The footprint lies in the plane.
    EXPECT_NEAR(dpdx.dot(n), 0.f, 1e-5f * dpdx.norm());
    EXPECT_NEAR(dpdy.dot(n), 0.f, 1e-5f * dpdy.norm());
  }
}

// Facing the plane head-on, a pixel covers a square of side 2 d tan(A/2) / width
// at distance d; orthographically, size / width whatever the distance.
TEST(PrefilterFootprint, FrontoParallelPixelIsASquareOfTheExpectedSide) {
  auto pinhole = makePerspectiveCamera(Vec3(0, 0, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 60.f);
  const int w = 100;
  const Ray ray = pinhole->generateRay(filmToScreen(50.f, 50.f, w, w));
  Vec3 dx, dy;
  footprintAt(primaryFootprint(*pinhole, 50.f, 50.f, w, w), ray, 5.f, Vec3::UnitZ(), dx, dy);
  const float side = 2 * 5 * std::tan(30.f * kPi / 180.f) / w;
  EXPECT_NEAR(dx.x(), side, 1e-6f);
  EXPECT_NEAR(dy.y(), side, 1e-6f);
  EXPECT_NEAR(dx.y(), 0.f, 1e-7f);

  auto ortho = makeOrthographicCamera(Vec3(0, 0, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 3.f);
  const Ray r2 = ortho->generateRay(filmToScreen(10.5f, 70.5f, w, w));
  footprintAt(primaryFootprint(*ortho, 10.5f, 70.5f, w, w, 0.5f), r2, 7.f, Vec3::UnitZ(), dx, dy);
  EXPECT_NEAR(dx.x(), 0.5f * 3.f / w, 1e-7f);  // half-pixel samples: half the side
  EXPECT_NEAR(dy.y(), 0.5f * 3.f / w, 1e-7f);
}

// A cone (secondary rays) widens with distance and stretches by 1 / cos at an oblique hit.
TEST(PrefilterFootprint, ConeWidensWithDistanceAndObliquity) {
  RayFootprint cone;
  cone.radius = 0.01f, cone.spread = 0.002f;
  const Ray ray{Vec3::Zero(), Vec3(0, 0, -1)};
  Vec3 dx, dy;
  footprintAt(cone, ray, 10.f, Vec3::UnitZ(), dx, dy);
  EXPECT_NEAR(dx.norm(), 2 * (0.01f + 10 * 0.002f), 1e-6f);
  EXPECT_NEAR(dy.norm(), 2 * (0.01f + 10 * 0.002f), 1e-6f);
  const Vec3 tilted = Vec3(0, std::sin(1.f), std::cos(1.f));  // 1 radian from the ray
  footprintAt(cone, ray, 10.f, tilted, dx, dy);
  const float longer = std::max(dx.norm(), dy.norm()), shorter = std::min(dx.norm(), dy.norm());
  EXPECT_GE(shorter, 2 * 0.03f - 1e-6f);
  EXPECT_GE(longer, 2 * 0.03f / std::cos(1.f) - 1e-4f);
}

// Through a mirror: a camera at the origin looks at a mirror facing it at
// z = -1; the reflected rays come back to a checkerboard at z = 5 whose
// cells (1/200 unit) are far finer than the reflected footprint (a cone of
// radius about 0.2 there). Point-sampled, every pixel is black or white;
// pre-filtered, every pixel is near the mean 1/2.
TEST(PrefilterFootprint, ReflectedRaysCarryAFootprint) {
  const std::string text = R"(
PerspectiveCamera { center 0 0 0 direction 0 0 -1 up 0 1 0 angle 40 }
Background { color 0 0 0 }
Materials {
  numMaterials 4
  PhongMaterial { diffuseColor 0 0 0 reflectiveColor 1 1 1 }
  PhongMaterial { diffuseColor 0 0 0 }
  PhongMaterial { diffuseColor 1 1 1 }
  Checkerboard { Transform { UniformScale 200 } materialIndex 1 materialIndex 2 }
}
Group {
  numObjects 2
  MaterialIndex 0
  Plane { normal 0 0 1 offset -1 }
  MaterialIndex 3
  Plane { normal 0 0 1 offset 5.0013 }
}
)";
  const Scene scene = parseSceneText(text, "mirror", ".");
  const auto aggregate = makeBruteForce(*scene.root);
  TraceOptions plain;
  plain.bounces = 1;
  TraceOptions filtered = plain;
  filtered.prefilter = true;
  const Tracer point(scene, *aggregate, plain), footprint(scene, *aggregate, filtered);
  int n = 0;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i, ++n) {
      const float v = point.radianceAt(i + 0.5f, j + 0.5f, 10, 10)[0];
      EXPECT_TRUE(v == 0.f || v == 1.f) << v;
      EXPECT_NEAR(footprint.radianceAt(i + 0.5f, j + 0.5f, 10, 10)[0], 0.5f, 0.02f) << i << "," << j;
    }
  EXPECT_EQ(n, 100);
}

// End to end -------------------------------------------------------------------

// The horizon checkerboard at 1 spp on pixel centres (uniform sampler: all the
// error is aliasing): pre-filtering must lower aliasing against the same
// target (the un-prefiltered box reference), and the two rows share that
// target (same ref_error). With a jittered sample the footprint sits at a
// random spot of the pixel, so pre-filtering turns noise into a small blur
// (counted as aliasing, a bias that stays put): there the mse and the noise
// must fall, not the aliasing (docs/prefiltering.md).
TEST(PrefilterSweep, PrefilteringLowersAliasingOnTheHorizonCheckerboardAt1Spp) {
  const fs::path dir = aliaslab::testing::scratchDir("aliaslab_prefilter_test");
  const std::string bin = std::string(ALIASLAB_BIN_DIR) + "/sweep";
  const std::string scene = std::string(ALIASLAB_SOURCE_DIR) + "/scenes/checker_horizon.txt";
  const std::string csv = (dir / "study.csv").string();
  const std::string cmd = bin + " --scenes " + scene +
                          " --size 64 64 --samplers uniform,jittered --spp 1 --filters box --radii 0.5 "
                          "--prefilter none,footprint --seeds 4 --ref-spp 256 --threads 2 --quiet --no-images "
                          "--out " + (dir / "out").string() + " --csv " + csv + " --cache " +
                          (dir / "cache").string() + " > " + (dir / "log.txt").string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cmd;
  std::map<std::string, std::vector<std::string>> rows;  // sampler/prefilter -> fields
  for (const std::string& line : readCsvLines(csv)) {
    auto f = splitCsvLine(line);
    rows[f[csvColumn("sampler")] + "/" + f[csvColumn("prefilter")]] = f;
  }
  ASSERT_EQ(rows.size(), 4u);
  auto value = [&](const std::string& key, const char* column) { return std::stod(rows.at(key)[csvColumn(column)]); };
  for (const char* sampler : {"uniform", "jittered"}) {
    const std::string none = std::string(sampler) + "/none", fp = std::string(sampler) + "/footprint";
    EXPECT_EQ(rows.at(none)[csvColumn("ref_error")], rows.at(fp)[csvColumn("ref_error")]) << "same target";
    EXPECT_LT(value(fp, "mse"), 0.5 * value(none, "mse")) << sampler;
  }
  EXPECT_LT(value("uniform/footprint", "aliasing"), 0.2 * value("uniform/none", "aliasing"));
  EXPECT_LT(value("jittered/footprint", "noise"), 0.2 * value("jittered/none", "noise"));
  EXPECT_EQ(value("uniform/footprint", "noise"), 0.0);  // deterministic pattern: all error is aliasing
}

}  // namespace
}  // namespace aliaslab
