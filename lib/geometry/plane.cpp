// Plane: n.P = d for the n given (stored as n / |n| and d / |n|, the same
// plane), hit at t = (d - n.o) / (n.d).
#include "geometry/flatten_util.h"
#include "geometry/primitives.h"

namespace aliaslab {

Plane::Plane(const Vec3& normal, float offset, const Material* material)
    : normal(normal.normalized()), offset(offset / normal.norm()), material(material) {}

bool Plane::intersect(const Ray& ray, float tmin, Hit& hit) const {
  const float nd = normal.dot(ray.direction);
  if (nd == 0.f) return false;  // parallel
  const float t = (offset - normal.dot(ray.origin)) / nd;
  if (!(t > tmin && t < hit.t)) return false;
  hit.t = t;
  hit.normal = normal;
  hit.material = material;
  return true;
}

BBox Plane::bounds() const { return BBox{Vec3::Constant(-kInf), Vec3::Constant(kInf)}; }

void Plane::flatten(const Mat4& toWorld, ObjectList& out) const {
  appendWorldPrimitive(toWorld, clone(), out);
}

std::unique_ptr<Object> Plane::clone() const { return std::make_unique<Plane>(*this); }

}  // namespace aliaslab
