// Ray-triangle intersection (Moller & Trumbore 1997) on a precomputed
// triangle: one vertex and its two edges. Triangle::intersect and the grid's
// packed triangle list both call these, so they compute bit-identical t and
// normals. Both faces are hit; the normal is the geometric front normal
// normalize(e1 x e2) (counter-clockwise front face), not flipped towards the ray.
#pragma once
#include <cmath>

#include "core/math.h"
#include "core/ray.h"

namespace aliaslab {

struct TriangleEdges {
  Vec3 a;   ///< first vertex
  Vec3 e1;  ///< b - a
  Vec3 e2;  ///< c - a
};

/// Ray parameter of the hit with triangle (a, e1, e2) when it lies in
/// (tmin, tmax), else NaN-free "no hit" (returns false). Edges and vertices
/// count as inside, so a ray through a shared edge hits at least one side.
[[gnu::always_inline]] inline bool intersectTriangle(const Ray& ray, const Vec3& a, const Vec3& e1, const Vec3& e2,
                              float tmin, float tmax, float& t) {
  const Vec3 p = ray.direction.cross(e2);
  const float det = e1.dot(p);
  if (det == 0.f) return false;  // ray parallel to the plane (or degenerate triangle)
  const float inv = 1.f / det;
  const Vec3 s = ray.origin - a;
  const float u = s.dot(p) * inv;
  if (!(u >= 0.f && u <= 1.f)) return false;
  const Vec3 q = s.cross(e1);
  const float v = ray.direction.dot(q) * inv;
  if (!(v >= 0.f && u + v <= 1.f)) return false;
  const float th = e2.dot(q) * inv;
  if (!(th > tmin && th < tmax)) return false;  // also rejects NaN / +-inf
  t = th;
  return true;
}

/// Unit geometric front normal of a triangle given by its edges.
inline Vec3 triangleNormal(const Vec3& e1, const Vec3& e2) { return e1.cross(e2).normalized(); }

}  // namespace aliaslab
