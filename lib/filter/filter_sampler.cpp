// FilterSampler: the piecewise-constant table of |f| and its inversion.
#include "filter/filter_sampler.h"

#include <algorithm>
#include <cmath>

#include "filter/filter_impl.h"

namespace aliaslab {

namespace {

constexpr int kSeparableCells = 2048;  // over [-r, r]: width r / 1024
constexpr int kRadialCells = 1024;     // over [0, r]: width r / 1024

/// Cell index c with cdf[c] <= t < cdf[c+1] (skips empty cells), and the position in it in [0, 1).
int findCell(const std::vector<double>& cdf, double t, double& within) {
  const int cells = static_cast<int>(cdf.size()) - 1;
  int c = static_cast<int>(std::upper_bound(cdf.begin(), cdf.end(), t) - cdf.begin()) - 1;
  c = std::clamp(c, 0, cells - 1);
  while (c > 0 && cdf[c + 1] <= cdf[c]) --c;  // t at the very top: last non-empty cell
  const double mass = cdf[c + 1] - cdf[c];
  within = mass > 0 ? std::clamp((t - cdf[c]) / mass, 0.0, 1.0 - 1e-12) : 0.5;
  return c;
}

}  // namespace

FilterSampler::FilterSampler(const Filter& filter) : filter_(&filter), radial_(filter.radial()) {
  const double r = filter.radius();
  const int cells = radial_ ? kRadialCells : kSeparableCells;
  lo_ = radial_ ? 0.0 : -r;
  cell_ = (radial_ ? r : 2 * r) / cells;
  cdf_.assign(cells + 1, 0.0);
  for (int c = 0; c < cells; ++c) {
    const double a = lo_ + c * cell_, b = a + cell_;
    const double mass =
        radial_ ? filterimpl::integrate([&](double x) { return 2 * M_PI * x * std::abs(filter.profile(float(x))); }, a, b, 1)
                : filterimpl::integrate([&](double x) { return std::abs(filter.profile(float(x))); }, a, b, 1);
    cdf_[c + 1] = cdf_[c] + mass;
  }
  const double total = cdf_.back();
  absIntegral_ = radial_ ? total : total * total;
}

Vec2 FilterSampler::sample(const Vec2& u, float& weight) const {
  const double total = cdf_.back();
  Vec2 offset;
  double within;
  if (radial_) {
    // radius: uniform in area within the cell; angle uniform
    const int c = findCell(cdf_, u.x() * total, within);
    const double r0 = c * cell_, r1 = r0 + cell_;
    const double rho = std::sqrt(r0 * r0 + within * (r1 * r1 - r0 * r0));
    const double phi = 2 * M_PI * u.y();
    offset = Vec2(float(rho * std::cos(phi)), float(rho * std::sin(phi)));
  } else {
    for (int axis = 0; axis < 2; ++axis) {
      const int c = findCell(cdf_, u[axis] * total, within);
      offset[axis] = float(lo_ + (c + within) * cell_);
    }
  }
  const float r = filter_->radius();
  offset = offset.cwiseMax(-r).cwiseMin(r);
  weight = static_cast<float>(filter_->eval(offset.x(), offset.y()) < 0 ? -absIntegral_ : absIntegral_);
  return offset;
}

}  // namespace aliaslab
