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
// Every filter is a 1-D profile g: separable filters are f = g(dx) g(dy) on
// the square [-r, r]^2, radial ones f = g(sqrt(dx^2 + dy^2)) on the disc.
//
// Filters whose natural profile has a fixed support (Mitchell: 2, Lanczos:
// tau lobes) are stretched to the radius: f_r(x) = f(x * natural / r).
//
// Protocol: filters are made only by makeFilter(), which builds the
// importance-sampling table and the integral of |f| once, so a finished
// Filter is immutable and safe to share between threads.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/math.h"

namespace aliaslab {

using FilterParams = std::map<std::string, double>;
struct FilterTable;

class Filter {
 public:
  explicit Filter(float radius) : radius_(radius) {}
  virtual ~Filter();

  float radius() const { return radius_; }
  virtual float eval(float dx, float dy) const = 0;
  virtual double integral() const = 0;
  /// Integral of |f| (for filter importance sampling); numeric, computed by makeFilter.
  virtual double absIntegral() const;
  /// True when the support is a disc of radius r, false for the square [-r, r]^2.
  virtual bool radial() const = 0;
  /// The 1-D profile g (see above); zero for |x| > r.
  virtual float profile(float x) const = 0;

  /// Weights of a whole footprint in one call (the film's fast path):
  /// out[b * nx + a] = eval(dx[a], dy[b]) for a < nx, b < ny (up to float
  /// rounding: the Gaussian multiplies per-axis exponentials).
  virtual void evalGrid(const float* dx, int nx, const float* dy, int ny, float* out) const;
  /// The film's fast path, one call per batch of samples, vectorised across
  /// them (4 lanes, or 8 where the CPU has AVX2, with the same bits): the weights of sample s < count at film position (x[s], y[s]) at
  /// the centres of the n x n pixels whose first centre is (cx[s], cy[s])
  /// (a pixel centre: column + 0.5, row + 0.5):
  ///   out[(b * n + a) * stride + s] = eval(x[s] - (cx[s] + a), y[s] - (cy[s] + b)),
  /// stride = batchStride(count); every input holds `stride` entries (the
  /// padding is evaluated and ignored). Bit for bit eval() (Lanczos and
  /// Hann: sin and cos by the filters' own code, shared by both), except
  /// Blackman-Harris (Eigen's vectorised cos: a few float ulps) and the
  /// Gaussian (per-axis exponentials: a few ulps per unit of the exponent).
  virtual void evalBatch(int count, const float* x, const float* y, const float* cx, const float* cy, int n,
                         float* out) const;
  /// Entries per weight of evalBatch's output: count rounded up to a multiple of 4.
  static int batchStride(int count) { return (count + 3) & ~3; }
  /// True when eval() is exactly 1 on the whole support (the box): the film then skips the weights.
  virtual bool unitWeights() const { return false; }
  /// The weight the course's classic gather uses: eval(), except that the
  /// course's Gaussian is exp(-d^2 / 2 sigma^2) uncut (no radius, no edge term).
  virtual float evalClassic(float dx, float dy) const { return eval(dx, dy); }

  virtual std::string name() const = 0;
  /// Shape parameters (without the radius) and their values.
  virtual FilterParams params() const { return {}; }
  /// One line: name, radius and every shape parameter, e.g. "mitchell r=2 B=0.3333 C=0.3333".
  virtual std::string describe() const;

  /// Filter importance sampling: maps u in [0,1)^2 to an offset with density
  /// |f| / absIntegral() (up to the tabulation: |f| averaged over cells of
  /// width r / 1024 along each separable axis, or along the radius of radial
  /// filters), and sets `weight` = sign(f(offset)) * absIntegral().
  /// Separable filters use u.x for dx and u.y for dy; radial ones u.x for
  /// the distance and u.y for the angle.
  virtual Vec2 sample(const Vec2& u, float& weight) const;

 private:
  friend std::unique_ptr<Filter> makeFilter(const std::string& name, float radius, const FilterParams& params);
  /// Builds table_ (called once by makeFilter on the finished object).
  void prepare();

  float radius_;
  std::shared_ptr<const FilterTable> table_;
};

/// Every registered name, in a fixed order.
const std::vector<std::string>& filterNames();

/// Makes a filter by name with support radius `radius` and shape `params`.
/// Throws OptionError("--filter", ...) listing the valid names for an unknown
/// name, OptionError("--radius", ...) for a radius that is not finite or
/// outside [1e-3, 1024] pixels (squared offsets underflow below, the integral
/// of |f| overflows above), and OptionError("--filter-param", ...) naming the parameter for an unknown or
/// out-of-range shape parameter (so a misspelt "sigmaa" cannot pass).
std::unique_ptr<Filter> makeFilter(const std::string& name, float radius, const FilterParams& params = {});

/// The radius used when a front end is given a filter name but no radius: the
/// filter's natural support (box 0.5 = the pixel area, tent 1, gaussian
/// 3 sigma, mitchell and catmullrom 2, lanczos and hann tau, blackmanharris
/// 2), with shape parameters from `params` over the defaults. 1 for an
/// unknown name (makeFilter then reports it).
double defaultFilterRadius(const std::string& name, const FilterParams& params = {});

/// Shape parameters a filter accepts, with defaults (for --help and docs).
FilterParams defaultFilterParams(const std::string& name);

}  // namespace aliaslab
