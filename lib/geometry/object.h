// The object protocol.
//
// A scene is a tree of Objects (groups, transforms, primitives) as the scene
// file declares it. Rendering does not walk the tree: an Aggregate
// (accel/aggregate.h) first asks the root to flatten() itself into a list
// of world-space primitives. Triangles are baked into world space (exact for
// affine maps); other primitives under a transform are wrapped in a
// Transform that holds the accumulated matrix. Brute force and the grid both
// test that same list, so they return the same closest hits.
//
// intersect() contract: report a hit only when tmin < t < hit.t; then
// overwrite hit.t, hit.normal (unit, world space, geometric front side) and
// hit.material, and return true. Otherwise leave hit untouched.
#pragma once
#include <memory>
#include <vector>

#include "core/math.h"
#include "core/ray.h"

namespace aliaslab {

class Object {
 public:
  virtual ~Object() = default;

  virtual bool intersect(const Ray& ray, float tmin, Hit& hit) const = 0;

  /// Bounds in the object's parent space; an empty or infinite box for
  /// unbounded objects (planes), which aggregates keep outside any grid.
  virtual BBox bounds() const = 0;

  /// Appends world-space primitives to `out`. `toWorld` is the accumulated
  /// transform of enclosing Transform nodes (identity at the root).
  virtual void flatten(const Mat4& toWorld, std::vector<std::unique_ptr<Object>>& out) const = 0;

  /// An independent copy (used by flatten for primitives kept as they are).
  virtual std::unique_ptr<Object> clone() const = 0;

  /// True for objects with a finite bounding box.
  bool bounded() const {
    BBox b = bounds();
    return !b.empty() && b.finite();
  }
};

using ObjectList = std::vector<std::unique_ptr<Object>>;

}  // namespace aliaslab
