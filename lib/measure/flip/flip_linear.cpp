// Stage 1 of LDR-FLIP (flip_planes.h): the contrast sensitivity filters of the opponent channels and the
// Gaussian-derivative responses of the luminance, as exact separable sums (flip_convolve.cpp).
#include <algorithm>
#include <cmath>

#include "measure/flip/flip.h"
#include "measure/flip/flip_colour.h"
#include "measure/flip/flip_planes.h"

namespace aliaslab {
namespace {

using namespace flipcolour;

constexpr double kFeatureWidth = 0.082;

/// The three opponent channels of an image (clamped to [0, 1]) after the contrast sensitivity filters, back in
/// linear RGB clamped to [0, 1].
void filteredRgb(const Image& img, double ppd, std::array<std::vector<double>, 3>& rgbOut) {
  const int w = img.width(), h = img.height();
  const size_t n = static_cast<size_t>(w) * h;
  std::array<std::vector<double>, 3> ycc;
  for (auto& p : ycc) p.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const float* c = img.data() + 3 * i;
    const V3 v = xyzToYcc(rgbToXyz(V3{std::clamp<double>(c[0], 0, 1), std::clamp<double>(c[1], 0, 1),
                                      std::clamp<double>(c[2], 0, 1)}));
    for (int k = 0; k < 3; ++k) ycc[k][i] = std::isfinite(v[k]) ? v[k] : 0.0;
  }
  // CSF of each channel as a sum of two Gaussians a sqrt(pi / b) exp(-pi^2 x^2 / b), x in degrees
  struct Csf { double a1, b1, a2, b2; };
  const Csf csf[3] = {{1, 0.0047, 0, 1e-5}, {1, 0.0053, 0, 1e-5}, {34.1, 0.04, 13.5, 0.025}};
  const double bMax = 0.04;
  const int r = static_cast<int>(std::ceil(3 * std::sqrt(bMax / (2 * M_PI * M_PI)) * ppd));
  for (int c = 0; c < 3; ++c) {
    std::vector<double> e1(2 * r + 1), e2(2 * r + 1);
    double s1 = 0, s2 = 0;
    for (int k = -r; k <= r; ++k) {
      const double x = k / ppd;
      e1[k + r] = std::exp(-M_PI * M_PI * x * x / csf[c].b1), s1 += e1[k + r];
      e2[k + r] = std::exp(-M_PI * M_PI * x * x / csf[c].b2), s2 += e2[k + r];
    }
    // kernel = A1 e1(x) e1(y) + A2 e2(x) e2(y), normalised to sum 1
    const double A1 = csf[c].a1 * std::sqrt(M_PI / csf[c].b1), A2 = csf[c].a2 * std::sqrt(M_PI / csf[c].b2);
    const double total = A1 * s1 * s1 + A2 * s2 * s2;
    std::vector<double> out = convolveClamped(ycc[c], w, h, e1, e1);
    if (A2 > 0) {
      const std::vector<double> second = convolveClamped(ycc[c], w, h, e2, e2);
      for (size_t i = 0; i < n; ++i) out[i] = A1 * out[i] + A2 * second[i];
    } else {
      for (double& v : out) v *= A1;
    }
    for (double& v : out) v /= total;
    ycc[c] = std::move(out);
  }
  for (auto& p : rgbOut) p.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const V3 rgb = xyzToRgb(yccToXyz({ycc[0][i], ycc[1][i], ycc[2][i]}));
    for (int k = 0; k < 3; ++k) rgbOut[k][i] = std::clamp(rgb[k], 0.0, 1.0);
  }
}

/// Edge and point responses of the luminance ((Y' + 16) / 116 = Y) with the first and second derivatives of a
/// Gaussian of sd = 0.5 * 0.082 deg * ppd; each kernel's positive weights sum to 1 and its negative ones to -1.
void features(const Image& img, double ppd, FlipLinear& out) {
  const int w = img.width(), h = img.height();
  const size_t n = static_cast<size_t>(w) * h;
  std::vector<double> y(n);
  for (size_t i = 0; i < n; ++i) {
    const float* c = img.data() + 3 * i;
    y[i] = rgbToXyz(V3{std::clamp<double>(c[0], 0, 1), std::clamp<double>(c[1], 0, 1),
                       std::clamp<double>(c[2], 0, 1)})[1];
    if (!std::isfinite(y[i])) y[i] = 0;
  }
  const double sd = 0.5 * kFeatureWidth * ppd;
  const int r = static_cast<int>(std::ceil(3 * sd));
  std::vector<double> g(2 * r + 1), d1(2 * r + 1), d2p(2 * r + 1), d2n(2 * r + 1);
  double sg = 0, pos1 = 0, pos2 = 0, neg2 = 0;
  for (int k = -r; k <= r; ++k) {
    const double e = std::exp(-(k * k) / (2 * sd * sd));
    g[k + r] = e, sg += e;
    d1[k + r] = -k * e;
    if (d1[k + r] > 0) pos1 += d1[k + r];
    const double s = (k * k / (sd * sd) - 1) * e;
    d2p[k + r] = std::max(s, 0.0), d2n[k + r] = std::min(s, 0.0);
    pos2 += d2p[k + r], neg2 += d2n[k + r];
  }
  // 2-D sums of the separable products: (positive sum along one axis) x (sum of g along the other)
  const std::vector<double> smoothX = convolveX(y, w, h, g);  // shared by the three y-derivative planes
  const std::vector<double> ex = convolveClamped(y, w, h, d1, g), ey = convolveY(smoothX, w, h, d1);
  const std::vector<double> pxp = convolveClamped(y, w, h, d2p, g), pxn = convolveClamped(y, w, h, d2n, g);
  const std::vector<double> pyp = convolveY(smoothX, w, h, d2p), pyn = convolveY(smoothX, w, h, d2n);
  out.gx.resize(n), out.gy.resize(n), out.px.resize(n), out.py.resize(n);
  for (size_t i = 0; i < n; ++i) {
    out.gx[i] = ex[i] / (pos1 * sg), out.gy[i] = ey[i] / (pos1 * sg);
    out.px[i] = pxp[i] / (pos2 * sg) + pxn[i] / (-neg2 * sg), out.py[i] = pyp[i] / (pos2 * sg) + pyn[i] / (-neg2 * sg);
  }
}

}  // namespace

FlipLinear flipLinear(const Image& img, double ppd) {
  FlipLinear out;
  out.width = img.width(), out.height = img.height();
  filteredRgb(img, ppd, out.rgb);
  features(img, ppd, out);
  return out;
}

}  // namespace aliaslab
