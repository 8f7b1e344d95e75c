// Helpers shared by the primitives' flatten(): an exact identity test and
// the wrapping of a cloned primitive in its accumulated transform.
#pragma once
#include <memory>

#include "geometry/primitives.h"

namespace aliaslab {

/// Appends `prim` as is when `toWorld` is exactly the identity, else wrapped
/// in a Transform holding `toWorld`.
inline void appendWorldPrimitive(const Mat4& toWorld, std::unique_ptr<Object> prim, ObjectList& out) {
  if (toWorld == Mat4::Identity())
    out.push_back(std::move(prim));
  else
    out.push_back(std::make_unique<Transform>(toWorld, std::move(prim)));
}

}  // namespace aliaslab
