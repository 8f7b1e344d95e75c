#include "measure/convergence.h"

#include <cmath>
#include <stdexcept>

#include "core/parallel.h"

namespace aliaslab {

namespace {
constexpr double kPiD = 3.14159265358979323846;

double disk(double x, double y) { return x * x + y * y < 2.0 / kPiD ? 1.0 : 0.0; }
double triangle(double x, double y) { return y < x ? 1.0 : 0.0; }
double step(double x, double) { return x < 1.0 / kPiD ? 1.0 : 0.0; }
double gaussian(double x, double y) { return std::exp(-x * x - y * y); }
double bilinear(double x, double y) { return x * y; }

// Integrals of the Gaussian over [0,1]: of exp(-x^2) and of exp(-2 x^2).
const double kG1 = std::sqrt(kPiD) / 2.0 * std::erf(1.0);
const double kG2 = std::sqrt(kPiD / 2.0) / 2.0 * std::erf(std::sqrt(2.0));

double indicatorSigma(double p) { return std::sqrt(p * (1.0 - p)); }

bool isPowerOfTwo(double n) {
  const double l = std::log2(n);
  return n >= 1 && std::abs(l - std::round(l)) < 1e-9;
}
}  // namespace

const std::vector<Integrand>& integrands() {
  static const std::vector<Integrand> list = {
      {"disk", "x^2 + y^2 < 2/pi", disk, 0.5, indicatorSigma(0.5), true},
      {"triangle", "y < x", triangle, 0.5, indicatorSigma(0.5), true},
      {"step", "x < 1/pi", step, 1.0 / kPiD, indicatorSigma(1.0 / kPiD), true},
      {"gaussian", "exp(-x^2 - y^2)", gaussian, kG1 * kG1, std::sqrt(kG2 * kG2 - kG1 * kG1 * kG1 * kG1), false},
      {"bilinear", "x y", bilinear, 0.25, std::sqrt(1.0 / 9.0 - 1.0 / 16.0), false},
  };
  return list;
}

std::vector<double> convergenceRmse(const Sampler& sampler, const std::vector<Integrand>& fs, int realisations,
                                    int threads) {
  // One row of squared errors per realisation, summed afterwards in a fixed order.
  const int n = sampler.spp();
  std::vector<double> sq(static_cast<size_t>(realisations) * fs.size(), 0.0);
  parallelFor(realisations, threads, [&](int k) {
    std::vector<Vec2> pts(n);
    sampler.generate(k % 256, k / 256, pts.data());
    for (size_t i = 0; i < fs.size(); ++i) {
      double sum = 0.0;
      for (const Vec2& p : pts) sum += fs[i].f(p.x(), p.y());
      const double err = sum / n - fs[i].exact;
      sq[static_cast<size_t>(k) * fs.size() + i] = err * err;
    }
  });
  std::vector<double> rmse(fs.size(), 0.0);
  for (int k = 0; k < realisations; ++k)
    for (size_t i = 0; i < fs.size(); ++i) rmse[i] += sq[static_cast<size_t>(k) * fs.size() + i];
  for (double& r : rmse) r = std::sqrt(r / realisations);
  return rmse;
}

SlopeFit fitLogLogSlope(const std::vector<double>& n, const std::vector<double>& y, double nMin, double nMax,
                        bool powersOfTwoOnly) {
  if (n.size() != y.size()) throw std::invalid_argument("fitLogLogSlope: n and y differ in length");
  // Ordinary least squares on (log n, log y).
  std::vector<double> lx, ly;
  for (size_t i = 0; i < n.size(); ++i) {
    if (n[i] < nMin || n[i] > nMax || !(y[i] > 0) || !std::isfinite(y[i])) continue;
    if (powersOfTwoOnly && !isPowerOfTwo(n[i])) continue;
    lx.push_back(std::log(n[i]));
    ly.push_back(std::log(y[i]));
  }
  const size_t m = lx.size();
  if (m < 2) throw std::invalid_argument("fitLogLogSlope: fewer than two points in the N range");
  double mx = 0, my = 0;
  for (size_t i = 0; i < m; ++i) mx += lx[i], my += ly[i];
  mx /= m, my /= m;
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < m; ++i) sxx += (lx[i] - mx) * (lx[i] - mx), sxy += (lx[i] - mx) * (ly[i] - my);
  if (sxx <= 0) throw std::invalid_argument("fitLogLogSlope: every point has the same N");
  SlopeFit fit;
  fit.slope = sxy / sxx;
  fit.intercept = my - fit.slope * mx;
  fit.points = static_cast<int>(m);
  if (m > 2) {
    double rss = 0;
    for (size_t i = 0; i < m; ++i) {
      const double r = ly[i] - fit.intercept - fit.slope * lx[i];
      rss += r * r;
    }
    fit.slopeError = std::sqrt(rss / (m - 2) / sxx);
  }
  return fit;
}

ExpectedSlope expectedSlope(const std::string& s, const Integrand& f) {
  const bool disc = f.discontinuous;
  // Stated in docs/science.md.
  if (s == "random") return {-0.5, "docs/science.md"};
  if (s == "jittered") return {disc ? -0.75 : -1.0, "docs/science.md"};
  if (s == "sobol" || s == "pmj02") return {disc ? -0.75 : -1.5, "docs/science.md (powers of two)"};
  // Literature values for the other stratified patterns.
  if (s == "multijittered" || s == "cmj")
    return {disc ? -0.75 : -1.0, "literature: as jittered (Christensen et al. 2018)"};
  if (s == "nrooks")
    return {-0.5, "literature: Latin hypercube, -0.5 for non-additive f (Owen 1997)"};
  if (s == "uniform") return {{}, "no stated expectation (deterministic grid: one error, no spread)"};
  return {{}, "no stated expectation"};
}

}  // namespace aliaslab
