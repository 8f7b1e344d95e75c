// Lights. illuminate() gives, for a point, the unit direction towards the
// light, the colour arriving there, and the distance to the light
// (infinity for directional lights) so shadow rays know where to stop.
#pragma once
#include <memory>
#include <string>

#include "core/math.h"

namespace aliaslab {

class Light {
 public:
  virtual ~Light() = default;
  virtual void illuminate(const Vec3& p, Vec3& toLight, Color& color, float& distance) const = 0;
  /// One line: kind and every parameter.
  virtual std::string describe() const = 0;
};

/// DirectionalLight { direction D color C }: D is the direction light travels.
std::unique_ptr<Light> makeDirectionalLight(const Vec3& direction, const Color& color);

/// PointLight { position P color C [attenuation c0 c1 c2] }: C / (c0 + c1 d + c2 d^2).
std::unique_ptr<Light> makePointLight(const Vec3& position, const Color& color, float c0 = 1.f,
                                      float c1 = 0.f, float c2 = 0.f);

}  // namespace aliaslab
