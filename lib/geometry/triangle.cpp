// Triangle: Moller-Trumbore via geometry/triangle_math.h.
#include "geometry/primitives.h"
#include "geometry/triangle_math.h"

namespace aliaslab {

Triangle::Triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Material* material)
    : a(a), b(b), c(c), material(material) {}

bool Triangle::intersect(const Ray& ray, float tmin, Hit& hit) const {
  const Vec3 e1 = b - a, e2 = c - a;
  float t;
  if (!intersectTriangle(ray, a, e1, e2, tmin, hit.t, t)) return false;
  hit.t = t;
  hit.normal = triangleNormal(e1, e2);
  hit.material = material;
  return true;
}

BBox Triangle::bounds() const {
  BBox box;
  box.extend(a);
  box.extend(b);
  box.extend(c);
  return box;
}

void Triangle::flatten(const Mat4& toWorld, ObjectList& out) const {
  const auto toW = [&](const Vec3& p) -> Vec3 {
    return toWorld.topLeftCorner<3, 3>() * p + toWorld.topRightCorner<3, 1>();
  };
  out.push_back(std::make_unique<Triangle>(toW(a), toW(b), toW(c), material));
}

std::unique_ptr<Object> Triangle::clone() const { return std::make_unique<Triangle>(*this); }

}  // namespace aliaslab
