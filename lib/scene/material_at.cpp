// MaterialAt: a material's blend weights evaluated once per hit point; the
// protocol is documented in material.h.
#include "scene/material.h"

namespace aliaslab {

void Material::resolve(const SurfacePoint&, MaterialAt& out) const { out.appendLeaf(this); }

MaterialAt::MaterialAt(const Material& m, const SurfacePoint& p) : material_(&m), p_(p) { m.resolve(p, *this); }

void MaterialAt::appendLeaf(const Material* leaf) {
  if (count_ < kMaxNodes) nodes_[count_++] = {leaf, 0.f, 0.f};
  else overflow_ = true;
}

void MaterialAt::appendBlend(float first, float second) {
  if (count_ < kMaxNodes) nodes_[count_++] = {nullptr, first, second};
  else overflow_ = true;
}

// The nodes are the blend tree in pre-order, pruned as Blend::resolve
// prunes it; this mirrors Blend::mix in material_procedural.cpp.
template <class Query>
auto MaterialAt::evaluate(int& i, Query query) const {
  const Node& node = nodes_[i++];
  if (node.leaf) return query(node.leaf);
  if (node.second <= 0.f || node.first <= 0.f) return evaluate(i, query);  // a pure end: one side only
  const auto first = evaluate(i, query);
  const auto second = evaluate(i, query);
  return decltype(query(node.leaf))(node.first * first + node.second * second);
}

template <class Query>
auto MaterialAt::evaluate(Query query) const {
  if (overflow_) return query(material_);
  int i = 0;
  return evaluate(i, query);
}

Color MaterialAt::shade(const Vec3& n, const Vec3& toViewer, const Vec3& toLight, const Color& lightColor) const {
  return evaluate([&](const Material* m) { return m->shade(p_, n, toViewer, toLight, lightColor); });
}
Color MaterialAt::diffuse() const {
  return evaluate([&](const Material* m) { return m->diffuse(p_); });
}
Color MaterialAt::reflective() const {
  return evaluate([&](const Material* m) { return m->reflective(p_); });
}
Color MaterialAt::transparent() const {
  return evaluate([&](const Material* m) { return m->transparent(p_); });
}
float MaterialAt::indexOfRefraction() const {
  return evaluate([&](const Material* m) { return m->indexOfRefraction(p_); });
}

}  // namespace aliaslab
