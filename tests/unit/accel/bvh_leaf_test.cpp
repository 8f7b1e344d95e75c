// The BVH's packed leaf test (accel/bvh_leaf.h) against its definition: for every lane of a TriPack,
// watertightHits() must answer exactly what the scalar watertight test watertightHit() (Woop, Benthin and Wald
// 2013, with its double recomputation when an edge function is zero) answers for that triangle alone. Rays
// through lattice vertices and edges along the axes make edge functions exactly zero (+0 and -0), rays lying in
// a triangle's plane make all three zero, and random rays cover the rest.
#include <gtest/gtest.h>

#include <vector>

#include "accel/bvh_leaf.h"
#include "core/hash.h"

namespace aliaslab::bvhimpl {
namespace {

Item triangleItem(const Vec3& a, const Vec3& b, const Vec3& c) {
  Item it{};
  it.a = a, it.b = b, it.c = c, it.e1 = b - a, it.e2 = c - a;
  return it;
}

/// Lanes 0..n-1 hold items[first..first+n-1]; lanes >= n repeat the last one (as the build does).
TriPack pack(const std::vector<Item>& items, int first, int n) {
  TriPack p{};
  for (int l = 0; l < 4; ++l) {
    const int i = first + std::min(l, n - 1);
    for (int k = 0; k < 3; ++k) p.a[k][l] = items[i].a[k], p.b[k][l] = items[i].b[k], p.c[k][l] = items[i].c[k];
    p.item[l] = i, p.prim[l] = i;
  }
  p.n = n;
  return p;
}

struct Counts {
  int lanes = 0, hits = 0, mismatches = 0;
};

void compare(const Ray& ray, const std::vector<Item>& items, Counts& c) {
  const PreparedRay r(ray);
  for (int first = 0; first < static_cast<int>(items.size()); first += 4) {
    const int n = std::min(4, static_cast<int>(items.size()) - first);
    const int mask = watertightHits(r, pack(items, first, n), items.data());
    EXPECT_EQ(mask >> n, 0) << "lanes beyond the pack's count must be off";
    for (int l = 0; l < n; ++l) {
      const bool scalar = watertightHit(r, items[first + l]);
      c.mismatches += scalar != (((mask >> l) & 1) != 0);
      c.hits += scalar, ++c.lanes;
    }
  }
}

// Unit right triangles on the integer lattice of the planes z = 0 and z = 1, both diagonals, both windings:
// every lattice point and edge is shared.
std::vector<Item> latticeTriangles() {
  std::vector<Item> items;
  for (int z = 0; z < 2; ++z)
    for (int y = -2; y < 2; ++y)
      for (int x = -2; x < 2; ++x) {
        const Vec3 p00(x, y, z), p10(x + 1, y, z), p01(x, y + 1, z), p11(x + 1, y + 1, z);
        items.push_back(triangleItem(p00, p10, p11));
        items.push_back(triangleItem(p00, p11, p01));
        items.push_back(triangleItem(p10, p00, p01));
        items.push_back(triangleItem(p10, p01, p11));
      }
  return items;
}

TEST(BvhLeaf, PackedWatertightTestEqualsScalarOnLatticeEdgesVerticesAndInPlaneRays) {
  const std::vector<Item> items = latticeTriangles();
  Counts c;
  for (int y2 = -5; y2 <= 5; ++y2)
    for (int x2 = -5; x2 <= 5; ++x2)
      for (const float dz : {1.f, -1.f}) {
        // Along z through lattice points, edge midpoints and cell centres (x2 / 2, y2 / 2)
        compare(Ray{Vec3(0.5f * x2, 0.5f * y2, dz > 0 ? -3.f : 3.f), Vec3(0, 0, dz)}, items, c);
        // In the plane z = 0 (and z = 1) along x and along y: every edge function of those triangles is zero
        compare(Ray{Vec3(-4.f * dz, 0.5f * y2, 0.5f * (x2 & 2)), Vec3(dz, 0, 0)}, items, c);
        compare(Ray{Vec3(0.5f * x2, -4.f * dz, 0.f), Vec3(0, dz, 0)}, items, c);
      }
  EXPECT_GT(c.hits, 500);
  EXPECT_GT(c.lanes - c.hits, 500);
  EXPECT_EQ(c.mismatches, 0) << "of " << c.lanes << " lanes";
}

TEST(BvhLeaf, PackedWatertightTestEqualsScalarOnRandomTrianglesAndRays) {
  HashRng rng(hashWords(7, 0x1eaf));
  auto point = [&] {
    Vec3 p;
    for (int k = 0; k < 3; ++k) p[k] = 2.f * rng.nextFloat() - 1.f;
    return p;
  };
  std::vector<Item> items;
  for (int i = 0; i < 63; ++i) items.push_back(triangleItem(point(), point(), point()));
  Counts c;
  for (int k = 0; k < 4000; ++k) {
    const Vec3 o = 3.f * point();
    // Half of the rays aimed at a vertex or an edge point of a random triangle
    const Item& t = items[static_cast<size_t>(rng.nextFloat() * items.size()) % items.size()];
    const Vec3 target = k % 2 ? point() : k % 4 == 0 ? t.b : t.a + rng.nextFloat() * (t.c - t.a);
    compare(Ray{o, target - o}, items, c);
  }
  EXPECT_GT(c.hits, 1000);
  EXPECT_EQ(c.mismatches, 0) << "of " << c.lanes << " lanes";
}

}  // namespace
}  // namespace aliaslab::bvhimpl
