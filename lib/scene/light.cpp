// Directional and point lights.
#include <cmath>
#include <sstream>

#include "core/format.h"
#include "scene/light.h"

namespace aliaslab {
namespace {

class DirectionalLight final : public Light {
 public:
  DirectionalLight(const Vec3& direction, const Color& color)
      : toLight_(-direction.normalized()), color_(color) {}
  void illuminate(const Vec3&, Vec3& toLight, Color& color, float& distance) const override {
    toLight = toLight_;
    color = color_;
    distance = kInf;
  }
  std::string describe() const override {
    return "directional direction " + formatVector(Vec3(-toLight_)) + " color " + formatVector(color_);
  }

 private:
  Vec3 toLight_;
  Color color_;
};

class PointLight final : public Light {
 public:
  PointLight(const Vec3& position, const Color& color, float c0, float c1, float c2)
      : position_(position), color_(color), c0_(c0), c1_(c1), c2_(c2) {}
  void illuminate(const Vec3& p, Vec3& toLight, Color& color, float& distance) const override {
    const Vec3 d = position_ - p;
    distance = d.norm();
    toLight = distance > 0.f ? Vec3(d / distance) : Vec3::UnitZ();
    color = color_ / (c0_ + c1_ * distance + c2_ * distance * distance);
  }
  std::string describe() const override {
    return "point position " + formatVector(position_) + " color " + formatVector(color_) + " attenuation " + formatVector(Vec3(c0_, c1_, c2_));
  }

 private:
  Vec3 position_;
  Color color_;
  float c0_, c1_, c2_;
};

}  // namespace

std::unique_ptr<Light> makeDirectionalLight(const Vec3& direction, const Color& color) {
  return std::make_unique<DirectionalLight>(direction, color);
}

std::unique_ptr<Light> makePointLight(const Vec3& position, const Color& color, float c0, float c1, float c2) {
  return std::make_unique<PointLight>(position, color, c0, c1, c2);
}

}  // namespace aliaslab
