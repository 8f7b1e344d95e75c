// Shared by the accelerator tests (accel_test.cpp: grid; bvh_test.cpp: BVH): random scenes and rays, and the
// comparison of an accelerator with brute force (same primitive, bit-identical t, same any-hit answers), and
// the bundled scenes with camera and random rays.
#pragma once
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

/// Calls visit(scene, k) for the k-th bundled scene file (scenes/*.txt, in directory order), each under a
/// SCOPED_TRACE naming it; returns how many there were.
template <class Visit>
int forEachBundledScene(Visit&& visit) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(ALIASLAB_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".txt") continue;
    SCOPED_TRACE(entry.path().string());
    visit(parseScene(entry.path().string()), scenes++);
  }
  return scenes;
}

/// n rays of the scene's camera through random film positions (the film and a 10% margin around it).
std::vector<RayQuery> cameraRays(const Scene& scene, int n, uint64_t seed) {
  HashRng rng(seed);
  std::vector<RayQuery> rays;
  for (int i = 0; i < n; ++i)
    rays.push_back({scene.camera->generateRay(Vec2(1.2f * rng.nextFloat() - 0.1f, 1.2f * rng.nextFloat() - 0.1f)),
                    scene.camera->tMin()});
  return rays;
}

/// Appends randomRays(n, seed) aimed at the scene's triangle vertices too, unless it has nothing bounded.
void appendRandomRays(const Scene& scene, int n, uint64_t seed, std::vector<RayQuery>& rays) {
  const BBox box = boundedBox(*scene.root);
  if (box.empty()) return;
  const auto more = randomRays(box, n, seed, vertices(*scene.root));
  rays.insert(rays.end(), more.begin(), more.end());
}

}  // namespace
}  // namespace aliaslab
