// Reconstruction filters.
//
// A filter is a weight f(dx, dy) for a sample at offset (dx, dy), in pixels,
// from a pixel centre. Every filter has a support radius r (the sweep
// variable) and shape parameters that are independent of r, with documented
// defaults. eval() is exactly zero outside the support: |dx| > r or |dy| > r
// for separable (square-support) filters, sqrt(dx^2 + dy^2) > r for radial
// ones. integral() is the integral of f over the plane (analytic, or numeric
// computed once at construction). Filters with negative lobes return
// negative weights; nothing is clamped.
//
// Filters whose natural profile has a fixed support (Mitchell: 2, Lanczos:
// tau lobes) are stretched to the radius: f_r(x) = f(x * natural / r).
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/math.h"

namespace aliaslab {

class Filter {
 public:
  explicit Filter(float radius) : radius_(radius) {}
  virtual ~Filter() = default;

  float radius() const { return radius_; }
  virtual float eval(float dx, float dy) const = 0;
  virtual double integral() const = 0;
  /// Integral of |f| (for filter importance sampling).
  virtual double absIntegral() const;
  /// True when the support is a disc of radius r, false for the square [-r, r]^2.
  virtual bool radial() const = 0;

  virtual std::string name() const = 0;
  /// One line: name, radius and every shape parameter, e.g. "mitchell r=2 B=0.333 C=0.333".
  virtual std::string describe() const = 0;

  /// Filter importance sampling: maps u in [0,1)^2 to an offset with density
  /// |f| / absIntegral(), and sets `weight` = sign(f(offset)) * absIntegral().
  /// The default uses a tabulated 2-D distribution built on first use.
  virtual Vec2 sample(const Vec2& u, float& weight) const;

 private:
  float radius_;
  mutable std::shared_ptr<const struct FilterTable> table_;
};

using FilterParams = std::map<std::string, double>;

/// Every registered name, in a fixed order.
const std::vector<std::string>& filterNames();

/// Makes a filter by name with support radius `radius` and shape `params`.
/// Throws OptionError("--filter", ...) listing the valid names for an unknown
/// name, OptionError("--radius", ...) for a radius that is not finite and
/// positive, and OptionError naming the parameter for an unknown or
/// out-of-range shape parameter (so a misspelt "sigmaa" cannot pass).
std::unique_ptr<Filter> makeFilter(const std::string& name, float radius, const FilterParams& params = {});

/// Shape parameters a filter accepts, with defaults (for --help and docs).
FilterParams defaultFilterParams(const std::string& name);

}  // namespace aliaslab
