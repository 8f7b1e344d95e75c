// Stages 2 and 3 of LDR-FLIP as defined (flip_planes.h, flip_definition.h): libm in double, pixel by pixel.
#include "measure/flip/flip_definition.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "measure/flip/flip_colour.h"
#include "measure/flip/flip_planes.h"

namespace aliaslab {
namespace {

using namespace flipcolour;

constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95, kQf = 0.5;

double labF(double t) { return t > kLabD3 ? std::cbrt(t) : labLinear(t); }
/// CIELab with the Hunt effect (chroma scaled by 0.01 L) of a linear RGB colour.
V3 huntLab(const V3& rgb) {
  const V3 x = rgbToXyz(rgb);
  return huntFromF(labF(x[0] / kWx), labF(x[1] / kWy), labF(x[2] / kWz));
}
/// HyAB: city-block in lightness, Euclidean in chroma.
double hyab(const V3& p, const V3& q) { return std::abs(p[0] - q[0]) + std::hypot(p[1] - q[1], p[2] - q[2]); }

}  // namespace

double flipColourMax() {
  static const double cmax = std::pow(hyab(huntLab({0, 1, 0}), huntLab({0, 0, 1})), kQc);
  return cmax;
}

FlipPlanes flipPlanesDefinition(const FlipLinear& lin) {
  FlipPlanes p;
  p.width = lin.width, p.height = lin.height;
  const size_t n = lin.gx.size();
  p.L.resize(n), p.a.resize(n), p.b.resize(n), p.edge.resize(n), p.point.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const V3 lab = huntLab({lin.rgb[0][i], lin.rgb[1][i], lin.rgb[2][i]});
    p.L[i] = lab[0], p.a[i] = lab[1], p.b[i] = lab[2];
    p.edge[i] = std::hypot(lin.gx[i], lin.gy[i]), p.point[i] = std::hypot(lin.px[i], lin.py[i]);
  }
  return p;
}

void flipCombineDefinition(const FlipPlanes& t, const FlipPlanes& r, float* out) {
  const double cmax = flipColourMax();
  for (size_t i = 0; i < t.L.size(); ++i) {
    const double dc = std::pow(hyab({t.L[i], t.a[i], t.b[i]}, {r.L[i], r.a[i], r.b[i]}), kQc);
    const double ec = dc < kPc * cmax ? dc * kPt / (kPc * cmax)
                                      : kPt + (dc - kPc * cmax) / (cmax - kPc * cmax) * (1 - kPt);
    const double ef = std::pow(std::max(std::abs(t.edge[i] - r.edge[i]), std::abs(t.point[i] - r.point[i])) /
                                   std::sqrt(2.0), kQf);
    out[i] = static_cast<float>(std::clamp(std::pow(std::min(ec, 1.0), 1 - std::min(ef, 1.0)), 0.0, 1.0));
  }
}

std::vector<float> flipMapDefinition(const Image& test, const Image& reference, double ppd) {
  if (test.width() != reference.width() || test.height() != reference.height())
    throw std::invalid_argument("flipMap: images of different sizes");
  const FlipPlanes t = flipPlanesDefinition(flipLinear(test, ppd));
  const FlipPlanes r = flipPlanesDefinition(flipLinear(reference, ppd));
  std::vector<float> out(t.L.size());
  flipCombineDefinition(t, r, out.data());
  return out;
}

double meanFlipDefinition(const Image& test, const Image& reference, double ppd) {
  const std::vector<float> m = flipMapDefinition(test, reference, ppd);
  double s = 0;
  for (float v : m) s += v;
  return m.empty() ? 0.0 : s / m.size();
}

}  // namespace aliaslab
