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
template <class T>
inline std::array<T, 3> xyzToRgb(const T& x, const T& y, const T& z) {
  return {3.2404542 * x - 1.5371385 * y - 0.4985314 * z, -0.9692660 * x + 1.8760108 * y + 0.0415560 * z,
          0.0556434 * x - 0.2040259 * y + 1.0572252 * z};
}
inline V3 xyzToRgb(const V3& c) { return xyzToRgb(c[0], c[1], c[2]); }
// The opponent space YCxCz: CIELab without the cube root (linear in XYZ).
template <class T>
inline std::array<T, 3> xyzToYcc(const T& x, const T& y, const T& z) {
  return {116.0 * y / kWy - 16.0, 500.0 * (x / kWx - y / kWy), 200.0 * (y / kWy - z / kWz)};
}
inline V3 xyzToYcc(const V3& c) { return xyzToYcc(c[0], c[1], c[2]); }
template <class T>
inline std::array<T, 3> yccToXyz(const T& l, const T& cx, const T& cz) {
  const T y = (l + 16.0) / 116.0;
  return {kWx * (cx / 500.0 + y), kWy * y, kWz * (y - cz / 200.0)};
}
inline V3 yccToXyz(const V3& c) { return yccToXyz(c[0], c[1], c[2]); }
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
