// Basic numeric types shared by every layer.
//
// Geometry is single precision (Eigen fixed-size vectors); anything that
// accumulates many samples uses double (see film/ and study/).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace aliaslab {

using Vec2 = Eigen::Vector2f;
using Vec3 = Eigen::Vector3f;
using Vec4 = Eigen::Vector4f;
using Mat3 = Eigen::Matrix3f;
using Mat4 = Eigen::Matrix4f;
using Color = Eigen::Array3f;  ///< linear RGB radiance, never clamped before reconstruction

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInf = std::numeric_limits<float>::infinity();

/// Axis-aligned bounding box; empty when min > max.
struct BBox {
  Vec3 min = Vec3::Constant(kInf);
  Vec3 max = Vec3::Constant(-kInf);

  bool empty() const { return (min.array() > max.array()).any(); }
  bool finite() const { return min.allFinite() && max.allFinite(); }
  void extend(const Vec3& p) { min = min.cwiseMin(p); max = max.cwiseMax(p); }
  void extend(const BBox& b) { min = min.cwiseMin(b.min); max = max.cwiseMax(b.max); }
  Vec3 extent() const { return max - min; }
  /// Box of the 8 transformed corners of this box.
  BBox transformed(const Mat4& m) const {
    BBox out;
    for (int c = 0; c < 8; ++c) {
      Vec4 p((c & 1) ? max.x() : min.x(), (c & 2) ? max.y() : min.y(), (c & 4) ? max.z() : min.z(), 1.f);
      Vec4 q = m * p;
      out.extend(Vec3(q.head<3>() / q.w()));
    }
    return out;
  }
};

}  // namespace aliaslab
