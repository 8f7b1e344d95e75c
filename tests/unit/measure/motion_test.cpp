// Motion measures in the content's frame (measure/motion.h, measure/registration.h, docs/science.md "Motion"):
// registration of a band-limited moving image is exact away from the border; point-sampled gratings above
// Nyquist against the closed form 2 a^2 sin^2(pi k v) (two frequencies, two speeds), below Nyquist zero; a
// blur that moves with the content scores zero; pure noise has no shimmer and new-seed flicker twice its
// variance; the target's own shimmer; the camera shift.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "accel/aggregate.h"
#include "core/math.h"
#include "measure/motion.h"
#include "measure/registration.h"
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

// A band-limited image (a Gaussian-enveloped sinusoid, negligible above 0.4 cycles per pixel and at the border)
// seen by a camera moved by t (dx, dy): film position p shows what p + t d showed in frame 0.
Image bandLimited(int n, int t, double dx, double dy) {
  Image im(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = i + 0.5 + t * dx - 0.5 * n, y = j + 0.5 + t * dy - 0.5 * n;
      const double g = std::exp(-(x * x + y * y) / (2 * 6.0 * 6.0));
      const double v = g * (0.5 + 0.3 * std::cos(2 * kPi * (0.21 * x + 0.07 * y)));
      im.set(i, j, Color(float(v), float(0.5 * v), float(0.25 * v)));
    }
  return im;
}

TEST(Registration, BandLimitedImageMovedByTheCameraRegistersToItself) {
  const int n = 64;
  for (const auto& [dx, dy] : {std::pair{0.25, 0.0}, {0.3, -0.7}, {1.5, 0.125}}) {
    const Image frame0 = bandLimited(n, 0, dx, dy), frame1 = bandLimited(n, 1, dx, dy);
    const std::vector<double> moved = shiftImage(frame1, dx, dy);
    const int m = registrationMargin(dx, dy);
    double worst = 0;
    for (int j = m; j < n - m; ++j)
      for (int i = m; i < n - m; ++i)
        for (int c = 0; c < 3; ++c) {
          const size_t k = 3 * frame0.index(i, j) + c;
          worst = std::max(worst, std::abs(moved[k] - frame0.data()[k]));
        }
    EXPECT_LT(worst, 1e-6) << dx << "," << dy;
    // unregistered, the frames differ by far more: the test can fail
    EXPECT_GT(std::abs(double(frame1.get(n / 2, n / 2)[0]) - frame0.get(n / 2, n / 2)[0]), 1e-3);
  }
  EXPECT_THROW(shiftImage(Image(4, 4), NAN, 0), std::invalid_argument);
}

// images[k][t] of point samples at the pixel centres of a grating of nu cycles per pixel along x at n pixels,
// the camera moving (v, 0) pixels per frame; K identical seeds (the samples are deterministic).
std::vector<std::vector<Image>> pointSampledGrating(int n, double nu, double v, int F, int K) {
  Scene scene = parseSceneText(gratingScene(nu * n / 2, 0), "grating", ".");
  const auto aggregate = makeDefaultAggregate(*scene.root);
  const Tracer tracer(scene, *aggregate, TraceOptions{});
  const std::unique_ptr<Camera> base = std::move(scene.camera);
  std::vector<Image> frames(F, Image(n, n));
  for (int t = 0; t < F; ++t) {
    scene.camera = makeShiftedCamera(*base, frameScreenOffset(t, v, 0, n, n));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) frames[t].set(i, j, tracer.radianceAt(i + 0.5f, j + 0.5f, n, n));
  }
  scene.camera.reset();
  return std::vector<std::vector<Image>>(K, frames);
}

// Above Nyquist the grating appears at the folded frequency nu - k (k = round(nu)) with amplitude a = 1/2, and
// its phase in the content's frame turns by 2 pi k v per frame: shimmer = 2 a^2 sin^2(pi k v). The interior
// (68 - 2 x 9 = 50 pixels) holds whole periods of the folded sinusoids, so the mean of cos^2 is 1/2 exactly.
TEST(Motion, PointSampledGratingAboveNyquistMatchesClosedForm) {
  const int n = 68;
  for (double nu : {0.9, 0.8})
    for (double v : {0.25, 0.5}) {
      const double expected = 2 * 0.25 * std::pow(std::sin(kPi * std::round(nu) * v), 2);
      const MotionMetrics m = computeMotionMetrics(pointSampledGrating(n, nu, v, 3, 2), v, 0);
      EXPECT_NEAR(m.shimmer, expected, 0.02 * expected) << "nu " << nu << " v " << v;
      EXPECT_NEAR(m.flickerSameSeed, expected, 0.02 * expected);  // no noise: every sequence sees the structure
    }
}

// Below Nyquist (k = 0) the point samples are the grating itself, band-limited: nothing changes once registered
// but the border's interpolation error (the mirror extension's slope jump, ~1e-6 in mean square at 8 pixels
// guard here), although the unregistered frames change by 4 orders of magnitude more.
TEST(Motion, GratingBelowNyquistHasNoShimmer) {
  const auto images = pointSampledGrating(64, 0.375, 0.25, 3, 2);
  EXPECT_LT(computeMotionMetrics(images, 0.25, 0).shimmer, 3e-6);
  EXPECT_GT(computeMotionMetrics(images, 0, 0).shimmer, 1e-2);  // registered as if still: the motion is seen
}

// A shift-invariant blur of moving content moves with it: the blurred band-limited image scores zero, however
// wide the blur, and so does a steady offset added to every frame.
TEST(Motion, BlurAndSteadyOffsetMovingWithTheContentDoNotShimmer) {
  const int n = 64, F = 3;
  const double dx = 0.3, dy = 0.2;
  std::vector<std::vector<Image>> images(2, std::vector<Image>(F));
  for (int t = 0; t < F; ++t) {
    // the picture blurred by [1 2 1] / 4 along x and y (borders clamped, inside the margin), plus 0.1
    const Image a = bandLimited(n, t, dx, dy);
    Image b(n, n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        Color sum = Color::Constant(0.1f);
        for (int v = -1; v <= 1; ++v)
          for (int u = -1; u <= 1; ++u)
            sum += a.get(std::clamp(i + u, 0, n - 1), std::clamp(j + v, 0, n - 1)) * float((2 - std::abs(u)) *
                                                                                          (2 - std::abs(v)) / 16.0);
        b.set(i, j, sum);
      }
    images[0][t] = images[1][t] = b;
  }
  EXPECT_LT(computeMotionMetrics(images, dx, dy).shimmer, 1e-10);
}

// Frames of a band-limited moving image plus independent noise of variance s2 per seed and frame: shimmer 0
// within 2 se; new-seed flicker 2 s2 (the interpolation keeps white noise's variance but for its Nyquist bin).
TEST(Motion, PureNoiseHasNoShimmerAndNewSeedFlickerTwiceTheNoise) {
  const int n = 48, F = 4, K = 16;
  const double dx = 0.25, dy = 0.1, sigma = 0.1, s2 = sigma * sigma;
  std::mt19937_64 rng(7);
  std::normal_distribution<float> noise(0.f, static_cast<float>(sigma));
  std::vector<std::vector<Image>> images(K, std::vector<Image>(F));
  for (int t = 0; t < F; ++t) {
    const Image clean = bandLimited(n, t, dx, dy);
    for (int k = 0; k < K; ++k) {
      images[k][t] = clean;
      for (int p = 0; p < n * n * 3; ++p) images[k][t].data()[p] += noise(rng);
    }
  }
  const MotionMetrics m = computeMotionMetrics(images, dx, dy);
  EXPECT_LT(std::abs(m.shimmer), 2 * m.shimmerSe) << m.shimmer << " se " << m.shimmerSe;
  EXPECT_GT(m.shimmerSe, 0);
  EXPECT_NEAR(m.flickerNewSeed, 2 * s2, 0.05 * 2 * s2);
  EXPECT_NEAR(m.flickerSameSeed, 2 * s2, 0.05 * 2 * s2);
}

// The target's own shimmer: the point-sampled grating above Nyquist as a target without halves scores the closed
// form; a half-difference's registered change is subtracted as the target's noise.
TEST(Motion, TargetShimmerIsTheTargetsRegisteredChange) {
  const int n = 68;
  const double v = 0.25, expected = 0.5 * std::pow(std::sin(kPi * v), 2);
  const std::vector<Image> frames = pointSampledGrating(n, 0.9, v, 3, 1)[0];
  std::vector<RefEstimate> T;
  for (const Image& f : frames) T.push_back({&f, nullptr, 0.5});
  EXPECT_NEAR(targetShimmer(T, v, 0), expected, 0.02 * expected);
  std::vector<Image> halves(3, Image(n, n));
  for (int t = 0; t < 3; ++t) halves[t].fill(Color::Constant(t % 2 ? 0.1f : -0.1f));  // change 0.2 -> 0.04
  for (int t = 0; t < 3; ++t) T[t].halfDiff = &halves[t];
  EXPECT_NEAR(targetShimmer(T, v, 0), expected - 0.04, 0.02 * expected);
}

TEST(Motion, RefusesTooFewFramesOrSeedsAndTooSmallImages) {
  const std::vector<Image> two(2, Image(32, 32));
  EXPECT_THROW(computeMotionMetrics({two}, 0.25, 0), std::invalid_argument);
  EXPECT_THROW(computeMotionMetrics({{two[0]}, {two[0]}}, 0.25, 0), std::invalid_argument);
  EXPECT_THROW(computeMotionMetrics({two, {two[0]}}, 0.25, 0), std::invalid_argument);
  EXPECT_NO_THROW(computeMotionMetrics({two, two}, 0.25, 0));
  EXPECT_THROW(computeMotionMetrics({two, two}, 8, 0), std::invalid_argument);  // margin 16: nothing inside
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
