// Orthographic and perspective cameras over the square screen [0,1]^2.
#include <cmath>
#include <sstream>

#include "core/format.h"
#include "scene/camera.h"

#include "core/error.h"

namespace aliaslab {
namespace {

/// Orthonormal frame: unit direction, up made perpendicular to it
/// (Gram-Schmidt), horizontal = direction x up.
struct Frame {
  Vec3 direction, up, horizontal;
  Frame(const Vec3& d, const Vec3& u) {
    if (!d.allFinite() || d.norm() == 0.f) throw InputError("camera: direction must be a non-zero vector");
    direction = d.normalized();
    const Vec3 perpendicular = u - u.dot(direction) * direction;
    if (!perpendicular.allFinite() || perpendicular.norm() <= 1e-6f * u.norm())
      throw InputError("camera: up must not be zero or parallel to direction");
    up = perpendicular.normalized();
    horizontal = direction.cross(up);
  }
};

class OrthographicCamera final : public Camera {
 public:
  OrthographicCamera(const Vec3& center, const Frame& frame, float size)
      : center_(center), f_(frame), size_(size) {}
  std::string describe() const override {
    std::ostringstream out;
    out << "orthographic center " << formatVector(center_) << " direction " << formatVector(f_.direction) << " up " << formatVector(f_.up)
        << " size " << size_;
    return out.str();
  }
  Ray generateRay(const Vec2& s) const override {
    Ray r;
    r.origin = center_ + (s.x() - 0.5f) * size_ * f_.horizontal + (s.y() - 0.5f) * size_ * f_.up;
    r.direction = f_.direction;
    return r;
  }
  RayDerivatives rayDerivatives(const Vec2&) const override {
    RayDerivatives d;
    d.dOriginDx = size_ * f_.horizontal, d.dOriginDy = size_ * f_.up;
    return d;
  }
  float tMin() const override { return -kInf; }

 private:
  Vec3 center_;
  Frame f_;
  float size_;
};

class PerspectiveCamera final : public Camera {
 public:
  PerspectiveCamera(const Vec3& center, const Frame& frame, float angleDegrees)
      : center_(center), f_(frame), angle_(angleDegrees), tanHalf_(std::tan(0.5f * angleDegrees * kPi / 180.f)) {}
  std::string describe() const override {
    std::ostringstream out;
    out << "perspective center " << formatVector(center_) << " direction " << formatVector(f_.direction) << " up " << formatVector(f_.up)
        << " angle " << angle_;
    return out.str();
  }
  Ray generateRay(const Vec2& s) const override {
    Ray r;
    r.origin = center_;
    r.direction = (f_.direction + (2.f * s.x() - 1.f) * tanHalf_ * f_.horizontal +
                   (2.f * s.y() - 1.f) * tanHalf_ * f_.up)
                      .normalized();
    return r;
  }
  // direction = v / |v|, v = D + (2sx-1) tan H + (2sy-1) tan U:
  // d(v/|v|) = (dv - (dv . v/|v|) v/|v|) / |v| with dv/dsx = 2 tan H, dv/dsy = 2 tan U.
  RayDerivatives rayDerivatives(const Vec2& s) const override {
    const Vec3 v = f_.direction + (2.f * s.x() - 1.f) * tanHalf_ * f_.horizontal + (2.f * s.y() - 1.f) * tanHalf_ * f_.up;
    const float len = v.norm();
    const Vec3 u = v / len;
    auto unit = [&](const Vec3& dv) { return Vec3((dv - dv.dot(u) * u) / len); };
    RayDerivatives d;
    d.dDirectionDx = unit(2.f * tanHalf_ * f_.horizontal);
    d.dDirectionDy = unit(2.f * tanHalf_ * f_.up);
    return d;
  }
  float tMin() const override { return 0.f; }

 private:
  Vec3 center_;
  Frame f_;
  float angle_, tanHalf_;
};

class ShiftedCamera final : public Camera {
 public:
  ShiftedCamera(const Camera& base, const Vec2& offset) : base_(base), offset_(offset) {}
  Ray generateRay(const Vec2& s) const override { return base_.generateRay(s + offset_); }
  RayDerivatives rayDerivatives(const Vec2& s) const override { return base_.rayDerivatives(s + offset_); }
  float tMin() const override { return base_.tMin(); }
  std::string describe() const override {
    std::ostringstream out;
    out << base_.describe() << " shifted by (" << offset_.x() << " " << offset_.y() << ") screen";
    return out.str();
  }

 private:
  const Camera& base_;
  Vec2 offset_;
};

}  // namespace

std::unique_ptr<Camera> makeShiftedCamera(const Camera& base, const Vec2& offset) {
  return std::make_unique<ShiftedCamera>(base, offset);
}

std::unique_ptr<Camera> makeOrthographicCamera(const Vec3& center, const Vec3& direction, const Vec3& up,
                                               float size) {
  return std::make_unique<OrthographicCamera>(center, Frame(direction, up), size);
}

std::unique_ptr<Camera> makePerspectiveCamera(const Vec3& center, const Vec3& direction, const Vec3& up,
                                              float angleDegrees) {
  return std::make_unique<PerspectiveCamera>(center, Frame(direction, up), angleDegrees);
}

}  // namespace aliaslab
