// Lights, Blinn-Phong and the Whitted tracer (and whole-image rendering) against values
// derived by hand (each expected number is worked out in the comment above it).
#include <gtest/gtest.h>

#include "core/parallel.h"

#include <cmath>
#include <cstring>

#include "accel/aggregate.h"
#include "core/hash.h"
#include "render/render.h"

namespace aliaslab {
namespace {

constexpr float kTol = 1e-5f;

void expectColor(const Color& got, const Color& want, float tol = kTol) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tol) << "channel " << c;
}

/// A scene built in code: add materials and objects, then call finish().
struct TestScene {
  Scene scene;
  ObjectList objects;
  std::unique_ptr<Aggregate> aggregate;

  const Material* phong(const PhongParams& p) {
    scene.materials.push_back(makePhong(p));
    return scene.materials.back().get();
  }
  const Material* add(std::unique_ptr<Material> m) {
    scene.materials.push_back(std::move(m));
    return scene.materials.back().get();
  }
  void plane(const Vec3& n, float d, const Material* m) { objects.push_back(std::make_unique<Plane>(n, d, m)); }
  void sphere(const Vec3& c, float r, const Material* m) { objects.push_back(std::make_unique<Sphere>(c, r, m)); }
  Tracer finish(const TraceOptions& options) {
    scene.root = std::make_unique<Group>(std::move(objects));
    aggregate = makeBruteForce(*scene.root);
    return Tracer(scene, *aggregate, options);
  }
};

Color traceRay(const Tracer& tracer, const Vec3& origin, const Vec3& direction) {
  Hit hit;
  return tracer.trace(Ray{origin, direction.normalized()}, 0.f, 0, 1.f, 1.f, hit);
}

/// Diffuse colour = world position (x, y, z): shows where a ray ended up.
class PositionMaterial final : public Material {
 public:
  Color shade(const SurfacePoint&, const Vec3&, const Vec3&, const Vec3&, const Color&) const override {
    return Color::Zero();
  }
  Color diffuse(const SurfacePoint& s) const override { return s.p.array(); }
  Color reflective(const SurfacePoint&) const override { return Color::Zero(); }
  Color transparent(const SurfacePoint&) const override { return Color::Zero(); }
  float indexOfRefraction(const SurfacePoint&) const override { return 1.f; }
  std::string describe() const override { return "position"; }
};

// Blinn-Phong ------------------------------------------------------------

// Light at 45 degrees from the normal: n.l = cos 45; colour = ambient kd + kd lc cos 45.
TEST(Shading, LambertPlaneUnderDirectionalLight) {
  TestScene t;
  const Color kd(0.8f, 0.6f, 0.4f), lc(1.f, 0.5f, 1.f), ambient(0.1f, 0.2f, 0.3f);
  t.plane(Vec3::UnitY(), 0.f, t.phong({.diffuse = kd}));
  t.scene.ambient = ambient;
  t.scene.lights.push_back(makeDirectionalLight(Vec3(-1, -1, 0), lc));
  const Tracer tracer = t.finish({});
  expectColor(traceRay(tracer, Vec3(0.3f, 1, 0.2f), -Vec3::UnitY()), ambient * kd + kd * lc * std::sqrt(0.5f));
}

// Viewer and light mirrored about n: h = n, n.h = 1, specular term = ks whatever the exponent.
TEST(Shading, BlinnPhongPeakAtMirrorConfiguration) {
  TestScene t;
  const Color ks(0.5f, 1.f, 0.25f), lc(0.6f, 0.8f, 1.f);
  t.plane(Vec3::UnitY(), 0.f, t.phong({.diffuse = Color::Zero(), .specular = ks, .exponent = 40.f}));
  t.scene.lights.push_back(makeDirectionalLight(Vec3(-1, -1, 0), lc));  // towards the light: (1,1,0)/sqrt2
  const Tracer tracer = t.finish({});
  // Eye at (-1, 1, 0) looking at the origin: towards the viewer (-1,1,0)/sqrt2.
  expectColor(traceRay(tracer, Vec3(-1, 1, 0), Vec3(1, -1, 0)), ks * lc);
}

// Viewer along n, light at 45 degrees: h bisects them at 22.5 degrees from n,
// shade = lc (kd cos45 + ks cos(22.5)^e).
TEST(Shading, BlinnPhongAtKnownHalfAngle) {
  const Color kd(0.2f, 0.3f, 0.4f), ks(1.f, 0.5f, 0.25f), lc(1.f, 1.f, 0.5f);
  const float e = 8.f;
  auto m = makePhong({.diffuse = kd, .specular = ks, .exponent = e});
  const Vec3 toLight = Vec3(1, 1, 0).normalized();
  const Color got = m->shade(Vec3::Zero(), Vec3::UnitY(), Vec3::UnitY(), toLight, lc);
  const float c45 = std::cos(kPi / 4), c225 = std::cos(kPi / 8);
  expectColor(got, lc * (kd * c45 + ks * std::pow(c225, e)));
  // A light below the surface contributes nothing.
  expectColor(m->shade(Vec3::Zero(), Vec3::UnitY(), Vec3::UnitY(), -toLight, lc), Color::Zero());
}

// Point light 2 above the surface, attenuation 1 + 0.5 d + 0.25 d^2 = 3 at d = 2.
TEST(Shading, PointLightAttenuationAtKnownDistance) {
  auto light = makePointLight(Vec3(0, 2, 0), Color(3, 6, 9), 1.f, 0.5f, 0.25f);
  Vec3 toLight;
  Color c;
  float d;
  light->illuminate(Vec3::Zero(), toLight, c, d);
  EXPECT_NEAR(d, 2.f, kTol);
  EXPECT_NEAR((toLight - Vec3::UnitY()).norm(), 0.f, kTol);
  expectColor(c, Color(1, 2, 3));

  TestScene t;
  const Color kd(0.5f, 0.5f, 1.f);
  t.plane(Vec3::UnitY(), 0.f, t.phong({.diffuse = kd}));
  t.scene.lights.push_back(std::move(light));
  const Tracer tracer = t.finish({});
  expectColor(traceRay(tracer, Vec3(0, 1, 0), -Vec3::UnitY()), kd * Color(1, 2, 3));  // n.l = 1

  auto directional = makeDirectionalLight(Vec3(0, 0, -2), Color::Ones());
  directional->illuminate(Vec3(5, 5, 5), toLight, c, d);
  EXPECT_TRUE(std::isinf(d));
  EXPECT_NEAR((toLight - Vec3::UnitZ()).norm(), 0.f, kTol);
}

// A sphere between the point and the light: with -shadows only ambient kd remains.
TEST(Shading, ShadowedPointKeepsOnlyAmbient) {
  for (bool shadows : {false, true}) {
    TestScene t;
    const Color kd(0.5f, 0.6f, 0.7f), ambient(0.2f, 0.2f, 0.2f);
    const Material* m = t.phong({.diffuse = kd});
    t.plane(Vec3::UnitY(), 0.f, m);
    t.sphere(Vec3(0, 2, 0), 0.5f, t.phong({.transparent = Color::Ones(), .indexOfRefraction = 1.f}));
    t.scene.ambient = ambient;
    t.scene.lights.push_back(makePointLight(Vec3(0, 4, 0), Color::Ones()));
    TraceOptions o;
    o.shadows = shadows;
    const Tracer tracer = t.finish(o);
    // A slanted eye ray reaches the plane point under the sphere without touching the sphere.
    const Color got = traceRay(tracer, Vec3(-3, 1, 0), Vec3(3, -1, 0));
    expectColor(got, shadows ? Color(ambient * kd) : Color(ambient * kd + kd));
    EXPECT_EQ(tracer.counters().total().shadow, shadows ? 1u : 0u);
  }
}

// No lights at all: flat diffuse colour; a miss: the background.
TEST(Shading, FlatColourWithoutLightsAndBackgroundOnMiss) {
  TestScene t;
  t.plane(Vec3::UnitY(), 0.f, t.phong({.diffuse = Color(0.1f, 0.2f, 0.3f)}));
  t.scene.ambient = Color::Constant(0.5f);
  t.scene.background = Color(0.9f, 0.8f, 0.7f);
  const Tracer tracer = t.finish({});
  expectColor(traceRay(tracer, Vec3(0, 1, 0), Vec3(1, -1, 0)), Color(0.1f, 0.2f, 0.3f));
  expectColor(traceRay(tracer, Vec3(0, 1, 0), Vec3(1, 1, 0)), Color(0.9f, 0.8f, 0.7f));
}

// Refraction ---------------------------------------------------------------

// Glass slab 0 > y > -1 (ior 1.5), entered at 30 degrees at the origin. Inside,
// sin t = sin30 / 1.5 = 1/3, so x advances tan t = 1/(2 sqrt2) over the
// thickness; the ray leaves parallel to its entry direction and advances
// 2 tan30 more down to the target plane y = -3, whose colour is its x.
TEST(Refraction, SlabExitsParallelToEntry) {
  TestScene t;
  const Material* glass = t.phong({.diffuse = Color::Zero(), .transparent = Color::Ones(), .indexOfRefraction = 1.5f});
  t.plane(Vec3::UnitY(), 0.f, glass);   // top face, front side up
  t.plane(-Vec3::UnitY(), 1.f, glass);  // bottom face y = -1, front side down
  t.plane(Vec3::UnitY(), -3.f, t.add(std::make_unique<PositionMaterial>()));
  TraceOptions o;
  o.shadeBack = true;
  o.bounces = 2;
  const Tracer tracer = t.finish(o);
  const float s30 = 0.5f, c30 = std::sqrt(3.f) / 2;
  const Color got = traceRay(tracer, Vec3(-s30 / c30, 1, 0), Vec3(s30, -c30, 0));
  const float expectedX = 1.f / (2.f * std::sqrt(2.f)) + 2.f * s30 / c30;
  expectColor(got, Color(expectedX, -3.f, 0.f), 1e-4f);
  EXPECT_EQ(tracer.counters().total().refracted, 2u);

  // The helper directly: out of the slab the direction equals the entry direction.
  Vec3 inside, outside;
  const Vec3 d(s30, -c30, 0);
  ASSERT_TRUE(refractDirection(d, Vec3::UnitY(), 1.f / 1.5f, inside));
  EXPECT_NEAR(inside.x(), 1.f / 3.f, kTol);
  ASSERT_TRUE(refractDirection(inside, Vec3::UnitY(), 1.5f, outside));
  EXPECT_NEAR((outside - d).norm(), 0.f, kTol);
}

// From inside glass (ior 1.5) the critical angle is asin(1/1.5) = 41.8 degrees:
// at 60 degrees nothing is transmitted (black: the glass has no diffuse colour),
// at 30 degrees the ray escapes to the white background.
TEST(Refraction, TotalInternalReflectionTransmitsNothing) {
  Vec3 t;
  EXPECT_FALSE(refractDirection(Vec3(std::sin(1.0472f), std::cos(1.0472f), 0), -Vec3::UnitY(), 1.5f, t));
  for (float degrees : {60.f, 30.f}) {
    TestScene s;
    const Material* glass = s.phong({.diffuse = Color::Zero(), .transparent = Color::Ones(), .indexOfRefraction = 1.5f});
    s.plane(Vec3::UnitY(), 0.f, glass);
    s.scene.background = Color::Ones();
    TraceOptions o;
    o.shadeBack = true;
    o.bounces = 1;
    const Tracer tracer = s.finish(o);
    const float a = degrees * kPi / 180;
    const Color got = traceRay(tracer, Vec3(0, -0.5f, 0), Vec3(std::sin(a), std::cos(a), 0));
    expectColor(got, degrees > 41.9f ? Color::Zero() : Color::Ones());
    EXPECT_EQ(tracer.counters().total().refracted, degrees > 41.9f ? 0u : 1u);
  }
}

// Two facing mirrors (reflective 1/2, flat diffuse 1, no lights): each bounce
// adds half the previous term, so the colour is sum_{k<=b} 2^-k.
TEST(Reflection, BounceLimitAndWeightCutoff) {
  auto build = [](TestScene& t) {
    const Material* mirror = t.phong({.diffuse = Color::Ones(), .reflective = Color::Constant(0.5f)});
    t.plane(Vec3::UnitY(), 0.f, mirror);
    t.plane(-Vec3::UnitY(), -1.f, mirror);  // y = 1, facing down
  };
  for (int bounces : {0, 1, 3, 6}) {
    TestScene t;
    build(t);
    TraceOptions o;
    o.bounces = bounces;
    const Tracer tracer = t.finish(o);
    const float expected = 2.f - std::ldexp(1.f, -bounces);
    expectColor(traceRay(tracer, Vec3(0, 0.5f, 0), Vec3::UnitY()), Color::Constant(expected));
    EXPECT_EQ(tracer.counters().total().reflected, static_cast<uint64_t>(bounces));
  }
  // Weight 0.2: the k-th reflection has weight 2^-k and is traced only while 2^-k >= 0.2 (k = 1, 2).
  TestScene t;
  build(t);
  TraceOptions o;
  o.bounces = 10;
  o.weight = 0.2f;
  const Tracer tracer = t.finish(o);
  expectColor(traceRay(tracer, Vec3(0, 0.5f, 0), Vec3::UnitY()), Color::Constant(1.75f));
  EXPECT_EQ(tracer.counters().total().reflected, 2u);
}

// Rendering ------------------------------------------------------------------

/// Independent uniform points from the hash of (seed, pixel, index).
class HashSampler final : public Sampler {
 public:
  HashSampler(int spp, uint64_t seed) : Sampler(spp, seed) {}
  void generate(int px, int py, Vec2* out) const override {
    HashRng rng(pixelSeed(seed(), px, py));
    for (int k = 0; k < spp(); ++k) out[k] = Vec2(rng.nextFloat(), rng.nextFloat());
  }
  std::string name() const override { return "hash"; }
  std::string describe() const override { return "hash"; }
};

TEST(Render, SamplesBitIdenticalForAnyThreadCount) {
  TestScene t;
  auto red = t.phong({.diffuse = Color(1, 0.1f, 0.1f)});
  auto white = t.phong({.diffuse = Color::Ones(), .reflective = Color::Constant(0.3f)});
  t.plane(Vec3::UnitY(), -1.f, t.add(makeCheckerboard(Mat4::Identity(), red, white)));
  t.sphere(Vec3::Zero(), 1.f, white);
  t.scene.lights.push_back(makePointLight(Vec3(2, 4, 3), Color::Ones()));
  t.scene.camera = makePerspectiveCamera(Vec3(0, 1, 6), Vec3(0, -0.2f, -1), Vec3::UnitY(), 40.f);
  TraceOptions o;
  o.shadows = true;
  o.bounces = 2;
  const Tracer tracer = t.finish(o);
  const HashSampler sampler(3, 11);
  const SampleBuffer one = traceSamples(tracer, sampler, 37, 21, 1);
  int calls = 0;
  const SampleBuffer two = traceSamples(tracer, sampler, 37, 21, 2, [&](int done, int total) {
    ++calls;
    EXPECT_EQ(total, 3 * 2);
  });
  EXPECT_EQ(calls, 6);
  ASSERT_EQ(one.samples().size(), size_t{37 * 21 * 3});
  ASSERT_EQ(two.samples().size(), one.samples().size());
  for (size_t k = 0; k < one.samples().size(); ++k) {
    const FilmSample &a = one.samples()[k], &b = two.samples()[k];
    EXPECT_EQ(std::memcmp(&a, &b, sizeof(FilmSample)), 0) << "sample " << k;
  }
  // Positions lie in their own pixel; the image is not constant.
  const FilmSample* s = one.pixel(5, 7);
  EXPECT_TRUE(s[0].x >= 5 && s[0].x < 6 && s[0].y >= 7 && s[0].y < 8);
  EXPECT_NE(one.pixel(0, 0)[0].L[0], one.pixel(18, 10)[0].L[0]);
}

// Orthographic camera straight down onto planes y = 0 and y = 2 from y = 10:
// depth t = 10 (or 8), grey (dmax - t) / (dmax - dmin); normal |(0,1,0)|.
TEST(Render, DepthAndNormalImages) {
  TestScene t;
  t.plane(Vec3::UnitY(), 0.f, t.phong({}));
  t.scene.camera = makeOrthographicCamera(Vec3(0, 10, 0), -Vec3::UnitY(), Vec3::UnitZ(), 4.f);
  const Tracer tracer = t.finish({});
  const Image depth = renderDepth(tracer, 4, 3, 6.f, 14.f, 2);
  expectColor(depth.get(2, 1), Color::Constant(0.5f));
  const Image normals = renderNormals(tracer, 4, 3, 2);
  expectColor(normals.get(3, 2), Color(0, 1, 0));
}

// Per-thread counters lose no count: 8 threads at once (more threads than
// cores, so they interleave) each add 20000 rays of every kind.
TEST(TraceCounters, ExactAcrossThreads) {
  TraceCounters counters;
  constexpr int kThreads = 8, kEach = 20000;
  parallelFor(kThreads, kThreads, [&](int t) {
    for (int i = 0; i < kEach; ++i) {
      counters.add(TraceCounters::Primary);
      if (i % 2 == 0) counters.add(TraceCounters::Shadow);
      if (t == 0) counters.add(TraceCounters::Refracted);
    }
  });
  const RayCounts c = counters.total();
  EXPECT_EQ(c.primary, uint64_t{kThreads} * kEach);
  EXPECT_EQ(c.shadow, uint64_t{kThreads} * kEach / 2);
  EXPECT_EQ(c.reflected, 0u);
  EXPECT_EQ(c.refracted, uint64_t{kEach});
}

}  // namespace
}  // namespace aliaslab
