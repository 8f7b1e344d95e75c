// Pre-splitting of the BVH's triangle references (bvh.h): early split clipping (Ernst and Greiner 2007), the
// boxes of triangles that fill their box poorly (the fence's rails, turned 25 degrees: a box of 5.5 x 2.6 units
// around a strip 0.03 high; the gem's long diagonal facets) cut into smaller boxes of the same triangle before
// the SAH build.
//
// A triangle whose box's surface area is above kPoorFit times its own area (4 for a right triangle along the
// axes; most of the vase's and the knot's are under 16) is halved at the middle of its box's longest axis while
// the box's area is above the mean over all triangles (kSplitFactor 1), at most kMaxDepth times: each half's
// box is the bounds of the triangle clipped to that half (vertices on the side, and edge crossings with the
// plane), cut to the box being split. Every point of the triangle stays inside at least one of its boxes (the
// crossings put exactly on the plane, the build's padding covering the interpolation's rounding), so the
// traversal finds every hit it found before; a triangle met in several leaves gives the same t each time (same
// prim), so the hits do not change. Factors measured on fence, vase, gem and reflective_refractive
// (results/tracing_speed.md, 2026-11-27 (second)): splitting every box above 1x the mean slowed the vase and
// the knot; above 4x the mean left the gem as it was.
#include <algorithm>

#include "accel/bvh.h"

namespace aliaslab::bvhimpl {
namespace {

constexpr float kSplitFactor = 1.f, kPoorFit = 16.f;
constexpr int kMaxDepth = 6;  ///< at most 64 boxes per triangle

float surface(const BBox& b) {
  if (b.empty()) return 0.f;
  const Vec3 e = b.extent();
  return 2.f * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x());
}

BBox clipped(const Item& it, const BBox& within, int axis, float s, bool below) {
  const Vec3 v[3] = {it.a, it.b, it.c};
  BBox out;
  for (int i = 0; i < 3; ++i) {
    const Vec3& p = v[i];
    const Vec3& q = v[(i + 1) % 3];
    if (below ? p[axis] <= s : p[axis] >= s) out.extend(p);
    if ((p[axis] < s && q[axis] > s) || (p[axis] > s && q[axis] < s)) {
      Vec3 x = p + (s - p[axis]) / (q[axis] - p[axis]) * (q - p);
      x[axis] = s;
      out.extend(x);
    }
  }
  out.min = out.min.cwiseMax(within.min), out.max = out.max.cwiseMin(within.max);
  return out;
}

void split(const Item& it, int item, const BBox& box, float limit, int depth, std::vector<Reference>& out) {
  if (depth == kMaxDepth || surface(box) <= limit) {
    out.push_back({box, item});
    return;
  }
  const Vec3 e = box.extent();
  const int axis = e.x() >= e.y() ? (e.x() >= e.z() ? 0 : 2) : (e.y() >= e.z() ? 1 : 2);
  const float s = 0.5f * (box.min[axis] + box.max[axis]);
  const BBox lo = clipped(it, box, axis, s, true), hi = clipped(it, box, axis, s, false);
  if (lo.empty() || hi.empty()) {
    out.push_back({box, item});
    return;
  }
  split(it, item, lo, limit, depth + 1, out);
  split(it, item, hi, limit, depth + 1, out);
}

}  // namespace

std::vector<Reference> presplit(const std::vector<Item>& items, const std::vector<BBox>& boxes) {
  double sum = 0;
  int triangles = 0;
  for (size_t i = 0; i < items.size(); ++i)
    if (!items[i].obj) sum += surface(boxes[i]), ++triangles;
  const float limit = triangles > 0 ? kSplitFactor * static_cast<float>(sum / triangles) : kInf;
  std::vector<Reference> refs;
  refs.reserve(items.size());
  for (size_t i = 0; i < items.size(); ++i) {
    const Item& it = items[i];
    const bool poorFit = !it.obj && surface(boxes[i]) > kPoorFit * 0.5f * it.e1.cross(it.e2).norm();
    if (poorFit) split(it, static_cast<int>(i), boxes[i], limit, 0, refs);
    else refs.push_back({boxes[i], static_cast<int>(i)});
  }
  return refs;
}

}  // namespace aliaslab::bvhimpl
