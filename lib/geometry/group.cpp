// Group: a list of children; the closest hit among them.
#include "geometry/primitives.h"

namespace aliaslab {

Group::Group(ObjectList children) : children(std::move(children)) {}

bool Group::intersect(const Ray& ray, float tmin, Hit& hit) const {
  bool any = false;
  for (const auto& child : children) any |= child->intersect(ray, tmin, hit);
  return any;
}

BBox Group::bounds() const {
  BBox box;
  for (const auto& child : children) box.extend(child->bounds());
  return box;
}

void Group::flatten(const Mat4& toWorld, ObjectList& out) const {
  for (const auto& child : children) child->flatten(toWorld, out);
}

std::unique_ptr<Object> Group::clone() const {
  ObjectList copies;
  copies.reserve(children.size());
  for (const auto& child : children) copies.push_back(child->clone());
  return std::make_unique<Group>(std::move(copies));
}

}  // namespace aliaslab
