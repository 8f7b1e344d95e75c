// Transform: the ray goes into object space (direction not renormalised, so
// t is the same in both spaces); the normal comes back by the inverse
// transpose and is renormalised.
#include "geometry/primitives.h"

namespace aliaslab {

Transform::Transform(const Mat4& matrix, std::unique_ptr<Object> child)
    : matrix(matrix),
      inverse(matrix.inverse()),
      normalMatrix(matrix.topLeftCorner<3, 3>().inverse().transpose()),
      child(std::move(child)) {}

bool Transform::intersect(const Ray& ray, float tmin, Hit& hit) const {
  Ray local;
  local.origin = inverse.topLeftCorner<3, 3>() * ray.origin + inverse.topRightCorner<3, 1>();
  local.direction = inverse.topLeftCorner<3, 3>() * ray.direction;
  Hit h = hit;
  if (!child->intersect(local, tmin, h)) return false;
  h.normal = (normalMatrix * h.normal).normalized();
  hit = h;
  return true;
}

BBox Transform::bounds() const {
  const BBox b = child->bounds();
  if (b.empty()) return b;
  if (!b.finite()) return BBox{Vec3::Constant(-kInf), Vec3::Constant(kInf)};
  return b.transformed(matrix);
}

void Transform::flatten(const Mat4& toWorld, ObjectList& out) const {
  child->flatten(toWorld * matrix, out);
}

std::unique_ptr<Object> Transform::clone() const {
  return std::make_unique<Transform>(matrix, child->clone());
}

}  // namespace aliaslab
