// Sphere: the quadratic |o + t d - C|^2 = R^2 for a direction of any length.
#include <cmath>

#include "geometry/flatten_util.h"
#include "geometry/primitives.h"

namespace aliaslab {

Sphere::Sphere(const Vec3& center, float radius, const Material* material)
    : center(center), radius(radius), material(material) {}

bool Sphere::intersect(const Ray& ray, float tmin, Hit& hit) const {
  // a t^2 + 2 h t + c = 0 with a = d.d, h = d.(o - C), c = |o - C|^2 - R^2
  const Vec3 oc = ray.origin - center;
  const float a = ray.direction.squaredNorm();
  const float h = ray.direction.dot(oc);
  const float c = oc.squaredNorm() - radius * radius;
  const float disc = h * h - a * c;
  if (!(disc >= 0.f) || a == 0.f) return false;
  // Stable roots: q = -(h + sign(h) sqrt(disc)), t = q / a and c / q.
  const float q = -(h + std::copysign(std::sqrt(disc), h));
  float t0 = q / a;
  float t1 = q != 0.f ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  float t;
  if (t0 > tmin && t0 < hit.t)
    t = t0;
  else if (t1 > tmin && t1 < hit.t)
    t = t1;
  else
    return false;
  hit.t = t;
  hit.normal = (ray.at(t) - center).normalized();
  hit.material = material;
  return true;
}

BBox Sphere::bounds() const {
  const Vec3 r = Vec3::Constant(std::abs(radius));
  return BBox{center - r, center + r};
}

void Sphere::flatten(const Mat4& toWorld, ObjectList& out) const {
  appendWorldPrimitive(toWorld, clone(), out);
}

std::unique_ptr<Object> Sphere::clone() const { return std::make_unique<Sphere>(*this); }

}  // namespace aliaslab
