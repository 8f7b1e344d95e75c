// Motion measures (measure/motion.h, docs/science.md "Motion"): shimmer of point-sampled gratings against the
// closed form, shimmer of pure noise, flicker of new seeds against twice the noise, and the camera shift.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "accel/aggregate.h"
#include "core/math.h"
#include "measure/motion.h"
#include "render/tracer.h"
#include "scene/scene.h"

namespace aliaslab {
namespace {

std::string gratingScene(double f, double angle) {
  return "OrthographicCamera { center 0 0 1 direction 0 0 -1 up 0 1 0 size 2 }\n"
         "Background { color 1 0 0 }\n"
         "Materials { numMaterials 3 PhongMaterial { diffuseColor 0 0 0 } PhongMaterial { diffuseColor 1 1 1 }\n"
         "Pattern { materialIndex 0 materialIndex 1 type grating frequency " + std::to_string(f) +
         " angle " + std::to_string(angle) + " } }\n"
         "Group { numObjects 1 MaterialIndex 2 Plane { normal 0 0 1 offset 0 } }\n";
}

double sinc(double x) { return x == 0 ? 1 : std::sin(kPi * x) / (kPi * x); }

// Point sampling (one sample at each pixel centre) of a grating at frequency nu = (nx, ny) cycles per pixel,
// frames moving by d pixels, against the pixel-area (box) target: the target is the point value with its
// cosine scaled by A = sinc(nx) sinc(ny), the error is (1 - A) / 2 cos(theta_t), and the frame shift is a
// phase step delta = 2 pi nu . d, so shimmer = (1 - A)^2 sin^2(delta / 2) / 2 (docs/science.md, "Motion").
TEST(Motion, PointSampledGratingMatchesClosedForm) {
  const int N = 32, F = 4;
  const double f = 6, angle = 30;  // 0.375 cycles per pixel at 32 px (16 pixels per unit)
  const double dx = 0.25, dy = 0.1;
  Scene scene = parseSceneText(gratingScene(f, angle), "grating", ".");
  const auto aggregate = makeDefaultAggregate(*scene.root);
  const Tracer tracer(scene, *aggregate, TraceOptions{});
  const std::unique_ptr<Camera> base = std::move(scene.camera);
  const double a = angle * kPi / 180, nx = 2 * f / N * std::cos(a), ny = 2 * f / N * std::sin(a);
  const double A = sinc(nx) * sinc(ny);
  std::vector<std::vector<Image>> images(2, std::vector<Image>(F, Image(N, N)));
  std::vector<Image> target(F, Image(N, N));
  for (int t = 0; t < F; ++t) {
    scene.camera = makeShiftedCamera(*base, frameScreenOffset(t, dx, dy, N, N));
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) {
        const Color c = tracer.radianceAt(i + 0.5f, j + 0.5f, N, N);
        images[0][t].set(i, j, c), images[1][t].set(i, j, c);  // deterministic: two identical "seeds"
        // the pixel's centre in world units, with the frame's shift
        const double x = 2 * (i + 0.5 + t * dx) / N - 1, y = 2 * (j + 0.5 + t * dy) / N - 1;
        const double w = 0.5 + 0.5 * A * std::cos(2 * kPi * f * (x * std::cos(a) + y * std::sin(a)));
        target[t].set(i, j, Color::Constant(static_cast<float>(w)));
      }
  }
  scene.camera.reset();
  std::vector<RefEstimate> targets;
  for (const Image& t : target) targets.push_back({&t, nullptr, 0.5});
  const MotionMetrics m = computeMotionMetrics(images, targets);
  const double delta = 2 * kPi * (nx * dx + ny * dy);
  const double expected = 0.5 * (1 - A) * (1 - A) * std::sin(delta / 2) * std::sin(delta / 2);
  EXPECT_NEAR(m.shimmer, expected, 0.02 * expected);
  EXPECT_NEAR(m.flickerSameSeed, expected, 0.02 * expected);  // no noise: every sequence sees the structure
  EXPECT_GT(expected, 1e-4);
}

// Images T_t + independent noise of variance v: shimmer 0 within 2 se, new-seed flicker 2 v, same-seed 2 v too
// (the noise is independent across frames here).
TEST(Motion, PureNoiseHasNoShimmerAndFlickersTwiceTheNoise) {
  const int N = 16, F = 4, K = 16;
  const double sigma = 0.1, v = sigma * sigma;
  std::mt19937_64 rng(7);
  std::normal_distribution<float> noise(0.f, static_cast<float>(sigma));
  std::vector<Image> target(F, Image(N, N));
  for (int t = 0; t < F; ++t)
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) target[t].set(i, j, Color::Constant(0.5f + 0.4f * std::cos(0.7f * (i + 0.3f * t))));
  std::vector<std::vector<Image>> images(K, target);
  for (auto& seq : images)
    for (Image& im : seq)
      for (int p = 0; p < N * N * 3; ++p) im.data()[p] += noise(rng);
  std::vector<RefEstimate> targets;
  for (const Image& t : target) targets.push_back({&t, nullptr, 0.5});
  const MotionMetrics m = computeMotionMetrics(images, targets);
  EXPECT_LT(std::abs(m.shimmer), 2 * m.shimmerSe) << m.shimmer << " se " << m.shimmerSe;
  EXPECT_GT(m.shimmerSe, 0);
  EXPECT_NEAR(m.flickerNewSeed, 2 * v, 3 * m.flickerNewSeedSe + 1e-12);
  EXPECT_NEAR(m.flickerNewSeed, 2 * v, 0.05 * 2 * v);
  EXPECT_NEAR(m.flickerSameSeed, 2 * v, 0.05 * 2 * v);
}

// A structured error b_t without noise: shimmer = mean (b_{t+1} - b_t)^2 exactly; a constant error none.
TEST(Motion, StructuredErrorChangeIsShimmer) {
  const int N = 8, F = 3, K = 4;
  std::vector<Image> target(F, Image(N, N, Color::Constant(0.5f)));
  std::vector<std::vector<Image>> images(K, std::vector<Image>(F, Image(N, N)));
  for (auto& seq : images)
    for (int t = 0; t < F; ++t) seq[t].fill(Color::Constant(0.5f + 0.125f * t));  // b_t = t / 8
  std::vector<RefEstimate> targets;
  for (const Image& t : target) targets.push_back({&t, nullptr, 0.5});
  EXPECT_NEAR(computeMotionMetrics(images, targets).shimmer, 1.0 / 64, 1e-12);
  for (auto& seq : images)
    for (Image& im : seq) im.fill(Color::Constant(0.75f));
  EXPECT_NEAR(computeMotionMetrics(images, targets).shimmer, 0, 1e-12);
}

TEST(Motion, RefusesTooFewFramesOrSeeds) {
  std::vector<Image> target(2, Image(2, 2));
  std::vector<RefEstimate> targets{{&target[0], nullptr, 0.5}, {&target[1], nullptr, 0.5}};
  EXPECT_THROW(computeMotionMetrics({target}, targets), std::invalid_argument);
  EXPECT_THROW(computeMotionMetrics({target, target}, {targets[0]}), std::invalid_argument);
  EXPECT_THROW(computeMotionMetrics({target, {target[0]}}, targets), std::invalid_argument);
}

// A zero offset leaves every ray bit-identical; an orthographic camera shifted by (dx, dy) pixels starts its
// rays (dx, dy) pixel widths further along its horizontal and up axes.
TEST(Motion, ShiftedCameraIsATranslation) {
  const auto cam = makeOrthographicCamera(Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(0, 1, 0), 2.f);
  const auto same = makeShiftedCamera(*cam, frameScreenOffset(0, 0.25, 0, 64, 32));
  const auto moved = makeShiftedCamera(*cam, frameScreenOffset(3, 0.25, -0.5, 64, 32));
  const Vec2 s = filmToScreen(10.5f, 7.5f, 64, 32);
  EXPECT_EQ(same->generateRay(s).origin, cam->generateRay(s).origin);
  const Vec3 d = moved->generateRay(s).origin - cam->generateRay(s).origin;
  const float pixel = 2.f / 64;  // world units per pixel
  EXPECT_NEAR(d.x(), 3 * 0.25 * pixel, 1e-6);
  EXPECT_NEAR(d.y(), -3 * 0.5 * pixel, 1e-6);
}

}  // namespace
}  // namespace aliaslab
