// Closest-hit and any-hit queries over a whole scene.
//
// An Aggregate flattens the scene tree (geometry/object.h) into world-space
// primitives once, at construction, and answers queries over that list.
// BruteForce tests every primitive; Grid marches a uniform grid with 3D-DDA
// (Amanatides & Woo) over the bounded primitives and tests unbounded ones
// (planes) directly. Both return the same closest hit for every ray.
#pragma once
#include <array>
#include <memory>
#include <string>

#include "geometry/object.h"

namespace aliaslab {

struct AggregateStats {
  size_t primitives = 0;   ///< bounded + unbounded primitives after flattening
  size_t unbounded = 0;    ///< primitives kept outside the grid
  std::array<int, 3> cells{0, 0, 0};  ///< grid resolution (0 for brute force)
  size_t references = 0;   ///< primitive references stored in grid cells (BVH: in leaves)
  size_t nodes = 0;        ///< BVH nodes (0 for the others)
  double buildSeconds = 0; ///< BVH build time (0 for the others)
};

class Aggregate {
 public:
  virtual ~Aggregate() = default;
  /// Closest hit with tmin < t < hit.t; same contract as Object::intersect.
  virtual bool intersect(const Ray& ray, float tmin, Hit& hit) const = 0;
  /// Any hit with tmin < t < tmax (shadow rays).
  virtual bool occluded(const Ray& ray, float tmin, float tmax) const = 0;
  virtual AggregateStats stats() const = 0;
  virtual std::string describe() const = 0;
};

std::unique_ptr<Aggregate> makeBruteForce(const Object& root);

/// A uniform grid of nx x ny x nz cells over the bounded primitives. A zero
/// resolution is chosen automatically: ceil(2 * cbrt(N)) cells along the
/// longest axis for N bounded primitives, proportionally fewer along shorter
/// ones (at least 1, at most 256). 2 rather than 3 cube roots: fewer empty
/// cells to step through, measured faster on vase, reflective_refractive and
/// gem (results/tracing_speed.md).
std::unique_ptr<Aggregate> makeGrid(const Object& root, int nx = 0, int ny = 0, int nz = 0);

/// Node width of the BVH: Four (SSE, any x86-64-v2 CPU), Eight (AVX2; only on a CPU that has it, else
/// makeBvh throws) or Automatic, the default: on a CPU with AVX2 both trees, the 8-wide one answering closest
/// hits and the 4-wide one any hits (each measured the faster for its query on three or four mesh scenes of four,
/// results/tracing_speed.md, 2026-11-27, 04:20 UTC; one SAH build collapsed twice, sharing the primitives: twice
/// the nodes), else Four. All give the same hits.
enum class BvhWidth { Automatic, Four, Eight };

/// Whether this CPU runs the 8-wide BVH (has AVX2).
bool bvhEightWideSupported();

/// A bounding volume hierarchy (accel/bvh.h, bvh_build.cpp, bvh_trace.cpp): binned-SAH build, 4-wide
/// nodes tested with SSE or 8-wide nodes tested with AVX2 (bvh_trace_avx2.cpp), ordered closest-hit
/// traversal, early-out any-hit; the same leaf tests either way (bvh_leaf.h), so the same hits.
/// Triangles use a watertight hit test (no ray slips between the triangles
/// of a shared edge) and Triangle::intersect's t, so the closest hit equals
/// brute force's (ties in t to the lower flattened index) except for rays
/// within rounding of an edge, where the watertight test decides.
std::unique_ptr<Aggregate> makeBvh(const Object& root, BvhWidth width = BvhWidth::Automatic);

/// The default accelerator: the BVH when the scene has triangles (measured
/// faster than the grid on every mesh scene, closest and any hit,
/// results/tracing_speed.md), else the grid at resolution nx x ny x nz (0 =
/// automatic) over its spheres and other bounded primitives, as before.
std::unique_ptr<Aggregate> makeDefaultAggregate(const Object& root, int nx = 0, int ny = 0, int nz = 0);

}  // namespace aliaslab
