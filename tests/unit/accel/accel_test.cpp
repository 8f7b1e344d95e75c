// The grid must return exactly brute force's closest hit (same primitive,
// bit-identical t) on every ray, and occluded() must agree with both.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "accel/aggregate.h"
#include "core/hash.h"
#include "geometry/primitives.h"
#include "scene/scene.h"

namespace aliaslab {
namespace {

const Material* material(int k) { return reinterpret_cast<const Material*>(uintptr_t(16 * (k + 1))); }

Vec3 uniformIn(HashRng& rng, const Vec3& lo, const Vec3& hi) {
  return lo + Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()).cwiseProduct(hi - lo);
}
Vec3 randomDirection(HashRng& rng) {
  const float z = 2 * rng.nextFloat() - 1, phi = 2 * kPi * rng.nextFloat(), r = std::sqrt(1 - z * z);
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}
Mat4 randomTransform(HashRng& rng) {
  Mat4 m = Mat4::Identity();
  const Mat3 rot = Eigen::AngleAxisf(2 * kPi * rng.nextFloat(), randomDirection(rng)).toRotationMatrix();
  m.topLeftCorner<3, 3>() = rot * Vec3(0.5f + 1.5f * rng.nextFloat(), 0.5f + 1.5f * rng.nextFloat(),
                                       0.5f + 1.5f * rng.nextFloat()).asDiagonal();
  m.topRightCorner<3, 1>() = uniformIn(rng, Vec3::Constant(-4), Vec3::Constant(4));
  return m;
}

/// A lathed surface: rings of vertices shared by neighbouring triangles.
std::unique_ptr<Group> lathe(int rings, int segments, const Vec3& base, float height, int mat) {
  ObjectList tris;
  auto point = [&](int i, int j) -> Vec3 {
    const float y = height * i / rings, r = 0.6f + 0.3f * std::sin(3.f * i / rings * kPi);
    const float phi = 2 * kPi * j / segments;
    return base + Vec3(r * std::cos(phi), y, r * std::sin(phi));
  };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      tris.push_back(std::make_unique<Triangle>(point(i, j), point(i + 1, j), point(i + 1, j + 1), material(mat)));
      tris.push_back(std::make_unique<Triangle>(point(i, j), point(i + 1, j + 1), point(i, j + 1), material(mat)));
    }
  return std::make_unique<Group>(std::move(tris));
}

/// Spheres, loose triangles, transformed objects, planes and meshes.
std::unique_ptr<Group> randomScene(uint64_t seed, bool withPlanes) {
  HashRng rng(hashWords(seed, 0x5ce7e));
  ObjectList kids;
  const Vec3 lo = Vec3::Constant(-5), hi = Vec3::Constant(5);
  for (int i = 0; i < 25; ++i) kids.push_back(std::make_unique<Sphere>(uniformIn(rng, lo, hi), 0.1f + rng.nextFloat(), material(1)));
  for (int i = 0; i < 120; ++i) {
    const Vec3 a = uniformIn(rng, lo, hi);
    const float s = 0.2f + 2.f * rng.nextFloat();
    kids.push_back(std::make_unique<Triangle>(a, a + s * randomDirection(rng), a + s * randomDirection(rng), material(2)));
  }
  for (int i = 0; i < 8; ++i) {
    std::unique_ptr<Object> child;
    if (i % 3 == 0) child = std::make_unique<Sphere>(Vec3(0, 0, 0), 0.8f, material(3));
    else if (i % 3 == 1) child = std::make_unique<Triangle>(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), material(3));
    else child = lathe(4, 8, Vec3(0, 0, 0), 1.f, 3);
    kids.push_back(std::make_unique<Transform>(randomTransform(rng), std::move(child)));
  }
  kids.push_back(lathe(12, 16, uniformIn(rng, lo, hi * 0.5f), 3.f, 4));
  kids.push_back(lathe(6, 6, Vec3(-4, -4, -4), 0.5f, 5));  // a small dense mesh
  if (withPlanes) {
    kids.push_back(std::make_unique<Plane>(Vec3(0, 1, 0), -6.f, material(6)));
    kids.push_back(std::make_unique<Transform>(randomTransform(rng), std::make_unique<Plane>(randomDirection(rng), 7.f, material(7))));
  }
  return std::make_unique<Group>(std::move(kids));
}

struct RayQuery {
  Ray ray;
  float tmin;
};

/// Rays from outside and inside the box, whole lines (tmin = -inf), axis-aligned ones and rays aimed at vertices.
std::vector<RayQuery> randomRays(const BBox& box, int n, uint64_t seed, const std::vector<Vec3>& targets) {
  HashRng rng(hashWords(seed, 0x7a75));
  const Vec3 c = 0.5f * (box.min + box.max), e = box.extent();
  const float radius = e.norm();
  std::vector<RayQuery> out;
  for (int i = 0; i < n; ++i) {
    const int kind = i % 6;
    const bool inside = kind == 1 || kind == 3;
    Vec3 o = inside ? uniformIn(rng, box.min, box.max) : c + radius * randomDirection(rng);
    Vec3 d = kind == 0 ? uniformIn(rng, box.min, box.max) - o : randomDirection(rng);
    if (kind == 4) {  // axis-aligned, origin on a coarse lattice
      d = Vec3::Zero();
      d[rng.nextBelow(3)] = rng.nextFloat() < 0.5f ? -1.f : 1.f;
      o = box.min + e.cwiseProduct(Vec3(rng.nextBelow(9), rng.nextBelow(9), rng.nextBelow(9)) / 8.f) - d * radius;
    }
    if (kind == 5 && !targets.empty()) d = targets[rng.nextBelow(uint32_t(targets.size()))] - o;  // exactly at a vertex
    d *= 0.25f + 2.f * rng.nextFloat();  // t is not a distance
    out.push_back({Ray{o, d}, (kind == 2 || kind == 3 || (kind == 5 && i % 4 == 1)) ? -kInf : 0.f});
  }
  return out;
}

/// Compares closest hits, bounded closest hits and shadow queries; returns the number of hits seen.
int expectGridMatchesBruteForce(const Aggregate& brute, const Aggregate& grid, const std::vector<RayQuery>& rays) {
  int hits = 0, mismatches = 0;
  for (const auto& [ray, tmin] : rays) {
    Hit hb, hg;
    const bool fb = brute.intersect(ray, tmin, hb), fg = grid.intersect(ray, tmin, hg);
    const bool same = fb == fg && hb.primitive == hg.primitive && hb.t == hg.t && hb.normal == hg.normal &&
                      hb.material == hg.material;
    if (!same && ++mismatches <= 5)
      ADD_FAILURE() << grid.describe() << ": o=" << ray.origin.transpose() << " d=" << ray.direction.transpose()
                    << " tmin=" << tmin << " brute (" << hb.primitive << ", " << hb.t << ") grid (" << hg.primitive
                    << ", " << hg.t << ")";
    hits += fb;
    // A bound from the caller: only strictly closer hits count
    const float bound = fb ? (hb.t > 0 ? 0.5f * hb.t : 2.f * hb.t) + 1e-3f : 3.f;
    Hit bb, bg;
    bb.t = bg.t = bound;
    const bool cb = brute.intersect(ray, tmin, bb), cg = grid.intersect(ray, tmin, bg);
    if ((cb != cg || bb.t != bg.t || bb.primitive != bg.primitive) && ++mismatches <= 5)
      ADD_FAILURE() << "bounded query differs, bound " << bound;
    // Shadow rays: occluded(tmin, tmax) iff brute force's closest hit lies before tmax
    for (float tmax : {fb ? hb.t : 1.f, fb ? std::nextafter(hb.t, kInf) : kInf, 0.7f}) {
      const bool expected = fb && hb.t < tmax;
      if ((brute.occluded(ray, tmin, tmax) != expected || grid.occluded(ray, tmin, tmax) != expected) && ++mismatches <= 5)
        ADD_FAILURE() << "occluded differs at tmax " << tmax << " (expected " << expected << ")";
    }
  }
  EXPECT_EQ(mismatches, 0) << grid.describe();
  return hits;
}

std::vector<Vec3> vertices(const Object& root) {
  ObjectList flat;
  root.flatten(Mat4::Identity(), flat);
  std::vector<Vec3> v;
  for (const auto& p : flat)
    if (const auto* t = dynamic_cast<const Triangle*>(p.get())) v.insert(v.end(), {t->a, t->b, t->c});
  return v;
}

BBox boundedBox(const Object& root) {
  ObjectList flat;
  root.flatten(Mat4::Identity(), flat);
  BBox b;
  for (const auto& p : flat)
    if (p->bounded()) b.extend(p->bounds());
  return b;
}

TEST(Grid, ClosestHitsIdenticalToBruteForceOnRandomScenes) {
  int total = 0, hits = 0;
  for (uint64_t seed = 0; seed < 6; ++seed) {
    const auto scene = randomScene(seed, seed % 3 != 2);
    const auto brute = makeBruteForce(*scene);
    const std::array<int, 3> res = seed == 0 ? std::array{1, 1, 1} : seed == 1 ? std::array{7, 3, 5} : std::array{0, 0, 0};
    const auto grid = makeGrid(*scene, res[0], res[1], res[2]);
    const auto rays = randomRays(boundedBox(*scene), 4000, seed, vertices(*scene));
    hits += expectGridMatchesBruteForce(*brute, *grid, rays);
    total += static_cast<int>(rays.size());
  }
  EXPECT_GE(total, 20000);
  EXPECT_GT(hits, total / 4);  // the comparison is not vacuous
}

TEST(Grid, FlatSceneGetsOneCellAcrossItsThinAxis) {
  ObjectList tris;
  HashRng rng(11);
  for (int i = 0; i < 300; ++i) {
    const Vec3 a(10 * rng.nextFloat(), 10 * rng.nextFloat(), 0.f);
    tris.push_back(std::make_unique<Triangle>(a, a + Vec3(1, 0, 0), a + Vec3(0, 1, 0), material(0)));
  }
  Group flat(std::move(tris));
  const auto grid = makeGrid(flat);
  const AggregateStats s = grid->stats();
  EXPECT_EQ(s.cells[2], 1);
  EXPECT_GT(s.cells[0], 10);
  EXPECT_EQ(s.cells[0], s.cells[1]);
  EXPECT_GT(expectGridMatchesBruteForce(*makeBruteForce(flat), *grid, randomRays(boundedBox(flat), 3000, 5, vertices(flat))), 100);
}

TEST(Grid, AutomaticResolutionIsTwoCubeRootsAlongLongestAxis) {
  ObjectList spheres;
  for (int i = 0; i < 1000; ++i) spheres.push_back(std::make_unique<Sphere>(Vec3(0.02f * i, 0.005f * (i % 100), 0.f), 0.1f, material(0)));
  Group g(std::move(spheres));
  const AggregateStats s = makeGrid(g)->stats();
  EXPECT_EQ(s.cells[0], 20);                   // 2 * cbrt(1000)
  EXPECT_NEAR(s.cells[1], 20 * 0.695 / 20.18, 1);  // proportional to the extent
  EXPECT_EQ(s.primitives, 1000u);
  EXPECT_EQ(s.unbounded, 0u);
  EXPECT_GE(s.references, 1000u);
}

TEST(Grid, OnlyPlanesAndEmptySceneAreHandled) {
  ObjectList kids;
  kids.push_back(std::make_unique<Plane>(Vec3(0, 0, 1), 2.f, material(0)));
  Group planes(std::move(kids)), empty;
  Hit h;
  ASSERT_TRUE(makeGrid(planes)->intersect(Ray{Vec3(0, 0, 0), Vec3(0, 0, 4)}, 0.f, h));
  EXPECT_EQ(h.t, 0.5f);
  EXPECT_EQ(h.primitive, 0);
  Hit none;
  EXPECT_FALSE(makeGrid(empty)->intersect(Ray{Vec3(0, 0, 0), Vec3(0, 0, 1)}, -kInf, none));
  EXPECT_FALSE(makeGrid(empty)->occluded(Ray{Vec3(0, 0, 0), Vec3(0, 0, 1)}, -kInf, kInf));
}

TEST(Grid, EverySceneFileMatchesBruteForceOnCameraAndRandomRays) {
  const std::filesystem::path dir = std::filesystem::path(ALIASLAB_SOURCE_DIR) / "scenes";
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".txt") continue;
    SCOPED_TRACE(entry.path().string());
    const Scene scene = parseScene(entry.path().string());
    const auto brute = makeBruteForce(*scene.root);
    const auto grid = makeGrid(*scene.root);
    HashRng rng(hashWords(0xca3e, scenes));
    std::vector<RayQuery> rays;
    for (int i = 0; i < 1500; ++i)
      rays.push_back({scene.camera->generateRay(Vec2(1.2f * rng.nextFloat() - 0.1f, 1.2f * rng.nextFloat() - 0.1f)),
                      scene.camera->tMin()});
    const BBox box = boundedBox(*scene.root);
    if (!box.empty()) {
      const auto more = randomRays(box, 1500, scenes, vertices(*scene.root));
      rays.insert(rays.end(), more.begin(), more.end());
    }
    EXPECT_GT(expectGridMatchesBruteForce(*brute, *grid, rays), 100);
    ++scenes;
  }
  EXPECT_GE(scenes, 5);
}

// BVH ------------------------------------------------------------------------
// Closest hits equal brute force's (same primitive, bit-identical t) on rays
// that do not graze an edge; rays aimed exactly at vertices are left to the
// watertightness test below, since there the watertight test may rightly
// decide differently from Moller-Trumbore.

TEST(Bvh, ClosestHitsIdenticalToBruteForceOnRandomScenes) {
  int total = 0, hits = 0;
  for (uint64_t seed = 0; seed < 6; ++seed) {
    const auto scene = randomScene(seed, seed % 3 != 2);
    const auto rays = randomRays(boundedBox(*scene), 4000, seed, {});
    hits += expectGridMatchesBruteForce(*makeBruteForce(*scene), *makeBvh(*scene), rays);
    total += static_cast<int>(rays.size());
  }
  EXPECT_GT(hits, total / 4);
}

TEST(Bvh, EverySceneFileMatchesBruteForceOnCameraAndRandomRays) {
  const std::filesystem::path dir = std::filesystem::path(ALIASLAB_SOURCE_DIR) / "scenes";
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".txt") continue;
    SCOPED_TRACE(entry.path().string());
    const Scene scene = parseScene(entry.path().string());
    HashRng rng(hashWords(0xb7a, scenes));
    std::vector<RayQuery> rays;
    for (int i = 0; i < 3000; ++i)
      rays.push_back({scene.camera->generateRay(Vec2(1.2f * rng.nextFloat() - 0.1f, 1.2f * rng.nextFloat() - 0.1f)),
                      scene.camera->tMin()});
    const BBox box = boundedBox(*scene.root);
    if (!box.empty()) {
      // without the axis-aligned rays from a lattice: on these scenes they run exactly along
      // edges and faces (e.g. vase rings at y = 1.99, fence rails at y = 0.5), where the
      // watertight test decides differently from Moller-Trumbore by design
      for (const RayQuery& q : randomRays(box, 1500, scenes, {}))
        if ((q.ray.direction.array() == 0.f).count() < 2) rays.push_back(q);
    }
    EXPECT_GT(expectGridMatchesBruteForce(*makeBruteForce(*scene.root), *makeBvh(*scene.root), rays), 100);
    ++scenes;
  }
  EXPECT_GE(scenes, 5);
}

TEST(Bvh, OnlyPlanesEmptySceneAndOneTriangle) {
  ObjectList kids;
  kids.push_back(std::make_unique<Plane>(Vec3(0, 0, 1), 2.f, material(0)));
  Group planes(std::move(kids)), empty;
  Hit h;
  ASSERT_TRUE(makeBvh(planes)->intersect(Ray{Vec3(0, 0, 0), Vec3(0, 0, 4)}, 0.f, h));
  EXPECT_EQ(h.t, 0.5f);
  Hit none;
  EXPECT_FALSE(makeBvh(empty)->intersect(Ray{Vec3(0, 0, 0), Vec3(0, 0, 1)}, -kInf, none));
  EXPECT_FALSE(makeBvh(empty)->occluded(Ray{Vec3(0, 0, 0), Vec3(0, 0, 1)}, -kInf, kInf));
  ObjectList one;
  one.push_back(std::make_unique<Triangle>(Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1), material(2)));
  Group g(std::move(one));
  Hit t;
  ASSERT_TRUE(makeBvh(g)->intersect(Ray{Vec3(0.25f, 0.25f, 0), Vec3(0, 0, 2)}, 0.f, t));
  EXPECT_EQ(t.t, 0.5f);
  EXPECT_EQ(t.material, material(2));
  EXPECT_TRUE(makeBvh(g)->occluded(Ray{Vec3(0.25f, 0.25f, 0), Vec3(0, 0, 2)}, 0.f, 0.6f));
  EXPECT_FALSE(makeBvh(g)->occluded(Ray{Vec3(0.25f, 0.25f, 0), Vec3(0, 0, 2)}, 0.f, 0.5f));
}

/// A closed mesh: a subdivided octahedron pushed onto an ellipsoid, under the
/// affine map m (so vertices are not on a lattice); neighbours share vertices.
std::unique_ptr<Group> closedMesh(int subdivisions, const Mat4& m) {
  const Vec3 corner[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  auto place = [&](Vec3 p) {
    p.normalize();
    return Vec3((m * Vec4(p.x(), 0.7f * p.y(), p.z(), 1.f)).head<3>());
  };
  ObjectList tris;
  const int n = subdivisions;
  for (const auto& f : faces) {
    const Vec3 a = corner[f[0]], b = corner[f[1]], c = corner[f[2]];
    // barycentric lattice (i, j) on the face: integer sums, so both faces of an edge compute the same vertex
    auto v = [&](int i, int j) {
      const int k = n - i - j;
      return place((float(k) * a + float(i) * b + float(j) * c) / float(n));
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n - i; ++j) {
        tris.push_back(std::make_unique<Triangle>(v(i, j), v(i + 1, j), v(i, j + 1), material(1)));
        if (i + j < n - 1) tris.push_back(std::make_unique<Triangle>(v(i + 1, j), v(i + 1, j + 1), v(i, j + 1), material(1)));
      }
  }
  return std::make_unique<Group>(std::move(tris));
}

// Rays through vertices, edge midpoints and points along shared edges of a
// closed mesh, each on a line through an interior point q (inside the
// ellipsoid scaled by 0.3): from q outwards, and from beyond the surface
// point back towards q. Either way the ray must cross the surface, so every
// ray must hit (closest hit and any-hit). Moller-Trumbore (brute force) is
// not watertight; its misses are printed for comparison.
TEST(Bvh, WatertightAtSharedEdgesAndVertices) {
  int rays = 0, bvhMisses = 0, bvhOccludedMisses = 0, bruteMisses = 0;
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    HashRng rng(hashWords(seed, 0xed9e));
    const Mat4 m = randomTransform(rng);
    const auto mesh = closedMesh(8, m);
    const auto bvh = makeBvh(*mesh), brute = makeBruteForce(*mesh);
    ObjectList flat;
    mesh->flatten(Mat4::Identity(), flat);
    for (const auto& p : flat) {
      const auto& t = static_cast<const Triangle&>(*p);
      const Vec3 targets[] = {t.a, t.b, 0.5f * (t.a + t.b), t.a + 0.25f * (t.c - t.a), t.b + rng.nextFloat() * (t.c - t.b)};
      for (const Vec3& target : targets) {
        const Vec3 u = 0.3f * rng.nextFloat() * randomDirection(rng);
        const Vec3 q = (m * Vec4(u.x(), 0.7f * u.y(), u.z(), 1.f)).head<3>();
        const Vec3 outside = target + (0.5f + 2.f * rng.nextFloat()) * (target - q);
        for (const Ray& ray : {Ray{q, target - q}, Ray{outside, q - outside}}) {
          Hit hb, hf;
          bvhMisses += !bvh->intersect(ray, 0.f, hb);
          bvhOccludedMisses += !bvh->occluded(ray, 0.f, kInf);
          bruteMisses += !brute->intersect(ray, 0.f, hf);
          ++rays;
        }
      }
    }
  }
  EXPECT_GT(rays, 10000);
  EXPECT_EQ(bvhMisses, 0) << "of " << rays << " rays";
  EXPECT_EQ(bvhOccludedMisses, 0) << "of " << rays << " rays";
  std::printf("watertight test: %d rays at edges and vertices; misses: bvh %d, brute force (Moller-Trumbore) %d\n", rays,
              bvhMisses, bruteMisses);
}

}  // namespace
}  // namespace aliaslab
