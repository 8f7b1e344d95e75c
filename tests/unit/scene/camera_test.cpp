// Cameras and the film-to-screen map, against rays worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "render/tracer.h"
#include "scene/camera.h"
#include "scene/light.h"
#include "scene/material.h"

namespace aliaslab {
namespace {

constexpr float kTol = 1e-5f;

void expectVec(const Vec3& got, const Vec3& want) {
  EXPECT_NEAR((got - want).norm(), 0.f, kTol) << "got " << got.transpose() << " want " << want.transpose();
}

// Looking down -z with up +y: horizontal = (-z) x y = +x. Size 4: the screen
// corners sit 2 units off the centre along x and y. D is normalised.
TEST(OrthographicCamera, CentreAndCornersOfTheScreenSquare) {
  auto cam = makeOrthographicCamera(Vec3(1, 2, 10), Vec3(0, 0, -5), Vec3::UnitY(), 4.f);
  EXPECT_TRUE(std::isinf(cam->tMin()) && cam->tMin() < 0);
  Ray r = cam->generateRay(Vec2(0.5f, 0.5f));
  expectVec(r.origin, Vec3(1, 2, 10));
  expectVec(r.direction, Vec3(0, 0, -1));
  expectVec(cam->generateRay(Vec2(0, 0)).origin, Vec3(-1, 0, 10));
  expectVec(cam->generateRay(Vec2(1, 1)).origin, Vec3(3, 4, 10));
  expectVec(cam->generateRay(Vec2(1, 0)).origin, Vec3(3, 0, 10));
  expectVec(cam->generateRay(Vec2(0.25f, 0.75f)).direction, Vec3(0, 0, -1));
}

// Direction +x with up (1, 1, 0): Gram-Schmidt leaves up = +y, so horizontal
// = x cross y = +z and the screen top edge lies size/2 above the centre.
TEST(OrthographicCamera, GramSchmidtOfNonPerpendicularUp) {
  auto cam = makeOrthographicCamera(Vec3::Zero(), Vec3(2, 0, 0), Vec3(1, 1, 0), 2.f);
  expectVec(cam->generateRay(Vec2(0.5f, 1.f)).origin, Vec3(0, 1, 0));
  expectVec(cam->generateRay(Vec2(1.f, 0.5f)).origin, Vec3(0, 0, 1));
  expectVec(cam->generateRay(Vec2(0.5f, 1.f)).direction, Vec3(1, 0, 0));
}

// A 90 degree field of view: tan 45 = 1, so the corner (1, 1) looks along
// (1, 1, -1)/sqrt3 and the left edge midpoint along (-1, 0, -1)/sqrt2.
TEST(PerspectiveCamera, RaysThroughCentreCornersAndEdges) {
  auto cam = makePerspectiveCamera(Vec3(0, 1, 5), Vec3(0, 0, -3), Vec3::UnitY(), 90.f);
  EXPECT_EQ(cam->tMin(), 0.f);
  Ray r = cam->generateRay(Vec2(0.5f, 0.5f));
  expectVec(r.origin, Vec3(0, 1, 5));
  expectVec(r.direction, Vec3(0, 0, -1));
  expectVec(cam->generateRay(Vec2(1, 1)).direction, Vec3(1, 1, -1).normalized());
  expectVec(cam->generateRay(Vec2(0, 0.5f)).direction, Vec3(-1, 0, -1).normalized());
  expectVec(cam->generateRay(Vec2(0, 0)).origin, Vec3(0, 1, 5));
  // 60 degrees: the right edge midpoint is 30 degrees off the axis.
  auto narrow = makePerspectiveCamera(Vec3::Zero(), Vec3(0, 0, -1), Vec3(0, 1, 1), 60.f);
  const Vec3 d = narrow->generateRay(Vec2(1, 0.5f)).direction;
  EXPECT_NEAR(std::acos(d.dot(Vec3(0, 0, -1))), kPi / 6, kTol);
  expectVec(d, Vec3(std::sin(kPi / 6), 0, -std::cos(kPi / 6)));
}

// 400 x 200: the width spans 0..1, the height sees the middle half 0.25..0.75.
TEST(FilmToScreen, NonSquareImageSeesTheMiddleOfTheSquare) {
  const Vec2 centre = filmToScreen(200, 100, 400, 200);
  EXPECT_NEAR(centre.x(), 0.5f, kTol);
  EXPECT_NEAR(centre.y(), 0.5f, kTol);
  const Vec2 lo = filmToScreen(0, 0, 400, 200), hi = filmToScreen(400, 200, 400, 200);
  EXPECT_NEAR(lo.x(), 0.f, kTol);
  EXPECT_NEAR(lo.y(), 0.25f, kTol);
  EXPECT_NEAR(hi.x(), 1.f, kTol);
  EXPECT_NEAR(hi.y(), 0.75f, kTol);
  // Tall images: the same with the axes swapped; square ones span 0..1 on both.
  const Vec2 tall = filmToScreen(0, 0, 200, 400);
  EXPECT_NEAR(tall.x(), 0.25f, kTol);
  EXPECT_NEAR(tall.y(), 0.f, kTol);
  EXPECT_NEAR(filmToScreen(3, 9, 12, 12).y(), 0.75f, kTol);
}

TEST(Camera, DegenerateFrameIsAnInputError) {
  EXPECT_THROW(makeOrthographicCamera(Vec3::Zero(), Vec3(0, 0, -1), Vec3(0, 0, 2), 1.f), InputError);
  EXPECT_THROW(makePerspectiveCamera(Vec3::Zero(), Vec3::Zero(), Vec3::UnitY(), 45.f), InputError);
}

// One-line descriptions name the kind and the parameters (after normalisation).
TEST(Describe, OneLineWithKindAndParameters) {
  EXPECT_EQ(makePerspectiveCamera(Vec3(0, 1, 5), Vec3(0, 0, -2), Vec3::UnitY(), 40.f)->describe(),
            "perspective center (0 1 5) direction (0 0 -1) up (0 1 0) angle 40");
  EXPECT_EQ(makeOrthographicCamera(Vec3::Zero(), Vec3(0, 0, -1), Vec3::UnitY(), 2.5f)->describe(),
            "orthographic center (0 0 0) direction (0 0 -1) up (0 1 0) size 2.5");
  EXPECT_EQ(makePointLight(Vec3(1, 2, 3), Color(1, 1, 0.5f), 1, 0, 0.25f)->describe(),
            "point position (1 2 3) color (1 1 0.5) attenuation (1 0 0.25)");
  EXPECT_EQ(makeDirectionalLight(Vec3(0, -2, 0), Color::Ones())->describe(),
            "directional direction (0 -1 0) color (1 1 1)");
  auto a = makePhong({}), b = makePhong({.diffuse = Color::Zero(), .exponent = 20});
  EXPECT_EQ(makeCheckerboard(Mat4::Identity(), a.get(), b.get())->describe(),
            "checkerboard [phong diffuse (1 1 1) specular (0 0 0) exponent 1 reflective (0 0 0) transparent (0 0 0) "
            "ior 1 | phong diffuse (0 0 0) specular (0 0 0) exponent 20 reflective (0 0 0) transparent (0 0 0) ior 1]");
  EXPECT_EQ(makeMarble(2 * Mat4::Identity(), a.get(), b.get(), 3, 9, 2)->describe().substr(0, 54),
            "marble octaves 3 frequency 9 amplitude 2 transformed [");
  TraceOptions o;
  o.shadows = true, o.bounces = 5, o.weight = 0.01f, o.shadeBack = true;
  EXPECT_EQ(o.describe(), "shadows bounces 5 weight 0.01 shade_back epsilon 0.001");
}

}  // namespace
}  // namespace aliaslab
