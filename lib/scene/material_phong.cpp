// PhongMaterial: Blinn-Phong direct light, constant colours.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/format.h"
#include "scene/material.h"

namespace aliaslab {
namespace {

class Phong final : public Material {
 public:
  explicit Phong(const PhongParams& params) : p_(params) {}

  Color shade(const SurfacePoint&, const Vec3& n, const Vec3& toViewer, const Vec3& toLight,
              const Color& lightColor) const override {
    const float nl = n.dot(toLight);
    if (!(nl > 0.f)) return Color::Zero();
    Color c = p_.diffuse * nl;
    if ((p_.specular != 0.f).any()) {
      const Vec3 h = (toLight + toViewer).normalized();
      const float nh = std::max(0.f, n.dot(h));
      c += p_.specular * std::pow(nh, p_.exponent);
    }
    return lightColor * c;
  }
  Color diffuse(const SurfacePoint&) const override { return p_.diffuse; }
  Color reflective(const SurfacePoint&) const override { return p_.reflective; }
  Color transparent(const SurfacePoint&) const override { return p_.transparent; }
  float indexOfRefraction(const SurfacePoint&) const override { return p_.indexOfRefraction; }
  std::string describe() const override {
    std::ostringstream out;
    out << "phong diffuse " << formatVector(p_.diffuse) << " specular " << formatVector(p_.specular) << " exponent " << p_.exponent
        << " reflective " << formatVector(p_.reflective) << " transparent " << formatVector(p_.transparent) << " ior "
        << p_.indexOfRefraction;
    return out.str();
  }

 private:
  PhongParams p_;
};

}  // namespace

std::unique_ptr<Material> makePhong(const PhongParams& params) { return std::make_unique<Phong>(params); }

}  // namespace aliaslab
