// Stage 1 of LDR-FLIP (flip_planes.h): the contrast sensitivity filters of the opponent channels and the
// Gaussian-derivative responses of the luminance, as exact separable sums (flip_convolve.cpp).
//
// The per-pixel passes around the sums (colour in, colour out, the normalisations) run on GCC vectors of 2
// doubles (SSE2) or 4 (AVX2, chosen at run time; built without FMA, so nothing is contracted): per lane the
// very operations of the scalar formulas, in the same order (a division stays a division, std::clamp's
// comparisons keep NaN and -0 as it does), so the same bits on either path as one pixel at a time
// (tests/unit/measure/flip/flip_linear_test.cpp checks them against the textbook).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "core/cpu.h"
#include "measure/flip/flip.h"
#include "measure/flip/flip_colour.h"
#include "measure/flip/flip_planes.h"

// 256-bit vectors are passed only between functions inlined into one built for AVX2 (GCC's -Wpsabi note).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace aliaslab {
namespace {

using namespace flipcolour;
using D2 = double __attribute__((vector_size(16)));
using D4 = double __attribute__((vector_size(32)));
template <class V>
constexpr int kLanes = sizeof(V) / sizeof(double);

constexpr double kFeatureWidth = 0.082;

// m <= L lanes of a plane (the rest 0: a vector tail computes on zeros and stores nothing of them).
template <class V>
[[gnu::always_inline]] inline V load(const double* p, int m) {
  V v = {};
  if (m == kLanes<V>) __builtin_memcpy(&v, p, sizeof v);
  else for (int l = 0; l < m; ++l) v[l] = p[l];
  return v;
}
template <class V>
[[gnu::always_inline]] inline void store(double* p, const V& v, int m) {
  if (m == kLanes<V>) __builtin_memcpy(p, &v, sizeof v);
  else for (int l = 0; l < m; ++l) p[l] = v[l];
}
// block(i, m) for the blocks [i, i + m) of [0, n): m = L, a constant folded into the loads and stores, then
// once m < L for the tail.
template <int L, class Block>
[[gnu::always_inline]] inline void forBlocks(size_t n, const Block& block) {
  size_t i = 0;
  for (; i + L <= n; i += L) block(i, L);
  if (i < n) block(i, static_cast<int>(n - i));
}
// Channel k of pixels 0 .. L - 1 of interleaved RGB, built in registers.
template <class V, size_t... l>
[[gnu::always_inline]] inline V channel(const float* p, int k, std::index_sequence<l...>) {
  return V{static_cast<double>(p[3 * l + k])...};
}
// std::clamp(v, 0, 1): v < 0 ? 0 : (1 < v ? 1 : v), so NaN and -0 pass through.
template <class V>
[[gnu::always_inline]] inline V clamp01(const V& v) {
  const V zero = {}, one = zero + 1.0;
  return v < zero ? zero : (one < v ? one : v);
}
// std::isfinite(v) ? v : 0 (v - v is 0 exactly when v is finite).
template <class V>
[[gnu::always_inline]] inline V finiteOr0(const V& v) {
  const V zero = {};
  return v - v == zero ? v : zero;
}

/// The opponent channels of the image clamped to [0, 1] (ycc) and its luminance Y (lum), each 0 where not finite.
template <class V>
[[gnu::always_inline]] inline void inputPlanes(const float* rgb, size_t n, double* const* ycc, double* lum) {
  constexpr int L = kLanes<V>;
  forBlocks<L>(n, [&](size_t i, int m) __attribute__((always_inline)) {
    V c[3] = {};
    if (m == L) {
      for (int k = 0; k < 3; ++k) c[k] = channel<V>(rgb + 3 * i, k, std::make_index_sequence<L>());
    } else {
      for (int l = 0; l < m; ++l)
        for (int k = 0; k < 3; ++k) c[k][l] = rgb[3 * (i + l) + k];
    }
    const auto xyz = rgbToXyz(clamp01(c[0]), clamp01(c[1]), clamp01(c[2]));
    const auto v = xyzToYcc(xyz[0], xyz[1], xyz[2]);
    for (int k = 0; k < 3; ++k) store(ycc[k] + i, finiteOr0(v[k]), m);
    store(lum + i, finiteOr0(xyz[1]), m);
  });
}

/// One row of a CSF-filtered channel: dst = [dst +] a src [/ total] (the channel is (A1 s1 + A2 s2) / total,
/// or A1 s1 / total with one Gaussian: the first sum stored, the second added to it, then the division).
struct RowScale {
  double a = 1, total = 1;
  bool accumulate = false, divide = true;
};
template <class V>
[[gnu::always_inline]] inline void csfRow(double* dst, const double* src, const RowScale& s, int n) {
  forBlocks<kLanes<V>>(n, [&](size_t i, int m) __attribute__((always_inline)) {
    V v = s.a * load<V>(src + i, m);
    if (s.accumulate) v = load<V>(dst + i, m) + v;
    if (s.divide) v = v / s.total;
    store(dst + i, v, m);
  });
}
/// The filtered channels (YCxCz) to linear RGB clamped to [0, 1], in place.
template <class V>
[[gnu::always_inline]] inline void yccToRgbInPlace(double* const* p, size_t n) {
  forBlocks<kLanes<V>>(n, [&](size_t i, int m) __attribute__((always_inline)) {
    const auto xyz = yccToXyz(load<V>(p[0] + i, m), load<V>(p[1] + i, m), load<V>(p[2] + i, m));
    const auto c = xyzToRgb(xyz[0], xyz[1], xyz[2]);
    for (int k = 0; k < 3; ++k) store(p[k] + i, clamp01(c[k]), m);
  });
}
/// One row of a feature plane: dst = [dst +] src / d (a point plane is pos / pos2 sg + neg / (-neg2 sg)).
template <class V>
[[gnu::always_inline]] inline void ratioRow(double* dst, const double* src, double d, bool accumulate, int n) {
  forBlocks<kLanes<V>>(n, [&](size_t i, int m) __attribute__((always_inline)) {
    V v = load<V>(src + i, m) / d;
    if (accumulate) v = load<V>(dst + i, m) + v;
    store(dst + i, v, m);
  });
}

void inputPlanesSse2(const float* rgb, size_t n, double* const* ycc, double* lum) { inputPlanes<D2>(rgb, n, ycc, lum); }
[[gnu::target("avx2")]] void inputPlanesAvx(const float* rgb, size_t n, double* const* ycc, double* lum) {
  inputPlanes<D4>(rgb, n, ycc, lum);
}
void csfRowSse2(double* dst, const double* src, const RowScale& s, int n) { csfRow<D2>(dst, src, s, n); }
[[gnu::target("avx2")]] void csfRowAvx(double* dst, const double* src, const RowScale& s, int n) {
  csfRow<D4>(dst, src, s, n);
}
void yccToRgbSse2(double* const* p, size_t n) { yccToRgbInPlace<D2>(p, n); }
[[gnu::target("avx2")]] void yccToRgbAvx(double* const* p, size_t n) { yccToRgbInPlace<D4>(p, n); }
void ratioRowSse2(double* dst, const double* src, double d, bool accumulate, int n) {
  ratioRow<D2>(dst, src, d, accumulate, n);
}
[[gnu::target("avx2")]] void ratioRowAvx(double* dst, const double* src, double d, bool accumulate, int n) {
  ratioRow<D4>(dst, src, d, accumulate, n);
}

/// The three opponent channels (ycc, from inputPlanes) after the contrast sensitivity filters, back in linear
/// RGB clamped to [0, 1]. Each filtered row goes straight into rgbOut (the sums of channel 2 one after the
/// other), which is then turned into RGB in place: no plane of sums is kept.
void filteredRgb(const std::array<std::vector<double>, 3>& ycc, int w, int h, double ppd,
                 std::array<std::vector<double>, 3>& rgbOut) {
  const size_t n = static_cast<size_t>(w) * h;
  for (auto& p : rgbOut) p.resize(n);
  const auto csfRows = cpuFeatures().avx2 ? csfRowAvx : csfRowSse2;
  const std::array<FlipCsfKernel, 3> csf = flipCsfKernels(ppd);
  for (int c = 0; c < 3; ++c) {
    const auto& [e1, e2, A1, A2, total] = csf[c];
    const auto into = [&](const RowScale& scale) {
      return [&, scale](int y, const double* const* rows) {
        csfRows(rgbOut[c].data() + static_cast<size_t>(y) * w, rows[0], scale, w);
      };
    };
    convolveClampedRows(ycc[c], w, h, e1, {&e1}, into({A1, total, false, !(A2 > 0)}));
    if (A2 > 0) convolveClampedRows(ycc[c], w, h, e2, {&e2}, into({A2, total, true, true}));
  }
  double* const rgb[3] = {rgbOut[0].data(), rgbOut[1].data(), rgbOut[2].data()};
  (cpuFeatures().avx2 ? yccToRgbAvx : yccToRgbSse2)(rgb, n);
}

/// Edge and point responses of the luminance y ((Y' + 16) / 116 = Y) with the first and second derivatives of a
/// Gaussian of sd = 0.5 * 0.082 deg * ppd; each kernel's positive weights sum to 1 and its negative ones to -1.
void features(const std::vector<double>& y, int w, int h, double ppd, FlipLinear& out) {
  const size_t n = static_cast<size_t>(w) * h;
  const auto [g, d1, d2p, d2n, edge, pos, neg] = flipFeatureKernels(ppd);
  // each row divided as it is made: g = sum / edge, p = positive sum / pos + negative sum / neg
  out.gx.resize(n), out.gy.resize(n), out.px.resize(n), out.py.resize(n);
  const auto ratio = cpuFeatures().avx2 ? ratioRowAvx : ratioRowSse2;
  const auto at = [&](std::vector<double>& p, int row) { return p.data() + static_cast<size_t>(row) * w; };
  // the y derivatives share the x pass with g
  convolveClampedRows(y, w, h, g, {&d1, &d2p, &d2n}, [&](int row, const double* const* s) {
    ratio(at(out.gy, row), s[0], edge, false, w);
    ratio(at(out.py, row), s[1], pos, false, w), ratio(at(out.py, row), s[2], neg, true, w);
  });
  // the x derivatives, then smoothed along y (the negative point sums added to the positive ones' rows)
  const auto xDerivative = [&](const std::vector<double>& kx, std::vector<double>& plane, double d, bool add) {
    convolveClampedRows(y, w, h, kx, {&g},
                        [&](int row, const double* const* s) { ratio(at(plane, row), s[0], d, add, w); });
  };
  xDerivative(d1, out.gx, edge, false), xDerivative(d2p, out.px, pos, false), xDerivative(d2n, out.px, neg, true);
}

}  // namespace

std::array<FlipCsfKernel, 3> flipCsfKernels(double ppd) {
  // CSF of each channel as a sum of two Gaussians a sqrt(pi / b) exp(-pi^2 x^2 / b), x in degrees
  struct Csf { double a1, b1, a2, b2; };
  const Csf csf[3] = {{1, 0.0047, 0, 1e-5}, {1, 0.0053, 0, 1e-5}, {34.1, 0.04, 13.5, 0.025}};
  const double bMax = 0.04;
  const int r = static_cast<int>(std::ceil(3 * std::sqrt(bMax / (2 * M_PI * M_PI)) * ppd));
  std::array<FlipCsfKernel, 3> out;
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
    out[c] = {std::move(e1), std::move(e2), A1, A2, A1 * s1 * s1 + A2 * s2 * s2};
  }
  return out;
}

FlipFeatureKernels flipFeatureKernels(double ppd) {
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
  return {std::move(g), std::move(d1), std::move(d2p), std::move(d2n), pos1 * sg, pos2 * sg, -neg2 * sg};
}

FlipLinear flipLinear(const Image& img, double ppd) {
  FlipLinear out;
  out.width = img.width(), out.height = img.height();
  const size_t n = static_cast<size_t>(img.width()) * img.height();
  std::array<std::vector<double>, 3> ycc;
  for (auto& p : ycc) p.resize(n);
  std::vector<double> lum(n);
  double* const yccData[3] = {ycc[0].data(), ycc[1].data(), ycc[2].data()};
  (cpuFeatures().avx2 ? inputPlanesAvx : inputPlanesSse2)(img.data(), n, yccData, lum.data());
  filteredRgb(ycc, img.width(), img.height(), ppd, out.rgb);
  features(lum, img.width(), img.height(), ppd, out);
  return out;
}

}  // namespace aliaslab
