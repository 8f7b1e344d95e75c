// The grid must return exactly brute force's closest hit (same primitive,
// bit-identical t) on every ray, and occluded() must agree with both.
#include <gtest/gtest.h>

#include "support/accel_fixtures.h"

namespace aliaslab {
namespace {

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
  const int scenes = forEachBundledScene([](const Scene& scene, int k) {
    std::vector<RayQuery> rays = cameraRays(scene, 1500, hashWords(0xca3e, k));
    appendRandomRays(scene, 1500, k, rays);
    EXPECT_GT(expectGridMatchesBruteForce(*makeBruteForce(*scene.root), *makeGrid(*scene.root), rays), 100);
  });
  EXPECT_GE(scenes, 5);
}

}  // namespace
}  // namespace aliaslab
