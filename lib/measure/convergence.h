// Convergence of sampling patterns on analytic integrands (docs/science.md,
// "Convergence on analytic integrands").
//
// Protocol: an estimate of an integrand's integral over the unit square is
// the mean of f over one N-point set. convergenceRmse() draws `realisations`
// independent sets from one Sampler (the sets of pixels 0, 1, 2, ... of a
// row-major strip, which the sampler decorrelates by its pixel hash) and
// returns the root mean square error of those estimates against the exact
// value. fitLogLogSlope() turns (N, RMSE) pairs into a convergence rate by
// least squares on log-log axes over a stated range of N. The experiment's
// tables made of these (every sampler, the slopes against theory) are in
// convergence_study.h.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "sampling/sampler.h"

namespace aliaslab {

/// A function on [0,1)^2 with a known integral.
struct Integrand {
  std::string name;            ///< "disk", "triangle", "step", "gaussian", "bilinear"
  std::string formula;         ///< one line, e.g. "x^2 + y^2 < 2/pi"
  double (*f)(double x, double y);
  double exact;                ///< integral over the unit square
  double sigma;                ///< standard deviation of f(U) for U uniform (RMSE of random sampling at N = 1)
  bool discontinuous;          ///< true for the indicator functions
};

/// The five integrands of docs/science.md, in its order.
const std::vector<Integrand>& integrands();

/// Estimates of every integrand from `realisations` sets of `sampler`:
/// returns one RMSE per integrand (same order as `integrands`). Sets are
/// generated in parallel on `threads` threads (0 = all cores); the result
/// does not depend on the thread count.
std::vector<double> convergenceRmse(const Sampler& sampler, const std::vector<Integrand>& integrands,
                                    int realisations, int threads = 0);

/// A least-squares line log(y) = intercept + slope log(n).
struct SlopeFit {
  double slope = 0;       ///< d log(rmse) / d log(N)
  double intercept = 0;   ///< natural-log intercept
  double slopeError = 0;  ///< standard error of the slope (0 with fewer than 3 points)
  int points = 0;         ///< pairs used
};

/// Fits log(y) against log(n) over the pairs with nMin <= n <= nMax (and,
/// when powersOfTwoOnly, n a power of two) and y > 0. Throws
/// std::invalid_argument with fewer than two usable pairs or a single n.
SlopeFit fitLogLogSlope(const std::vector<double>& n, const std::vector<double>& y, double nMin, double nMax,
                        bool powersOfTwoOnly = false);

/// The convergence rate theory expects for `sampler` on `integrand`, and
/// where the expectation comes from.
struct ExpectedSlope {
  std::optional<double> slope;  ///< empty: no stated expectation
  std::string source;           ///< "docs/science.md", "literature: ...", or why there is none
};
ExpectedSlope expectedSlope(const std::string& sampler, const Integrand& integrand);

}  // namespace aliaslab
