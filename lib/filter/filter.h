// Reconstruction filters: the maths.
//
// A filter is a weight f(dx, dy) for a sample at offset (dx, dy), in pixels,
// from a pixel centre. Every filter has a support radius r (the sweep
// variable) and shape parameters that are independent of r, with documented
// defaults (the Gaussian's default sigma is r / 3: see below). eval() is exactly zero outside the support: |dx| > r or |dy| > r
// for separable (square-support) filters, sqrt(dx^2 + dy^2) > r for radial
// ones. integral() is the integral of f over the plane (analytic, or numeric
// computed once at construction). Filters with negative lobes return
// negative weights; nothing is clamped.
//
// Every filter is a 1-D profile g, written once per filter: separable
// filters are f = g(dx) g(dy) on the square [-r, r]^2, radial ones
// f = g(sqrt(dx^2 + dy^2)) on the disc (eval() derives f from g).
//
// Filters whose natural profile has a fixed support (Mitchell: 2, Lanczos:
// tau lobes) are stretched to the radius: f_r(x) = f(x * natural / r). So is
// the Gaussian by default (sigma = r / 3, natural radius 1.5): in a sweep the
// radius is the width for every filter. gaussian-cut keeps a fixed sigma and
// only cuts it at r.
//
// Beside the maths, built from a finished Filter: FilterBatch
// (filter_batch.h), the film's vectorised weights of many samples at once,
// and FilterSampler (filter_sampler.h), filter importance sampling. The
// course's classic gather uses a filter's course variant
// (makeCourseVariant), itself a registered filter.
//
// Protocol: filters are made only by makeFilter(); a finished Filter is
// immutable and safe to share between threads.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace aliaslab {

using FilterParams = std::map<std::string, double>;

class Filter {
 public:
  explicit Filter(float radius) : radius_(radius) {}
  virtual ~Filter();

  float radius() const { return radius_; }
  /// True when the support is a disc of radius r, false for the square [-r, r]^2.
  virtual bool radial() const = 0;
  /// The 1-D profile g (see above); zero for |x| > r.
  virtual float profile(float x) const = 0;
  /// f(dx, dy), from the profile: g(dx) g(dy) on the square or g(d) on the disc, zero outside.
  virtual float eval(float dx, float dy) const = 0;
  /// The integral of f over the plane.
  virtual double integral() const = 0;

  /// The registered name ("mitchell").
  virtual std::string name() const = 0;
  /// Shape parameters (without the radius) and their values.
  virtual FilterParams params() const { return {}; }
  /// One line: name, radius and every shape parameter, e.g. "mitchell r=2 B=0.3333 C=0.3333".
  std::string describe() const;

 private:
  float radius_;
};

/// The study's filters: every registered name except gaussian-cut and the course variants, in a fixed order.
const std::vector<std::string>& filterNames();
/// Every registered name, in a fixed order: filterNames(), then gaussian-cut (the fixed-sigma Gaussian) and the
/// course variants (course-gaussian).
const std::vector<std::string>& allFilterNames();

/// Makes a filter by name with support radius `radius` and shape `params`.
/// Throws OptionError("filter", ...) listing the valid names for an unknown
/// name, OptionError("radius", ...) for a radius that is not finite or
/// outside [1e-3, 1024] pixels (squared offsets underflow below, the integral
/// of |f| overflows above), and OptionError("filter-param", ...) naming the parameter for an unknown or
/// out-of-range shape parameter (so a misspelt "sigmaa" cannot pass).
std::unique_ptr<Filter> makeFilter(const std::string& name, float radius, const FilterParams& params = {});

/// The radius used when a front end is given a filter name but no radius: the
/// filter's natural support (box 0.5 = the pixel area, tent 1, gaussian
/// 1.5 (3 sigma when sigma is given), gaussian-cut 3 sigma, mitchell and
/// catmullrom 2, lanczos and hann tau, blackmanharris 2, course-gaussian
/// ceil(2 sigma - 0.5) + 0.5), clamped to [1e-3, 1024],
/// with shape parameters from `params` over the defaults. 1 for an unknown
/// name (makeFilter then reports it).
double defaultFilterRadius(const std::string& name, const FilterParams& params = {});

/// Shape parameters a filter accepts, with defaults (for --help and docs).
FilterParams defaultFilterParams(const std::string& name);

/// The filter the course's classic gather (ReconMode::Classic, film.h) uses in place of `filter`: the course
/// variant registered for its name, made with the shape parameters it shares with `filter` at its natural
/// radius (gaussian: course-gaussian, exp(-d^2 / 2 sigma^2) uncut over the square of the course's integer
/// support ceil(2 sigma - 0.5), plus half a pixel); null when the filter is its own course variant.
std::unique_ptr<Filter> makeCourseVariant(const Filter& filter);

}  // namespace aliaslab
