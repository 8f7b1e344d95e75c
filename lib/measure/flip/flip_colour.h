// The colour formulas of LDR-FLIP (docs/flip.md), shared by its stages (flip_planes.h): linear sRGB <-> XYZ
// (D65), the opponent space YCxCz and Hunt-adjusted CIELab. Templates over the number type, so the fast stages
// apply the very same operations to several pixels at once (T = a GCC vector of doubles).
#pragma once
#include <array>
#include <cmath>

namespace aliaslab::flipcolour {
namespace {  // one copy per translation unit (flip_fastmath.h says why)

using V3 = std::array<double, 3>;

// D65 white of linear sRGB in XYZ.
constexpr double kWx = 0.950428545, kWy = 1.0, kWz = 1.088900371;
// CIELab's threshold between the cube root and the linear part: (6/29)^3.
constexpr double kLabD = 6.0 / 29.0, kLabD3 = kLabD * kLabD * kLabD;

template <class T>
inline std::array<T, 3> rgbToXyz(const T& r, const T& g, const T& b) {
  return {0.4124564 * r + 0.3575761 * g + 0.1804375 * b, 0.2126729 * r + 0.7151522 * g + 0.0721750 * b,
          0.0193339 * r + 0.1191920 * g + 0.9503041 * b};
}
inline V3 rgbToXyz(const V3& c) { return rgbToXyz(c[0], c[1], c[2]); }
inline V3 xyzToRgb(const V3& c) {
  return {3.2404542 * c[0] - 1.5371385 * c[1] - 0.4985314 * c[2],
          -0.9692660 * c[0] + 1.8760108 * c[1] + 0.0415560 * c[2],
          0.0556434 * c[0] - 0.2040259 * c[1] + 1.0572252 * c[2]};
}
// The opponent space YCxCz: CIELab without the cube root (linear in XYZ).
inline V3 xyzToYcc(const V3& c) {
  return {116 * c[1] / kWy - 16, 500 * (c[0] / kWx - c[1] / kWy), 200 * (c[1] / kWy - c[2] / kWz)};
}
inline V3 yccToXyz(const V3& c) {
  const double y = (c[0] + 16) / 116;
  return {kWx * (c[1] / 500 + y), kWy * y, kWz * (y - c[2] / 200)};
}
/// CIELab's f below its threshold (the linear part).
template <class T>
inline T labLinear(const T& t) {
  return t / (3 * kLabD * kLabD) + 4.0 / 29.0;
}
/// Hunt-adjusted Lab from the three f values: L, then a and b scaled by 0.01 L.
template <class T>
inline std::array<T, 3> huntFromF(const T& fx, const T& fy, const T& fz) {
  const T L = 116 * fy - 16, a = 500 * (fx - fy), b = 200 * (fy - fz);
  return {L, 0.01 * L * a, 0.01 * L * b};
}

}  // namespace
}  // namespace aliaslab::flipcolour
