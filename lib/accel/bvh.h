// Private to accel/: the layout of the bounding volume hierarchy behind makeBvh(), built by buildBvh()
// (bvh_build.cpp) and traversed by the Bvh aggregate (bvh_trace.cpp); the protocol is in aggregate.h.
//
// Build: a binary tree by binned SAH over reference centroids (a reference: a primitive's box, or for a
// triangle that fills its box poorly one of several boxes around parts of it, bvh_presplit.cpp; kBins bins
// per axis, leaves of at most kMaxLeaf primitives), collapsed into 4-wide
// nodes (each node adopts the children of its largest-area inner children
// until it has four), boxes stored axis by axis so one SSE instruction tests
// a ray against four boxes; or, for the AVX2 traversal (bvh_trace_avx2.cpp),
// into 8-wide nodes the same way, one AVX instruction per eight boxes. Boxes
// are padded like the grid's so that the float slab test never drops a box a
// hit lies in.
//
// Leaves made only of triangles (all but a few) are stored as a TriPack, so the watertight test
// (bvh_trace.cpp) runs on up to four triangles per SSE instruction.
#pragma once
#include <cstdint>
#include <vector>

#include "accel/aggregate.h"

namespace aliaslab::bvhimpl {

struct Item {
  Vec3 a, b, c;      ///< triangle vertices (unused for other primitives)
  Vec3 e1, e2;       ///< b - a, c - a as Triangle::intersect computes them
  const Object* obj; ///< nullptr for a triangle, else a primitive tested by its own intersect()
  const Material* material;
  int prim;          ///< flattened index
};

struct alignas(16) Node4 {
  static constexpr int kWidth = 4;
  float lo[3][4], hi[3][4];  ///< child boxes, axis by axis
  int32_t child[4];          ///< inner: node index; leaf: first item (packed leaf: TriPack index); -1: empty
  uint32_t count[4];         ///< 0: inner node, else number of items of the leaf (| kPacked: a TriPack)
};

/// Node4 with eight children (empty ones: lo = +inf, hi = -inf, child = -1).
struct alignas(32) Node8 {
  static constexpr int kWidth = 8;
  float lo[3][8], hi[3][8];
  int32_t child[8];
  uint32_t count[8];
};

/// A leaf made only of triangles, vertices stored axis by axis so that one SSE
/// instruction runs a step of the watertight test (and of Moller-Trumbore's t) for all of them. Lanes >= n
/// repeat the last triangle and are masked off; item[l] is lane l's entry in items_ (material, edges),
/// prim[l] its flattened index. Three cache lines.
struct alignas(64) TriPack {
  float a[3][4], b[3][4], c[3][4];
  int32_t item[4];
  int32_t prim[4];
  int32_t n;
};
constexpr uint32_t kPacked = 0x80000000u;  ///< in Node4::count: child is a TriPack index, low bits the count

/// The hierarchy: the flattened primitives, the unbounded ones (indices into prims, tested before the
/// nodes), the bounded ones as items in leaf order, the 4-wide and/or 8-wide nodes (node 0 the root; none
/// when no primitive is bounded), collapsed from one binary tree so that both share the items, and the
/// triangle-only leaves (each width's packs in its own visiting order, the 8-wide ones after the 4-wide).
struct BvhLayout {
  ObjectList prims;
  std::vector<int> unbounded;
  std::vector<Item> items;
  std::vector<Node4> nodes;    ///< the 4-wide nodes (width 4 or 0), else empty
  std::vector<Node8> nodes8;   ///< the 8-wide nodes (width 8 or 0), else empty
  std::vector<TriPack> packs;  ///< the triangle-only leaves
  double buildSeconds = 0;
};

/// A box the build bins: all or part of item's primitive (pre-splitting, bvh_presplit.cpp).
struct Reference {
  BBox box;
  int item;
};

/// The references of the bounded items (boxes[i]: item i's bounds): one per item, except that triangles with a
/// box far larger than the mean get several, each bounding the part of the triangle in a half of the box.
std::vector<Reference> presplit(const std::vector<Item>& items, const std::vector<BBox>& boxes);

/// Binned SAH build over root's flattened primitives, collapsed into nodes of the given width (4 or 8), or
/// into both (width 0).
BvhLayout buildBvh(const Object& root, int width);

/// The 8-wide traversal (bvh_trace_avx2.cpp, built with -mavx2): call only where the CPU has AVX2. Raw
/// arrays in; the same closest-hit contract as the 4-wide one (bvh_trace.cpp): hit.t, normal and material
/// updated in place, best = flattened index of the closest primitive so far (-1: none).
struct Bvh8View {
  const Item* items;
  const Node8* nodes;  ///< node 0 the root; at least one node
  const TriPack* packs;
};
void closestHit8(const Bvh8View& bvh, const Ray& ray, float tmin, Hit& hit, int& best);
bool anyHit8(const Bvh8View& bvh, const Ray& ray, float tmin, float tmax);

}  // namespace aliaslab::bvhimpl
