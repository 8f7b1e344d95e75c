// Private to accel/: the layout of the bounding volume hierarchy behind makeBvh(), built by buildBvh()
// (bvh_build.cpp) and traversed by the Bvh aggregate (bvh_trace.cpp); the protocol is in aggregate.h.
//
// Build: a binary tree by binned SAH over primitive centroids (kBins bins
// per axis, leaves of at most kMaxLeaf primitives), collapsed into 4-wide
// nodes (each node adopts the children of its largest-area inner children
// until it has four), boxes stored axis by axis so one SSE instruction tests
// a ray against four boxes. Boxes are padded like the grid's so that the
// float slab test never drops a box a hit lies in.
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
  float lo[3][4], hi[3][4];  ///< child boxes, axis by axis
  int32_t child[4];          ///< inner: node index; leaf: first item (packed leaf: TriPack index); -1: empty
  uint32_t count[4];         ///< 0: inner node, else number of items of the leaf (| kPacked: a TriPack)
};

/// A leaf made only of triangles, vertices stored axis by axis so that one SSE
/// instruction runs a step of the watertight test for all of them. Lanes >= n
/// are unused; item[l] is lane l's entry in items_ (material, prim, edges).
struct alignas(16) TriPack {
  float a[3][4], b[3][4], c[3][4];
  int32_t item[4];
  int32_t n;
};
constexpr uint32_t kPacked = 0x80000000u;  ///< in Node4::count: child is a TriPack index, low bits the count

/// The hierarchy: the flattened primitives, the unbounded ones (indices into prims, tested before the
/// nodes), the bounded ones as items in leaf order, the 4-wide nodes (node 0 the root; none when no
/// primitive is bounded) and the triangle-only leaves.
struct BvhLayout {
  ObjectList prims;
  std::vector<int> unbounded;
  std::vector<Item> items;
  std::vector<Node4> nodes;
  std::vector<TriPack> packs;  ///< the triangle-only leaves
  double buildSeconds = 0;
};

/// Binned SAH build over root's flattened primitives, collapsed into 4-wide nodes.
BvhLayout buildBvh(const Object& root);

}  // namespace aliaslab::bvhimpl
