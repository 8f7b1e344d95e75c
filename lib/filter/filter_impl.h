// Internal helpers shared by the filter implementations (not an interface:
// only lib/filter includes this). Each filter file defines its class over
// one of the two CRTP bases below and a make function the factory calls
// with the shape parameters already merged with their defaults.
#pragma once
#include <immintrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "filter/filter.h"

namespace aliaslab::filterimpl {

/// Composite 8-point Gauss-Legendre rule over `cells` equal cells of [a, b].
template <class F>
double integrate(F&& f, double a, double b, int cells = 512) {
  static constexpr double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static constexpr double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const double h = (b - a) / cells;
  double sum = 0;
  for (int c = 0; c < cells; ++c) {
    const double mid = a + (c + 0.5) * h;
    for (int k = 0; k < 4; ++k) sum += w[k] * (f(mid - 0.5 * h * x[k]) + f(mid + 0.5 * h * x[k]));
  }
  return sum * 0.5 * h;
}

// sin(pi t) / (pi t) and cos(pi t) for float or Eigen float lanes: the same
// operations in both, so eval() and the vectorised fast path agree bit for
// bit (no libm). The reduction f = t - round(t) is exact, so the only error
// is the float evaluation of the Taylor series in f^2 (to f^14, within 1e-8
// on |f| <= 1/2): about an ulp. Valid for |t| < 2^22.
namespace trig {
constexpr float kRound = 12582912.f;  // 1.5 * 2^23: (v + kRound) - kRound rounds v to an integer
/// Taylor coefficients in f^2 of sin(pi f) / (pi f) (odd = 1) and of cos(pi f) (odd = 0): (-1)^k pi^2k / (2k + odd)!
constexpr std::array<float, 8> taylor(int odd) {
  std::array<float, 8> c{};
  double v = 1;
  for (int k = 0; k < 8; ++k) {
    c[k] = float(v);
    v *= -(M_PI * M_PI) / ((2 * k + odd + 1) * (2 * k + odd + 2));
  }
  return c;
}
inline constexpr std::array<float, 8> kSinc = taylor(1), kCos = taylor(0);
/// Sets f = t - round(t) and returns (-1)^round(t) times the series c in f^2.
template <class T>
[[gnu::always_inline]] inline T reduced(const T& t, T& f, const std::array<float, 8>& c) {
  const T n = (t + kRound) - kRound, half = n * 0.5f;
  f = t - n;
  const T f2 = f * f, sign = 1.f - 4.f * (half - ((half - 0.25f + kRound) - kRound));  // half - floor(half): 0 or 1/2
  T p = f2 * c[7] + c[6];
  for (int k = 5; k >= 0; --k) p = p * f2 + c[k];
  return sign * p;
}
/// sin(pi t) / (pi t), 1 at t = 0.
template <class T>
[[gnu::always_inline]] inline T sincPi(const T& t) {
  T f;
  const T q = reduced(t, f, kSinc);
  return q * ((f + 1e-30f) / (t + 1e-30f));  // f / t; exactly 1 while round(t) = 0 (then f = t)
}
template <class T>
[[gnu::always_inline]] inline T cosPi(const T& t) {
  T f;
  return reduced(t, f, kCos);
}
}  // namespace trig

// Vectorised helpers (Filter::evalBatch): 4 lanes at a time.
using Lanes = Eigen::Array4f;
inline Eigen::Map<Lanes> lanes(float* p) { return Eigen::Map<Lanes>(p); }
inline Eigen::Map<const Lanes> lanes(const float* p) { return Eigen::Map<const Lanes>(p); }

/// Lane-wise a <= bound ? v : 0 (0 for NaN a): a compare and an and.
inline Lanes keepLe(const Lanes& a, float bound, const Lanes& v) {
  Lanes out;
  _mm_storeu_ps(out.data(), _mm_and_ps(_mm_cmple_ps(_mm_loadu_ps(a.data()), _mm_set1_ps(bound)), _mm_loadu_ps(v.data())));
  return out;
}
/// Lane-wise sqrt, correctly rounded like std::sqrt (Eigen's fast-math sqrt is not).
inline Lanes sqrt4(const Lanes& v) {
  Lanes out;
  _mm_storeu_ps(out.data(), _mm_sqrt_ps(_mm_loadu_ps(v.data())));
  return out;
}
/// Lane-wise a < bound ? v : w.
inline Lanes ifLess(const Lanes& a, float bound, const Lanes& v, const Lanes& w) {
  const __m128 m = _mm_cmplt_ps(_mm_loadu_ps(a.data()), _mm_set1_ps(bound));
  Lanes out;
  _mm_storeu_ps(out.data(), _mm_or_ps(_mm_and_ps(m, _mm_loadu_ps(v.data())), _mm_andnot_ps(m, _mm_loadu_ps(w.data()))));
  return out;
}

/// Scratch floats for one evalBatch call, on the stack unless large.
class Scratch {
 public:
  explicit Scratch(size_t n) {
    if (n > kSmall) big_.resize(n);
  }
  float* data() { return big_.empty() ? small_ : big_.data(); }

 private:
  static constexpr size_t kSmall = 8192;
  alignas(16) float small_[kSmall];
  std::vector<float> big_;
};

/// f(dx, dy) = g(dx) g(dy) on the square [-r, r]^2; Derived::g(x) is the profile for |x| <= r.
/// Derived may define g4 (g in 4 lanes, bit for bit g; also called beyond r and on padding)
/// to vectorise evalBatch.
template <class Derived>
class SeparableFilter : public Filter {
 public:
  using Filter::Filter;
  bool radial() const final { return false; }
  float profile(float x) const final { return std::abs(x) <= radius() ? self().g(x) : 0.f; }
  float eval(float dx, float dy) const final { return profile(dx) * profile(dy); }
  void evalGrid(const float* dx, int nx, const float* dy, int ny, float* out) const final {
    for (int a = 0; a < nx; ++a) out[a] = profile(dx[a]);  // row 0 holds g(dx) until last
    for (int b = ny - 1; b >= 0; --b) {
      const float gy = profile(dy[b]);
      float* row = out + static_cast<size_t>(b) * nx;
      for (int a = 0; a < nx; ++a) row[a] = out[a] * gy;
    }
  }
  // n profile values per axis and sample, then the n x n products
  void evalBatch(int count, const float* x, const float* y, const float* cx, const float* cy, int n,
                 float* out) const final {
    const size_t stride = batchStride(count);
    Scratch scratch(2 * n * stride);
    float *gx = scratch.data(), *gy = gx + n * stride;
    profiles(x, cx, n, stride, gx), profiles(y, cy, n, stride, gy);
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a)
        for (size_t s = 0; s < stride; s += 4)
          lanes(out + (b * n + a) * stride + s) = lanes(gx + a * stride + s) * lanes(gy + b * stride + s);
  }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
  /// out[a * stride + s] = profile(p[s] - (c[s] + a)) for a < n.
  void profiles(const float* p, const float* c, int n, size_t stride, float* out) const {
    const float r = radius();
    for (size_t s = 0; s < stride; s += 4)
      for (int a = 0; a < n; ++a) {
        const Lanes d = lanes(p + s) - (lanes(c + s) + static_cast<float>(a));
        Lanes g;
        if constexpr (requires(const Derived& f, const Lanes& l) { f.g4(l); }) g = self().g4(d);
        else
          for (int l = 0; l < 4; ++l) g[l] = self().g(d[l]);
        lanes(out + a * stride + s) = keepLe(d.abs(), r, g);
      }
  }
};

/// f(dx, dy) = g(d), d = sqrt(dx^2 + dy^2) <= r; Derived::g(d) is the profile for 0 <= d <= r.
template <class Derived>
class RadialFilter : public Filter {
 public:
  explicit RadialFilter(float r) : Filter(r), disc_(discBound(r)) {}
  bool radial() const final { return true; }
  float profile(float x) const final { return std::abs(x) <= radius() ? self().g(std::abs(x)) : 0.f; }
  float eval(float dx, float dy) const final {
    const float d = std::sqrt(dx * dx + dy * dy);
    return d <= radius() ? self().g(d) : 0.f;
  }
  void evalGrid(const float* dx, int nx, const float* dy, int ny, float* out) const override {
    const float r = radius();
    for (int b = 0; b < ny; ++b)
      for (int a = 0; a < nx; ++a) {
        const float d = std::sqrt(dx[a] * dx[a] + dy[b] * dy[b]);
        out[static_cast<size_t>(b) * nx + a] = d <= r ? self().g(d) : 0.f;
      }
  }
  // squared offsets per axis, then d and g4(d) per pixel, cut to the disc as eval() rounds it
  void evalBatch(int count, const float* x, const float* y, const float* cx, const float* cy, int n,
                 float* out) const override {
    const size_t stride = batchStride(count);
    Scratch scratch(2 * n * stride);
    float *dx2 = scratch.data(), *dy2 = dx2 + n * stride;
    squaredOffsets(x, cx, n, stride, dx2), squaredOffsets(y, cy, n, stride, dy2);
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a)
        for (size_t s = 0; s < stride; s += 4) {
          const Lanes d2 = lanes(dx2 + a * stride + s) + lanes(dy2 + b * stride + s);
          lanes(out + (b * n + a) * stride + s) = keepLe(d2, disc_, self().g4(sqrt4(d2)));
        }
  }
  /// g(d) in 4 lanes (default: lane by lane; also called beyond r).
  Lanes g4(const Lanes& d) const {
    Lanes v;
    for (int l = 0; l < 4; ++l) v[l] = self().g(d[l]);
    return v;
  }

 protected:
  /// out[a * stride + s] = (p[s] - (c[s] + a))^2 for a < n.
  static void squaredOffsets(const float* p, const float* c, int n, size_t stride, float* out) {
    for (int a = 0; a < n; ++a)
      for (size_t s = 0; s < stride; s += 4) lanes(out + a * stride + s) = (lanes(p + s) - (lanes(c + s) + float(a))).square();
  }
  /// The largest dx^2 + dy^2 with sqrt(dx^2 + dy^2) <= r in float (the disc test without the sqrt).
  static float discBound(float r) {
    float s = r * r;
    while (s > 0 && !(std::sqrt(s) <= r)) s = std::nextafter(s, 0.f);
    while (std::sqrt(std::nextafter(s, kInf)) <= r) s = std::nextafter(s, kInf);
    return s;
  }
  float disc_;  ///< discBound(radius())

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

/// Throws OptionError("--filter-param", ...) unless lo <= value <= hi.
void requireRange(const std::string& filter, const std::string& param, double value, double lo, double hi);

// Make functions, one per filter file; `p` holds every shape parameter.
std::unique_ptr<Filter> makeBox(float r, const FilterParams& p);
std::unique_ptr<Filter> makeTent(float r, const FilterParams& p);
std::unique_ptr<Filter> makeGaussian(float r, const FilterParams& p);
std::unique_ptr<Filter> makeMitchell(float r, const FilterParams& p);
std::unique_ptr<Filter> makeCatmullRom(float r, const FilterParams& p);
std::unique_ptr<Filter> makeLanczos(float r, const FilterParams& p);
std::unique_ptr<Filter> makeHann(float r, const FilterParams& p);
std::unique_ptr<Filter> makeBlackmanHarris(float r, const FilterParams& p);
/// Mitchell-Netravali profile with its own name (shared by mitchell and catmullrom).
std::unique_ptr<Filter> makeMitchellNamed(const std::string& name, float r, double B, double C, bool showParams);

}  // namespace aliaslab::filterimpl
