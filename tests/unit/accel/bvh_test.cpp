// The BVH on both node widths (4-wide SSE, and 8-wide AVX2 where the CPU has it; each test runs once per
// width, so the 4-wide fallback is covered on AVX2 machines too): closest hits equal brute force's (same
// primitive, bit-identical t) on rays that do not graze an edge, any-hit agrees, closed meshes are watertight,
// and the two widths return the same hits as each other on every ray, grazing ones included.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/accel_fixtures.h"

namespace aliaslab {
namespace {

class Bvh : public ::testing::TestWithParam<BvhWidth> {
 protected:
  void SetUp() override {
    if (GetParam() == BvhWidth::Eight && !bvhEightWideSupported()) GTEST_SKIP() << "this CPU has no AVX2";
  }
  BvhWidth width() const { return GetParam(); }
};

INSTANTIATE_TEST_SUITE_P(Width, Bvh, ::testing::Values(BvhWidth::Four, BvhWidth::Eight),
                         [](const auto& info) { return info.param == BvhWidth::Four ? "Four" : "Eight"; });

// Closest hits equal brute force's (same primitive, bit-identical t) on rays
// that do not graze an edge; rays aimed exactly at vertices are left to the
// watertightness test below, since there the watertight test may rightly
// decide differently from Moller-Trumbore.

TEST_P(Bvh, ClosestHitsIdenticalToBruteForceOnRandomScenes) {
  int total = 0, hits = 0;
  for (uint64_t seed = 0; seed < 6; ++seed) {
    const auto scene = randomScene(seed, seed % 3 != 2);
    const auto rays = randomRays(boundedBox(*scene), 4000, seed, {});
    hits += expectGridMatchesBruteForce(*makeBruteForce(*scene), *makeBvh(*scene, width()), rays);
    total += static_cast<int>(rays.size());
  }
  EXPECT_GT(hits, total / 4);
}

TEST_P(Bvh, EverySceneFileMatchesBruteForceOnCameraAndRandomRays) {
  const int scenes = forEachBundledScene([&](const Scene& scene, int k) {
    std::vector<RayQuery> rays = cameraRays(scene, 3000, hashWords(0xb7a, k));
    const BBox box = boundedBox(*scene.root);
    if (!box.empty()) {
      // without the axis-aligned rays from a lattice: on these scenes they run exactly along
      // edges and faces (e.g. vase rings at y = 1.99, fence rails at y = 0.5), where the
      // watertight test decides differently from Moller-Trumbore by design
      for (const RayQuery& q : randomRays(box, 1500, k, {}))
        if ((q.ray.direction.array() == 0.f).count() < 2) rays.push_back(q);
    }
    EXPECT_GT(expectGridMatchesBruteForce(*makeBruteForce(*scene.root), *makeBvh(*scene.root, width()), rays), 100);
  });
  EXPECT_GE(scenes, 5);
}

TEST_P(Bvh, OnlyPlanesEmptySceneAndOneTriangle) {
  ObjectList kids;
  kids.push_back(std::make_unique<Plane>(Vec3(0, 0, 1), 2.f, material(0)));
  Group planes(std::move(kids)), empty;
  Hit h;
  ASSERT_TRUE(makeBvh(planes, width())->intersect(Ray{Vec3(0, 0, 0), Vec3(0, 0, 4)}, 0.f, h));
  EXPECT_EQ(h.t, 0.5f);
  Hit none;
  EXPECT_FALSE(makeBvh(empty, width())->intersect(Ray{Vec3(0, 0, 0), Vec3(0, 0, 1)}, -kInf, none));
  EXPECT_FALSE(makeBvh(empty, width())->occluded(Ray{Vec3(0, 0, 0), Vec3(0, 0, 1)}, -kInf, kInf));
  ObjectList one;
  one.push_back(std::make_unique<Triangle>(Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1), material(2)));
  Group g(std::move(one));
  Hit t;
  ASSERT_TRUE(makeBvh(g, width())->intersect(Ray{Vec3(0.25f, 0.25f, 0), Vec3(0, 0, 2)}, 0.f, t));
  EXPECT_EQ(t.t, 0.5f);
  EXPECT_EQ(t.material, material(2));
  EXPECT_TRUE(makeBvh(g, width())->occluded(Ray{Vec3(0.25f, 0.25f, 0), Vec3(0, 0, 2)}, 0.f, 0.6f));
  EXPECT_FALSE(makeBvh(g, width())->occluded(Ray{Vec3(0.25f, 0.25f, 0), Vec3(0, 0, 2)}, 0.f, 0.5f));
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
TEST_P(Bvh, WatertightAtSharedEdgesAndVertices) {
  int rays = 0, bvhMisses = 0, bvhOccludedMisses = 0, bruteMisses = 0;
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    HashRng rng(hashWords(seed, 0xed9e));
    const Mat4 m = randomTransform(rng);
    const auto mesh = closedMesh(8, m);
    const auto bvh = makeBvh(*mesh, width()), brute = makeBruteForce(*mesh);
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

// Long thin diagonal triangles fill their boxes poorly and are pre-split into several boxes each
// (bvh_presplit.cpp); rays aimed at points inside them (and random ones) still find brute force's hits.
TEST_P(Bvh, PreSplitSliversHitLikeBruteForce) {
  HashRng rng(hashWords(0x5b11, 7));
  ObjectList kids;
  std::vector<Vec3> targets;
  for (int i = 0; i < 200; ++i) {
    const Vec3 p = uniformIn(rng, Vec3(-3, -3, -3), Vec3(3, 3, 3));  // small, well-fitting triangles
    kids.push_back(std::make_unique<Triangle>(p, p + Vec3(0.3f, 0, 0), p + Vec3(0, 0.3f, 0), material(1)));
    if (i % 10 != 0) continue;
    const Vec3 a = uniformIn(rng, Vec3(-3, -3, -3), Vec3(3, 3, 3));
    const Vec3 b = a + 5.f * randomDirection(rng), c = b + 0.05f * randomDirection(rng);
    const float u = 0.05f + 0.9f * rng.nextFloat(), v = (1.f - u) * (0.1f + 0.8f * rng.nextFloat());
    targets.push_back(a + u * (b - a) + v * (c - a));
    kids.push_back(std::make_unique<Triangle>(a, b, c, material(i % 3)));
  }
  Group scene(std::move(kids));
  const auto bvh = makeBvh(scene, width());
  EXPECT_GT(bvh->stats().references, bvh->stats().primitives + 3 * targets.size()) << bvh->describe();
  std::vector<RayQuery> rays = randomRays(boundedBox(scene), 3000, 11, {});
  for (const Vec3& t : targets)
    for (int k = 0; k < 60; ++k) {
      const Vec3 o = t + 8.f * randomDirection(rng);
      rays.push_back({Ray{o, t - o}, 0.f});
    }
  EXPECT_GT(expectGridMatchesBruteForce(*makeBruteForce(scene), *bvh, rays), 1000);
}

TEST_P(Bvh, BuildsNodesOfItsWidth) {
  const auto scene = randomScene(3, true);
  const std::string wide = width() == BvhWidth::Four ? "bvh 4-wide" : "bvh 8-wide";
  EXPECT_EQ(makeBvh(*scene, width())->describe().rfind(wide, 0), 0u) << makeBvh(*scene, width())->describe();
}

// The automatic choice: with AVX2 both trees (8-wide for closest hits, 4-wide for any hits; same hits as brute
// force), else 4-wide; 8-wide only where asked and available.
TEST(BvhWidthChoice, AutomaticUsesBothWidthsWithAvx2AndEightWideNeedsAvx2) {
  const auto scene = randomScene(1, false);
  const auto automatic = makeBvh(*scene);
  const std::string d = automatic->describe();
  if (bvhEightWideSupported()) {
    EXPECT_EQ(d.rfind("bvh 8-wide closest, 4-wide any hits", 0), 0u) << d;
    const auto four = makeBvh(*scene, BvhWidth::Four), eight = makeBvh(*scene, BvhWidth::Eight);
    EXPECT_EQ(automatic->stats().nodes, four->stats().nodes + eight->stats().nodes);
    const auto rays = randomRays(boundedBox(*scene), 2000, 5, {});
    expectGridMatchesBruteForce(*makeBruteForce(*scene), *automatic, rays);
  } else {
    EXPECT_EQ(d.rfind("bvh 4-wide", 0), 0u) << d;
    EXPECT_THROW(makeBvh(*scene, BvhWidth::Eight), std::runtime_error);
  }
}

/// Closest hits (found, primitive, t, normal, material), bounded closest hits and any-hit answers of a and b
/// on every ray must be the same bits; returns the number of mismatches.
int countDifferences(const Aggregate& a, const Aggregate& b, const std::vector<RayQuery>& rays) {
  int mismatches = 0;
  for (const auto& [ray, tmin] : rays) {
    Hit ha, hb;
    const bool fa = a.intersect(ray, tmin, ha), fb = b.intersect(ray, tmin, hb);
    bool same = fa == fb && ha.primitive == hb.primitive && ha.t == hb.t && ha.normal == hb.normal &&
                ha.material == hb.material;
    const float bound = fa ? (ha.t > 0 ? 0.5f * ha.t : 2.f * ha.t) + 1e-3f : 3.f;
    Hit ba, bb;
    ba.t = bb.t = bound;
    same = same && a.intersect(ray, tmin, ba) == b.intersect(ray, tmin, bb) && ba.t == bb.t &&
           ba.primitive == bb.primitive;
    for (float tmax : {fa ? ha.t : 1.f, fa ? std::nextafter(ha.t, kInf) : kInf, 0.7f})
      same = same && a.occluded(ray, tmin, tmax) == b.occluded(ray, tmin, tmax);
    if (!same && ++mismatches <= 5)
      ADD_FAILURE() << a.describe() << " vs " << b.describe() << ": o=" << ray.origin.transpose()
                    << " d=" << ray.direction.transpose() << " tmin=" << tmin << " (" << ha.primitive << ", " << ha.t
                    << ") vs (" << hb.primitive << ", " << hb.t << ")";
  }
  return mismatches;
}

// 4-wide and 8-wide against each other on every bundled scene and on random scenes, with all the rays that
// brute force cannot referee: axis-aligned rays along edges and faces, rays aimed exactly at vertices.
TEST(BvhWidthChoice, FourAndEightWideGiveTheSameHitsOnEveryRay) {
  if (!bvhEightWideSupported()) GTEST_SKIP() << "this CPU has no AVX2";
  const int scenes = forEachBundledScene([](const Scene& scene, int k) {
    std::vector<RayQuery> rays = cameraRays(scene, 3000, hashWords(0x8a8, k));
    appendRandomRays(scene, 3000, k, rays);
    const auto four = makeBvh(*scene.root, BvhWidth::Four), eight = makeBvh(*scene.root, BvhWidth::Eight);
    EXPECT_EQ(countDifferences(*four, *eight, rays), 0);
  });
  EXPECT_GE(scenes, 5);
  for (uint64_t seed = 0; seed < 4; ++seed) {
    const auto scene = randomScene(seed, seed % 2 == 0);
    const auto rays = randomRays(boundedBox(*scene), 4000, seed, vertices(*scene));
    EXPECT_EQ(countDifferences(*makeBvh(*scene, BvhWidth::Four), *makeBvh(*scene, BvhWidth::Eight), rays), 0);
  }
}

}  // namespace
}  // namespace aliaslab
