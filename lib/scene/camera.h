// Cameras map a point of the square screen [0,1]^2 to a ray. The film is
// mapped onto that square by filmToScreen(): the larger image side spans
// 0..1 and the smaller one is centred inside it.
#pragma once
#include <memory>

#include "core/math.h"
#include "core/ray.h"

namespace aliaslab {

class Camera {
 public:
  virtual ~Camera() = default;
  virtual Ray generateRay(const Vec2& screen) const = 0;
  /// Smallest t a primary ray accepts: -infinity for orthographic cameras
  /// (everything along the viewing line is seen), 0 for perspective.
  virtual float tMin() const = 0;
};

/// Film position (continuous pixels, y up) to the camera's square screen.
inline Vec2 filmToScreen(float fx, float fy, int width, int height) {
  const float side = static_cast<float>(width > height ? width : height);
  return Vec2((fx - 0.5f * width) / side + 0.5f, (fy - 0.5f * height) / side + 0.5f);
}

/// OrthographicCamera { center P direction D up U size S }
std::unique_ptr<Camera> makeOrthographicCamera(const Vec3& center, const Vec3& direction,
                                               const Vec3& up, float size);
/// PerspectiveCamera { center P direction D up U angle A } (A: full field of view, degrees)
std::unique_ptr<Camera> makePerspectiveCamera(const Vec3& center, const Vec3& direction,
                                              const Vec3& up, float angleDegrees);

}  // namespace aliaslab
