// Rays and ray-surface hits.
#pragma once
#include "core/math.h"

namespace aliaslab {

class Material;

/// origin + t * direction. The direction need not be unit length (rays
/// transformed into object space are not); t is measured in its units.
struct Ray {
  Vec3 origin = Vec3::Zero();
  Vec3 direction = Vec3::UnitZ();
  Vec3 at(float t) const { return origin + t * direction; }
};

/// The closest hit found so far. Intersection routines only ever shrink t:
/// an object reports a hit when tmin < t' < hit.t and then overwrites the
/// record. Start with Hit{} (t = infinity) for a closest-hit query.
struct Hit {
  float t = kInf;
  Vec3 normal = Vec3::Zero();          ///< world-space, unit length, facing the front side
  const Material* material = nullptr;  ///< the material current where the object was declared
  int primitive = -1;                  ///< index of the primitive in its aggregate (for tests)
  bool found() const { return t < kInf; }
};

}  // namespace aliaslab
