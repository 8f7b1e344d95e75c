// Primitives against hand-derived answers; transforms against the
// analytically transformed primitive; the OBJ reader and its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/hash.h"
#include "geometry/primitives.h"

namespace aliaslab {
namespace {

const Material* const kMatA = reinterpret_cast<const Material*>(0x10);  // identity only, never dereferenced

Ray makeRay(Vec3 o, Vec3 d) { return Ray{o, d}; }

Mat4 translation(const Vec3& t) {
  Mat4 m = Mat4::Identity();
  m.topRightCorner<3, 1>() = t;
  return m;
}
Mat4 scaling(const Vec3& s) {
  Mat4 m = Mat4::Identity();
  m.diagonal().head<3>() = s;
  return m;
}
Mat4 rotation(const Vec3& axis, float degrees) {
  Mat4 m = Mat4::Identity();
  m.topLeftCorner<3, 3>() = Eigen::AngleAxisf(degrees * kPi / 180.f, axis.normalized()).toRotationMatrix();
  return m;
}

// ---- Sphere: |o + t d - C|^2 = R^2 -------------------------------------------

TEST(Sphere, NearRootOfQuadraticWithNonUnitDirection) {
  // (-8 + 2t)^2 = 4  =>  t = 3 or 5; the near root, normal pointing back along -z.
  Sphere s({1, 2, 3}, 2.f, kMatA);
  Hit h;
  ASSERT_TRUE(s.intersect(makeRay({1, 2, -5}, {0, 0, 2}), 0.f, h));
  EXPECT_FLOAT_EQ(h.t, 3.f);
  EXPECT_NEAR((h.normal - Vec3(0, 0, -1)).norm(), 0.f, 1e-6f);
  EXPECT_EQ(h.material, kMatA);
}

TEST(Sphere, ObliqueRayMatchesQuadraticFormulaInDouble) {
  const Vec3 c(0.3f, -0.2f, 0.5f), o(-3, 1, 2), d(1.f, -0.25f, -0.3f);
  const float r = 1.2f;
  Sphere s(c, r, kMatA);
  Hit h;
  ASSERT_TRUE(s.intersect(makeRay(o, d), 0.f, h));
  const Eigen::Vector3d oc = (o - c).cast<double>(), dd = d.cast<double>();
  const double A = dd.dot(dd), B = 2 * dd.dot(oc), C = oc.dot(oc) - double(r) * r;
  const double t = (-B - std::sqrt(B * B - 4 * A * C)) / (2 * A);
  EXPECT_NEAR(h.t, t, 1e-5);
  const Eigen::Vector3d n = (oc + t * dd).normalized();
  EXPECT_NEAR((h.normal.cast<double>() - n).norm(), 0.0, 1e-5);
}

TEST(Sphere, FromInsideHitsFarRootWithOutwardNormal) {
  Sphere s({0, 0, 0}, 2.f, kMatA);
  Hit h;
  ASSERT_TRUE(s.intersect(makeRay({0, 0, 0}, {0, 0.5f, 0}), 0.f, h));
  EXPECT_FLOAT_EQ(h.t, 4.f);  // R / |d|
  EXPECT_NEAR((h.normal - Vec3(0, 1, 0)).norm(), 0.f, 1e-6f);
}

TEST(Sphere, TangentRayTouchesAtDoubleRootAndOffsetRayMisses) {
  Sphere s({0, 0, 0}, 1.f, kMatA);
  Hit h;
  ASSERT_TRUE(s.intersect(makeRay({1, 0, -5}, {0, 0, 1}), 0.f, h));  // discriminant exactly 0
  EXPECT_FLOAT_EQ(h.t, 5.f);
  EXPECT_NEAR((h.normal - Vec3(1, 0, 0)).norm(), 0.f, 1e-6f);
  Hit miss;
  EXPECT_FALSE(s.intersect(makeRay({1.001f, 0, -5}, {0, 0, 1}), 0.f, miss));
  EXPECT_FALSE(miss.found());
}

TEST(Sphere, RespectsTminAndCurrentHit) {
  Sphere s({0, 0, 10}, 1.f, kMatA);
  Hit h;
  ASSERT_TRUE(s.intersect(makeRay({0, 0, 0}, {0, 0, 1}), 9.5f, h));  // near root 9 <= tmin
  EXPECT_FLOAT_EQ(h.t, 11.f);
  Hit behind;  // tmin = -inf: the whole line, the root behind the origin counts
  ASSERT_TRUE(s.intersect(makeRay({0, 0, 20}, {0, 0, 1}), -kInf, behind));
  EXPECT_FLOAT_EQ(behind.t, -11.f);
  Hit closer;
  closer.t = 8.f;
  EXPECT_FALSE(s.intersect(makeRay({0, 0, 0}, {0, 0, 1}), 0.f, closer));
  EXPECT_EQ(closer.t, 8.f);
}

// ---- Plane: n.P = d ----------------------------------------------------------

TEST(Plane, HitAtOffsetOverNormalDotDirection) {
  Plane p({0, 2, 0}, 3.f, kMatA);  // 2 y = 3: the plane y = 1.5 (SCENE_FORMAT: n.P = d for the n given)
  Hit h;
  ASSERT_TRUE(p.intersect(makeRay({0, 0, 0}, {1, 0.5f, 0}), 0.f, h));
  EXPECT_FLOAT_EQ(h.t, 3.f);
  EXPECT_EQ(h.normal, Vec3(0, 1, 0));  // geometric normal from either side
  Hit back;
  ASSERT_TRUE(p.intersect(makeRay({0, 10, 0}, {0, -1, 0}), 0.f, back));
  EXPECT_FLOAT_EQ(back.t, 8.5f);
  EXPECT_EQ(back.normal, Vec3(0, 1, 0));
  Hit parallel;
  EXPECT_FALSE(p.intersect(makeRay({0, 0, 0}, {1, 0, 0}), -kInf, parallel));
  Hit behindOrigin;
  EXPECT_FALSE(p.intersect(makeRay({0, 0, 0}, {0, -1, 0}), 0.f, behindOrigin));
  ASSERT_TRUE(p.intersect(makeRay({0, 0, 0}, {0, -1, 0}), -kInf, behindOrigin));
  EXPECT_FLOAT_EQ(behindOrigin.t, -1.5f);
  // a unit normal keeps d as it is, bit for bit (|n| = 1 exactly)
  Plane unit({0, 1, 0}, 0.3f, kMatA);
  Hit u;
  ASSERT_TRUE(unit.intersect(makeRay({0, 0, 0}, {0, 1, 0}), 0.f, u));
  EXPECT_EQ(u.t, 0.3f);
  EXPECT_FALSE(p.bounded());
}

// ---- Triangle ----------------------------------------------------------------

TEST(Triangle, InsideOutsideAndEdge) {
  Triangle tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, kMatA);
  Hit h;
  ASSERT_TRUE(tri.intersect(makeRay({0.25f, 0.25f, 2}, {0, 0, -0.5f}), 0.f, h));
  EXPECT_FLOAT_EQ(h.t, 4.f);
  EXPECT_EQ(h.normal, Vec3(0, 0, 1));
  Hit out;
  EXPECT_FALSE(tri.intersect(makeRay({0.75f, 0.75f, 2}, {0, 0, -1}), 0.f, out));
  EXPECT_FALSE(tri.intersect(makeRay({-0.01f, 0.5f, 2}, {0, 0, -1}), 0.f, out));
  Hit edge;  // u + v = 1 exactly: on the hypotenuse, counts as inside
  EXPECT_TRUE(tri.intersect(makeRay({0.5f, 0.5f, 2}, {0, 0, -1}), 0.f, edge));
  Hit vertex;
  EXPECT_TRUE(tri.intersect(makeRay({0, 0, 2}, {0, 0, -1}), 0.f, vertex));
}

TEST(Triangle, NormalFollowsCounterClockwiseWindingFromBothSides) {
  Triangle ccw({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, kMatA), cw({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, kMatA);
  Hit fromBack;
  ASSERT_TRUE(ccw.intersect(makeRay({0.2f, 0.2f, -1}, {0, 0, 1}), 0.f, fromBack));
  EXPECT_EQ(fromBack.normal, Vec3(0, 0, 1));
  Hit h;
  ASSERT_TRUE(cw.intersect(makeRay({0.2f, 0.2f, 1}, {0, 0, -1}), 0.f, h));
  EXPECT_EQ(h.normal, Vec3(0, 0, -1));
}

TEST(Triangle, ParallelRayAndTminBounds) {
  Triangle tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, kMatA);
  Hit h;
  EXPECT_FALSE(tri.intersect(makeRay({-1, 0.2f, 0}, {1, 0, 0}), -kInf, h));  // in-plane
  EXPECT_FALSE(tri.intersect(makeRay({0.2f, 0.2f, 1}, {0, 0, -1}), 1.f, h));  // t = 1 is not > tmin
  ASSERT_TRUE(tri.intersect(makeRay({0.2f, 0.2f, 1}, {0, 0, 1}), -kInf, h));
  EXPECT_FLOAT_EQ(h.t, -1.f);
}

// ---- Transform: compare with the analytically transformed primitive ---------

/// Deterministic rays aimed near `target` from a shell around it.
std::vector<Ray> raysToward(const Vec3& target, float spread, int n, uint64_t seed) {
  std::vector<Ray> rays;
  HashRng rng(seed);
  for (int i = 0; i < n; ++i) {
    const Vec3 o = target + Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f).normalized() * 8.f;
    const Vec3 aim = target + spread * Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f);
    rays.push_back(makeRay(o, (aim - o) * (0.3f + rng.nextFloat())));  // non-unit directions
  }
  return rays;
}

void expectSameHits(const Object& a, const Object& b, const std::vector<Ray>& rays, float tmin = 0.f) {
  int hits = 0;
  for (const Ray& r : rays) {
    Hit ha, hb;
    const bool fa = a.intersect(r, tmin, ha), fb = b.intersect(r, tmin, hb);
    ASSERT_EQ(fa, fb);
    if (!fa) continue;
    ++hits;
    EXPECT_NEAR(ha.t, hb.t, 1e-4f * std::max(1.f, std::abs(hb.t)));
    EXPECT_NEAR((ha.normal - hb.normal).norm(), 0.f, 1e-4f);
    EXPECT_NEAR(ha.normal.norm(), 1.f, 1e-5f);
    EXPECT_EQ(ha.material, hb.material);
  }
  EXPECT_GT(hits, static_cast<int>(rays.size()) / 4);  // the comparison must not be vacuous
}

TEST(Transform, TranslatedSphereIsSphereAtMovedCentre) {
  Transform moved(translation({3, -1, 2}), std::make_unique<Sphere>(Vec3(0, 0, 0), 1.5f, kMatA));
  Sphere direct({3, -1, 2}, 1.5f, kMatA);
  expectSameHits(moved, direct, raysToward({3, -1, 2}, 4.f, 300, 1));
  expectSameHits(moved, direct, raysToward({3, -1, 2}, 4.f, 300, 2), -kInf);
}

TEST(Transform, NonUniformScaleGivesEllipsoidWithGradientNormal) {
  // x^2/4 + y^2 + z^2/0.25 = 1; normal along the gradient (x/4, y, 4z).
  Transform ellipsoid(scaling({2, 1, 0.5f}), std::make_unique<Sphere>(Vec3(0, 0, 0), 1.f, kMatA));
  HashRng rng(7);
  int hits = 0;
  for (const Ray& r : raysToward({0, 0, 0}, 3.f, 400, 3)) {
    Hit h;
    const Eigen::Vector3d o = r.origin.cast<double>(), d = r.direction.cast<double>(), w(0.25, 1, 4);
    const double A = (d.array() * d.array() * w.array()).sum(), B = 2 * (o.array() * d.array() * w.array()).sum(),
                 C = (o.array() * o.array() * w.array()).sum() - 1, disc = B * B - 4 * A * C;
    const bool hit = ellipsoid.intersect(r, 0.f, h);
    if (std::abs(disc) < 1e-3 * B * B) continue;  // too close to tangent to decide in float
    ASSERT_EQ(hit, disc > 0);
    if (!hit) continue;
    ++hits;
    const double t = (-B - std::sqrt(disc)) / (2 * A);
    EXPECT_NEAR(h.t, t, 1e-4 * std::abs(t));
    const Eigen::Vector3d n = ((o + t * d).array() * w.array()).matrix().normalized();
    EXPECT_NEAR((h.normal.cast<double>() - n).norm(), 0.0, 1e-4);
  }
  EXPECT_GT(hits, 50);
}

TEST(Transform, RotatedTriangleEqualsTriangleOfRotatedVertices) {
  const Mat4 m = translation({1, 2, 3}) * rotation({1, 1, 0}, 50.f) * scaling({1, 3, 2});
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  auto apply = [&](const Vec3& p) -> Vec3 { return (m * Vec4(p.x(), p.y(), p.z(), 1)).head<3>(); };
  Transform rotated(m, std::make_unique<Triangle>(a, b, c, kMatA));
  Triangle direct(apply(a), apply(b), apply(c), kMatA);
  expectSameHits(rotated, direct, raysToward(apply(Vec3(0.3f, 0.3f, 0)), 0.8f, 300, 4));
}

TEST(Transform, NestedTransformsComposeAsMatrixProduct) {
  const Mat4 outer = rotation({0, 0, 1}, 30.f) * translation({2, 0, 0}), inner = scaling({1, 2, 1});
  Transform nested(outer, std::make_unique<Transform>(inner, std::make_unique<Sphere>(Vec3(0, 0, 0), 1.f, kMatA)));
  Transform product(outer * inner, std::make_unique<Sphere>(Vec3(0, 0, 0), 1.f, kMatA));
  expectSameHits(nested, product, raysToward(Vec3(1.732f, 1.f, 0.f), 3.f, 300, 5));
  const BBox nb = nested.bounds();
  EXPECT_TRUE(nb.finite());
}

// ---- flatten ------------------------------------------------------------------

TEST(Flatten, TrianglesBakedSpheresWrappedPlanesStayUnbounded) {
  ObjectList kids;
  kids.push_back(std::make_unique<Sphere>(Vec3(0, 0, 0), 1.f, kMatA));
  ObjectList inner;
  inner.push_back(std::make_unique<Triangle>(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), kMatA));
  inner.push_back(std::make_unique<Sphere>(Vec3(0, 0, 0), 1.f, kMatA));
  inner.push_back(std::make_unique<Plane>(Vec3(0, 1, 0), 0.f, kMatA));
  kids.push_back(std::make_unique<Transform>(translation({5, 0, 0}) * scaling({2, 2, 2}),
                                             std::make_unique<Group>(std::move(inner))));
  Group root(std::move(kids));
  ObjectList flat;
  root.flatten(Mat4::Identity(), flat);
  ASSERT_EQ(flat.size(), 4u);
  EXPECT_NE(dynamic_cast<Sphere*>(flat[0].get()), nullptr);  // identity: kept as is
  const auto* tri = dynamic_cast<Triangle*>(flat[1].get());
  ASSERT_NE(tri, nullptr);
  EXPECT_EQ(tri->b, Vec3(7, 0, 0));
  EXPECT_EQ(tri->c, Vec3(5, 2, 0));
  EXPECT_NE(dynamic_cast<Transform*>(flat[2].get()), nullptr);
  EXPECT_TRUE(flat[2]->bounded());
  EXPECT_NEAR((flat[2]->bounds().max - Vec3(7, 2, 2)).norm(), 0.f, 1e-5f);
  EXPECT_NE(dynamic_cast<Transform*>(flat[3].get()), nullptr);
  EXPECT_FALSE(flat[3]->bounded());
  EXPECT_FALSE(root.bounded());
}

// ---- OBJ ------------------------------------------------------------------------

std::string writeObj(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::path(::testing::TempDir()) / name;
  std::ofstream(path) << text;
  return path.string();
}

TEST(LoadObj, QuadIsFanSplitAndSlashAndNegativeIndicesResolve) {
  const std::string path = writeObj("quad.obj",
                                    "# a unit square\nmtllib x.mtl\no square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                    "vn 0 0 1\nvt 0 0\ng g1\ns off\nusemtl m\nf 1/1/1 2/2/1 3//1 4\n"
                                    "v 0 0 1\r\nf -5 -4 -1\n");
  auto mesh = loadObj(path, kMatA);
  ASSERT_EQ(mesh->children.size(), 3u);
  const auto& t0 = dynamic_cast<const Triangle&>(*mesh->children[0]);
  const auto& t1 = dynamic_cast<const Triangle&>(*mesh->children[1]);
  const auto& t2 = dynamic_cast<const Triangle&>(*mesh->children[2]);
  EXPECT_EQ(t0.a, Vec3(0, 0, 0));  // fan (1 2 3), (1 3 4)
  EXPECT_EQ(t0.c, Vec3(1, 1, 0));
  EXPECT_EQ(t1.b, Vec3(1, 1, 0));
  EXPECT_EQ(t1.c, Vec3(0, 1, 0));
  EXPECT_EQ(t2.b, Vec3(1, 0, 0));  // -4 of 5 vertices is vertex 2
  EXPECT_EQ(t2.c, Vec3(0, 0, 1));
  EXPECT_EQ(t0.material, kMatA);
  Hit h1, h2;
  EXPECT_TRUE(mesh->intersect(makeRay({0.9f, 0.2f, 1}, {0, 0, -1}), 0.f, h1));
  EXPECT_TRUE(mesh->intersect(makeRay({0.1f, 0.8f, 1}, {0, 0, -1}), 0.f, h2));
}

TEST(LoadObj, MissingFileIsFileError) {
  EXPECT_THROW(loadObj("/nonexistent/dir/none.obj", kMatA), FileError);
}

struct BadObj {
  const char* text;
  int line;
};

class LoadObjErrors : public ::testing::TestWithParam<BadObj> {};

TEST_P(LoadObjErrors, ParseErrorNamesFileAndLine) {
  const std::string path = writeObj("bad.obj", GetParam().text);
  try {
    loadObj(path, kMatA);
    FAIL() << "no ParseError for:\n" << GetParam().text;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), GetParam().line);
    EXPECT_NE(std::string(e.what()).find(path + ":" + std::to_string(GetParam().line) + ":"), std::string::npos)
        << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, LoadObjErrors,
    ::testing::Values(BadObj{"v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n", 2},      // not a number
                      BadObj{"v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", 2},        // too few fields
                      BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0 1 2 3 4\nf 1 2 3\n", 3},  // too many fields
                      BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", 4},        // two-vertex face
                      BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n", 5},    // index out of range
                      BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4},      // index zero
                      BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", 4},   // relative before first
                      BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 a 3\n", 4},      // non-numeric index
                      BadObj{"v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 1},    // NaN coordinate
                      BadObj{"v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n", 2},    // infinite coordinate
                      BadObj{"v 0 0 0\nv 1 1e60 0\nv 0 1 0\nf 1 2 3\n", 2},   // beyond float range
                      BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\n", 3}));             // no faces

}  // namespace
}  // namespace aliaslab
