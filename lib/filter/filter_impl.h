// Internal helpers shared by the filter implementations (not an interface:
// only lib/filter includes this). Each filter file defines its class over
// one of the two CRTP bases below (which derive eval() from the profile g)
// and the two functions its registry line names (factory.cpp): a make
// function the factory calls with the shape parameters already merged with
// their defaults, and a batch function giving FilterBatch its vectorised
// kernel (filter_batch_impl.h; null: FilterBatch's loop over eval()).
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "core/math.h"
#include "filter/filter.h"
#include "filter/filter_simd.h"

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

/// f(dx, dy) = g(dx) g(dy) on the square [-r, r]^2; Derived::g(x) is the profile for |x| <= r. Derived may
/// define product(dx, dy), g(dx) g(dy) in another float form (the course's Gaussian: one exponential of the
/// summed exponents), which eval() then returns inside the square.
template <class Derived>
class SeparableFilter : public Filter {
 public:
  using Filter::Filter;
  bool radial() const final { return false; }
  float profile(float x) const final { return std::abs(x) <= radius() ? self().g(x) : 0.f; }
  float eval(float dx, float dy) const final {
    if constexpr (requires(const Derived& f, float a) { f.product(a, a); })
      return std::abs(dx) <= radius() && std::abs(dy) <= radius() ? self().product(dx, dy) : 0.f;
    else
      return profile(dx) * profile(dy);
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

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

class BatchKernel;
/// A filter file's batch function: the kernel for `filter` (made by that file), or null.
using BatchMaker = std::shared_ptr<const BatchKernel> (*)(const Filter& filter);

/// Throws OptionError("filter-param", ...) unless lo <= value <= hi.
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
std::unique_ptr<Filter> makeCourseGaussian(float r, const FilterParams& p);
std::unique_ptr<Filter> makeGaussianCut(float r, const FilterParams& p);
/// The radial Gaussian with its own name and a given sigma (shared by gaussian and gaussian-cut).
std::unique_ptr<Filter> makeGaussianNamed(const std::string& name, float r, double sigma, double subtractEdge);
/// Mitchell-Netravali profile with its own name (shared by mitchell and catmullrom).
std::unique_ptr<Filter> makeMitchellNamed(const std::string& name, float r, double B, double C, bool showParams);

// Batch functions, one per filter file with vectorised code (catmullrom uses mitchell's, gaussian-cut gaussian's).
std::shared_ptr<const BatchKernel> boxBatch(const Filter& f);
std::shared_ptr<const BatchKernel> tentBatch(const Filter& f);
std::shared_ptr<const BatchKernel> gaussianBatch(const Filter& f);
std::shared_ptr<const BatchKernel> mitchellBatch(const Filter& f);
std::shared_ptr<const BatchKernel> lanczosBatch(const Filter& f);
std::shared_ptr<const BatchKernel> hannBatch(const Filter& f);
std::shared_ptr<const BatchKernel> blackmanHarrisBatch(const Filter& f);

/// The batch function registered for a filter name (null for none or an unknown name).
BatchMaker batchMaker(const std::string& name);

}  // namespace aliaslab::filterimpl
