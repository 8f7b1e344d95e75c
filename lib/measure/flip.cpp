// LDR-FLIP (flip.h, docs/flip.md): colour pipeline (contrast sensitivity
// filters in the opponent space YCxCz, then the Hunt-adjusted HyAB
// distance, compressed and remapped) and feature pipeline (edges and points
// of the luminance), combined per pixel as colour^(1 - feature).
#include "measure/flip.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <stdexcept>

// 256-bit vectors are passed only between functions inlined into one built for AVX2 (GCC's -Wpsabi note).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace aliaslab {
namespace {

using V3 = std::array<double, 3>;

// D65 white of linear sRGB in XYZ.
constexpr double kWx = 0.950428545, kWy = 1.0, kWz = 1.088900371;

V3 rgbToXyz(const V3& c) {
  return {0.4124564 * c[0] + 0.3575761 * c[1] + 0.1804375 * c[2],
          0.2126729 * c[0] + 0.7151522 * c[1] + 0.0721750 * c[2],
          0.0193339 * c[0] + 0.1191920 * c[1] + 0.9503041 * c[2]};
}
V3 xyzToRgb(const V3& c) {
  return {3.2404542 * c[0] - 1.5371385 * c[1] - 0.4985314 * c[2],
          -0.9692660 * c[0] + 1.8760108 * c[1] + 0.0415560 * c[2],
          0.0556434 * c[0] - 0.2040259 * c[1] + 1.0572252 * c[2]};
}
// The opponent space YCxCz: CIELab without the cube root (linear in XYZ).
V3 xyzToYcc(const V3& c) {
  return {116 * c[1] / kWy - 16, 500 * (c[0] / kWx - c[1] / kWy), 200 * (c[1] / kWy - c[2] / kWz)};
}
V3 yccToXyz(const V3& c) {
  const double y = (c[0] + 16) / 116;
  return {kWx * (c[1] / 500 + y), kWy * y, kWz * (y - c[2] / 200)};
}
double labF(double t) {
  constexpr double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29.0;
}
/// CIELab with the Hunt effect (chroma scaled by 0.01 L) of a linear RGB colour.
V3 huntLab(const V3& rgb) {
  const V3 x = rgbToXyz(rgb);
  const double fx = labF(x[0] / kWx), fy = labF(x[1] / kWy), fz = labF(x[2] / kWz);
  const double L = 116 * fy - 16, a = 500 * (fx - fy), b = 200 * (fy - fz);
  return {L, 0.01 * L * a, 0.01 * L * b};
}
/// HyAB: city-block in lightness, Euclidean in chroma.
double hyab(const V3& p, const V3& q) { return std::abs(p[0] - q[0]) + std::hypot(p[1] - q[1], p[2] - q[2]); }

constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95, kQf = 0.5, kFeatureWidth = 0.082;

// dst[x] = sum_k c[k] src[k][x] for x in [0, n), each sum started at 0 and taken in the order of k (the
// textbook loop's operations: a multiply, then an add, per tap). Blocks of 4 vectors of x stay in registers
// across the taps; 2 lanes per SSE2 vector, 4 per AVX one where the CPU has AVX2 (chosen at run time, built
// without FMA, so nothing is contracted): the same IEEE operations per element on either path, so the same
// bits.
using D2 = double __attribute__((vector_size(16)));
using D4 = double __attribute__((vector_size(32)));
template <class V>
[[gnu::always_inline]] inline V load(const double* p) {
  V v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
[[gnu::always_inline]] inline void weightedSum(double* dst, const double* const* src, const double* c, int taps,
                                               int n) {
  constexpr int L = sizeof(V) / sizeof(double), B = 4 * L;
  int x = 0;
  for (; x + B <= n; x += B) {
    V a0 = {}, a1 = {}, a2 = {}, a3 = {};
    for (int k = 0; k < taps; ++k) {
      V ck;
      for (int l = 0; l < L; ++l) ck[l] = c[k];
      const double* p = src[k] + x;
      a0 += ck * load<V>(p), a1 += ck * load<V>(p + L), a2 += ck * load<V>(p + 2 * L), a3 += ck * load<V>(p + 3 * L);
    }
    __builtin_memcpy(dst + x, &a0, sizeof a0), __builtin_memcpy(dst + x + L, &a1, sizeof a1);
    __builtin_memcpy(dst + x + 2 * L, &a2, sizeof a2), __builtin_memcpy(dst + x + 3 * L, &a3, sizeof a3);
  }
  for (; x < n; ++x) {
    double sum = 0;
    for (int k = 0; k < taps; ++k) sum += c[k] * src[k][x];
    dst[x] = sum;
  }
}
void weightedSumSse2(double* dst, const double* const* src, const double* c, int taps, int n) {
  weightedSum<D2>(dst, src, c, taps, n);
}
[[gnu::target("avx2")]] void weightedSumAvx(double* dst, const double* const* src, const double* c, int taps, int n) {
  weightedSum<D4>(dst, src, c, taps, n);
}
void weightedRows(double* dst, const double* const* src, const double* c, int taps, int n) {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  (avx2 && convolutionLanes().load(std::memory_order_relaxed) >= 4 ? weightedSumAvx : weightedSumSse2)(dst, src, c,
                                                                                                       taps, n);
}

/// Separable convolution of a w x h plane with kernels kx (along x) and ky (along y), each of odd length,
/// edges clamped: convolveY(convolveX(in, kx), ky). The same sums, in the same order of k, as the textbook
/// loop with clamped indices: a row is first copied with its edge values repeated r times on either side, so
/// every pixel (border ones too) is one weightedRows sum over k = -r .. r in order, starting from 0.
std::vector<double> convolveX(const std::vector<double>& in, int w, int h, const std::vector<double>& kx) {
  const int rx = static_cast<int>(kx.size()) / 2;
  std::vector<double> out(in.size()), padded(static_cast<size_t>(w) + 2 * rx);
  std::vector<const double*> taps(2 * rx + 1);
  for (int k = 0; k <= 2 * rx; ++k) taps[k] = padded.data() + k;
  for (int y = 0; y < h; ++y) {
    const double* row = in.data() + static_cast<size_t>(y) * w;
    for (int i = 0; i < w + 2 * rx; ++i) padded[i] = row[std::clamp(i - rx, 0, w - 1)];
    weightedRows(out.data() + static_cast<size_t>(y) * w, taps.data(), kx.data(), 2 * rx + 1, w);
  }
  return out;
}

std::vector<double> convolveY(const std::vector<double>& in, int w, int h, const std::vector<double>& ky) {
  const int ry = static_cast<int>(ky.size()) / 2;
  std::vector<double> out(in.size());
  std::vector<const double*> rows(2 * ry + 1);
  for (int y = 0; y < h; ++y) {
    for (int k = -ry; k <= ry; ++k) rows[k + ry] = in.data() + static_cast<size_t>(std::clamp(y + k, 0, h - 1)) * w;
    weightedRows(out.data() + static_cast<size_t>(y) * w, rows.data(), ky.data(), 2 * ry + 1, w);
  }
  return out;
}


/// The three opponent channels of an image (clamped to [0, 1]) after the
/// contrast sensitivity filters, back in linear RGB clamped to [0, 1], as Hunt-adjusted Lab.
std::vector<V3> filteredLab(const Image& img, double ppd) {
  const int w = img.width(), h = img.height();
  const size_t n = static_cast<size_t>(w) * h;
  std::array<std::vector<double>, 3> ycc;
  for (auto& p : ycc) p.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const float* c = img.data() + 3 * i;
    const V3 v = xyzToYcc(rgbToXyz({std::clamp<double>(c[0], 0, 1), std::clamp<double>(c[1], 0, 1),
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
  std::vector<V3> lab(n);
  for (size_t i = 0; i < n; ++i) {
    V3 rgb = xyzToRgb(yccToXyz({ycc[0][i], ycc[1][i], ycc[2][i]}));
    for (double& v : rgb) v = std::clamp(v, 0.0, 1.0);
    lab[i] = huntLab(rgb);
  }
  return lab;
}

/// Edge and point strength of the luminance ((Y' + 16) / 116 = Y) with the
/// first and second derivatives of a Gaussian of sd = 0.5 * 0.082 deg * ppd;
/// each kernel's positive weights sum to 1 and its negative ones to -1.
void features(const Image& img, double ppd, std::vector<double>& edge, std::vector<double>& point) {
  const int w = img.width(), h = img.height();
  const size_t n = static_cast<size_t>(w) * h;
  std::vector<double> y(n);
  for (size_t i = 0; i < n; ++i) {
    const float* c = img.data() + 3 * i;
    y[i] = rgbToXyz({std::clamp<double>(c[0], 0, 1), std::clamp<double>(c[1], 0, 1), std::clamp<double>(c[2], 0, 1)})[1];
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
  edge.resize(n), point.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double gx = ex[i] / (pos1 * sg), gy = ey[i] / (pos1 * sg);
    const double px = pxp[i] / (pos2 * sg) + pxn[i] / (-neg2 * sg), py = pyp[i] / (pos2 * sg) + pyn[i] / (-neg2 * sg);
    edge[i] = std::hypot(gx, gy), point[i] = std::hypot(px, py);
  }
}

}  // namespace

std::atomic<int>& convolutionLanes() {
  static std::atomic<int> lanes{4};
  return lanes;
}

std::vector<double> convolveClamped(const std::vector<double>& in, int w, int h, const std::vector<double>& kx,
                                    const std::vector<double>& ky) {
  if (kx.size() % 2 == 0 || ky.size() % 2 == 0 || in.size() != static_cast<size_t>(w) * h)
    throw std::invalid_argument("convolveClamped: kernels of odd length and a w x h plane expected");
  return convolveY(convolveX(in, w, h, kx), w, h, ky);
}

FlipReference::FlipReference(const Image& reference, double ppd)
    : width_(reference.width()), height_(reference.height()), ppd_(ppd), lab_(filteredLab(reference, ppd)) {
  features(reference, ppd, edge_, point_);
}

std::vector<float> FlipReference::map(const Image& test) const {
  if (test.width() != width_ || test.height() != height_)
    throw std::invalid_argument("flipMap: images of different sizes");
  const size_t n = static_cast<size_t>(width_) * height_;
  const std::vector<V3> lt = filteredLab(test, ppd_);
  std::vector<double> et, pt;
  features(test, ppd_, et, pt);
  // the largest colour difference of the gamut: pure green against pure blue
  const double cmax = std::pow(hyab(huntLab({0, 1, 0}), huntLab({0, 0, 1})), kQc);
  std::vector<float> out(n);
  for (size_t i = 0; i < n; ++i) {
    const double dc = std::pow(hyab(lt[i], lab_[i]), kQc);
    const double ec = dc < kPc * cmax ? dc * kPt / (kPc * cmax)
                                      : kPt + (dc - kPc * cmax) / (cmax - kPc * cmax) * (1 - kPt);
    const double ef = std::pow(std::max(std::abs(et[i] - edge_[i]), std::abs(pt[i] - point_[i])) / std::sqrt(2.0), kQf);
    out[i] = static_cast<float>(std::clamp(std::pow(std::min(ec, 1.0), 1 - std::min(ef, 1.0)), 0.0, 1.0));
  }
  return out;
}

double FlipReference::mean(const Image& test) const {
  const std::vector<float> m = map(test);
  double s = 0;
  for (float v : m) s += v;
  return m.empty() ? 0.0 : s / m.size();
}

// (FlipReference::map checks the sizes.)
std::vector<float> flipMap(const Image& test, const Image& reference, double ppd) {
  return FlipReference(reference, ppd).map(test);
}

double meanFlip(const Image& test, const Image& reference, double ppd) { return FlipReference(reference, ppd).mean(test); }

}  // namespace aliaslab
