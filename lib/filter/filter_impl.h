// Internal helpers shared by the filter implementations (not an interface:
// only lib/filter includes this). Each filter file defines its class over
// one of the two CRTP bases below and a make function the factory calls
// with the shape parameters already merged with their defaults.
#pragma once
#include <algorithm>
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

/// sin(pi t) / (pi t), 1 at t = 0.
inline float sinc(float t) {
  if (std::abs(t) < 1e-5f) return 1.f;
  const float a = kPi * t;
  return std::sin(a) / a;
}

// Vectorised footprint helpers (Filter::evalFootprint): 4 lanes at a time.
using Lanes = Eigen::Array4f;
inline Eigen::Map<Lanes> lanes(float* p) { return Eigen::Map<Lanes>(p); }

/// Scratch floats for one evalFootprint call, on the stack unless large.
class Scratch {
 public:
  explicit Scratch(size_t n) {
    if (n > kSmall) big_.resize(n);
  }
  float* data() { return big_.empty() ? small_ : big_.data(); }

 private:
  static constexpr size_t kSmall = 256;
  float small_[kSmall];
  std::vector<float> big_;
};

/// out[a] = c - (i0 + a + 0.5) for a < n: the offsets eval() sees.
inline void unitOffsets(float c, int i0, int n, float* out) {
  for (int a = 0; a < n; ++a) out[a] = c - (static_cast<float>(i0 + a) + 0.5f);
}

/// f(dx, dy) = g(dx) g(dy) on the square [-r, r]^2; Derived::g(x) is the profile for |x| <= r.
/// Derived may define g4 (g in 4 lanes, also called on padding lanes beyond r)
/// to vectorise evalFootprint; lanczos and
/// hann keep the scalar g, because Eigen's vectorised sin differs from std::sin
/// by an ulp or two, which the cancelling negative lobes amplify beyond 1e-5
/// at small radii (film_test's brute-force comparison).
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
  // per axis g at the padded offsets, then the products
  void evalFootprint(float x, float y, int i0, int nx, int j0, int ny, float* out) const final {
    const int sx = footprintStride(nx), sy = footprintStride(ny);
    Scratch scratch(sx + sy);
    float *gx = scratch.data(), *gy = gx + sx;
    unitOffsets(x, i0, sx, gx), unitOffsets(y, j0, sy, gy);
    if constexpr (requires(const Derived& d, const Lanes& l) { d.g4(l); }) {
      for (int k = 0; k < sx; k += 4) lanes(gx + k) = self().g4(lanes(gx + k));
      for (int k = 0; k < sy; k += 4) lanes(gy + k) = self().g4(lanes(gy + k));
    } else {  // scalar g: only the nx + ny offsets that are used
      for (int a = 0; a < nx; ++a) gx[a] = self().g(gx[a]);
      for (int b = 0; b < ny; ++b) gy[b] = self().g(gy[b]);
    }
    for (int b = 0; b < ny; ++b)
      for (int k = 0; k < sx; k += 4) lanes(out + static_cast<size_t>(b) * sx + k) = lanes(gx + k) * gy[b];
  }
 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

/// f(dx, dy) = g(d), d = sqrt(dx^2 + dy^2) <= r; Derived::g(d) is the profile for 0 <= d <= r.
template <class Derived>
class RadialFilter : public Filter {
 public:
  using Filter::Filter;
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
  // d = sqrt(dx^2 + dy^2) exactly as eval() rounds it, 4 lanes at a time
  void evalFootprint(float x, float y, int i0, int nx, int j0, int ny, float* out) const override {
    const int sx = footprintStride(nx);
    Scratch scratch(sx);
    float* dx2 = scratch.data();
    unitOffsets(x, i0, sx, dx2);
    for (int k = 0; k < sx; k += 4) lanes(dx2 + k) = lanes(dx2 + k).square();
    for (int b = 0; b < ny; ++b) {
      const float dy = y - (static_cast<float>(j0 + b) + 0.5f), dy2 = dy * dy;
      for (int k = 0; k < sx; k += 4)
        lanes(out + static_cast<size_t>(b) * sx + k) = self().g4(Lanes(lanes(dx2 + k) + dy2).sqrt());
    }
  }
  /// g(d) in 4 lanes, 0 where d > r (default: lane by lane).
  Lanes g4(const Lanes& d) const {
    const float r = radius();
    Lanes v;
    for (int l = 0; l < 4; ++l) v[l] = d[l] <= r ? self().g(d[l]) : 0.f;
    return v;
  }

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
