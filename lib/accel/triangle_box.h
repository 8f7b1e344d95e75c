// Private to accel/: does a triangle overlap an axis-aligned box?
// Separating-axis test (Akenine-Moller 2001): the box axes, the triangle's
// normal and the nine edge x axis cross products. Double precision; callers
// pad the box so the test stays conservative.
#pragma once
#include <Eigen/Core>
#include <cmath>

namespace aliaslab {

inline bool triangleOverlapsBox(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                const Eigen::Vector3d& center, const Eigen::Vector3d& half) {
  const Eigen::Vector3d v[3] = {a - center, b - center, c - center};
  // Box axes
  for (int k = 0; k < 3; ++k) {
    const double lo = std::min({v[0][k], v[1][k], v[2][k]}), hi = std::max({v[0][k], v[1][k], v[2][k]});
    if (lo > half[k] || hi < -half[k]) return false;
  }
  // Edge x box-axis cross products
  const Eigen::Vector3d e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  for (const auto& edge : e)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d axis = edge.cross(Eigen::Vector3d::Unit(k));
      const double p0 = axis.dot(v[0]), p1 = axis.dot(v[1]), p2 = axis.dot(v[2]);
      const double r = half.dot(axis.cwiseAbs());
      if (std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r) return false;
    }
  // Triangle plane
  const Eigen::Vector3d n = e[0].cross(e[1]);
  return std::abs(n.dot(v[0])) <= half.dot(n.cwiseAbs());
}

}  // namespace aliaslab
