// Cameras map a point of the square screen [0,1]^2 to a ray. The film is
// mapped onto that square by filmToScreen(): the larger image side spans
// 0..1 and the smaller one is centred inside it.
#pragma once
#include <memory>
#include <string>

#include "core/math.h"
#include "core/ray.h"

namespace aliaslab {

/// Derivatives of a camera ray's origin and unit direction with respect to
/// the screen coordinates sx and sy (ray differentials, Igehy 1999).
struct RayDerivatives {
  Vec3 dOriginDx = Vec3::Zero(), dOriginDy = Vec3::Zero();
  Vec3 dDirectionDx = Vec3::Zero(), dDirectionDy = Vec3::Zero();
};

class Camera {
 public:
  virtual ~Camera() = default;
  virtual Ray generateRay(const Vec2& screen) const = 0;
  /// d(origin)/d(screen) and d(direction)/d(screen) of generateRay(screen), analytically.
  virtual RayDerivatives rayDerivatives(const Vec2& screen) const = 0;
  /// Smallest t a primary ray accepts: -infinity for orthographic cameras
  /// (everything along the viewing line is seen), 0 for perspective.
  virtual float tMin() const = 0;
  /// One line: kind and every parameter, e.g. "perspective center (0 1 5) direction (0 0 -1) up (0 1 0) angle 40".
  virtual std::string describe() const = 0;
};

/// Film position (continuous pixels, y up) to the camera's square screen.
inline Vec2 filmToScreen(float fx, float fy, int width, int height) {
  const float side = static_cast<float>(width > height ? width : height);
  return Vec2((fx - 0.5f * width) / side + 0.5f, (fy - 0.5f * height) / side + 0.5f);
}

/// Camera motion (frames of an animation, docs/science.md "Motion"): frame t of a motion of (dx, dy) pixels per
/// frame moves the camera by (t dx, t dy) pixels parallel to the image plane, so film position p of frame t
/// sees what film position p + t (dx, dy) saw in frame 0 (the picture moves by -t (dx, dy)). It is applied as an
/// offset of the screen point given to the camera: exactly a translation for an orthographic camera, a shift
/// of the image plane (lens shift) for a perspective one. Offset zero leaves every ray bit-identical.
inline Vec2 frameScreenOffset(int frame, double dx, double dy, int width, int height) {
  const double side = width > height ? width : height;
  return Vec2(static_cast<float>(frame * dx / side), static_cast<float>(frame * dy / side));
}
/// `base` seen through a screen offset: generateRay(s) = base.generateRay(s + offset), likewise its
/// derivatives; describe() adds " shifted by (ox oy) screen". Keeps a reference to `base`, which must outlive it.
std::unique_ptr<Camera> makeShiftedCamera(const Camera& base, const Vec2& offset);

// Both factories normalise D, make U perpendicular to D (Gram-Schmidt) and
// take horizontal = D x U. They throw InputError("camera: ...") when D is
// zero or U is zero or parallel to D (the parser adds the file and line).

/// OrthographicCamera { center P direction D up U size S }: screen (sx, sy)
/// gives origin P + (sx - 0.5) S horizontal + (sy - 0.5) S up, direction D.
std::unique_ptr<Camera> makeOrthographicCamera(const Vec3& center, const Vec3& direction,
                                               const Vec3& up, float size);
/// PerspectiveCamera { center P direction D up U angle A } (A: full field of view, degrees):
/// origin P, direction normalize(D + (2sx-1) tan(A/2) horizontal + (2sy-1) tan(A/2) up).
std::unique_ptr<Camera> makePerspectiveCamera(const Vec3& center, const Vec3& direction,
                                              const Vec3& up, float angleDegrees);

}  // namespace aliaslab
