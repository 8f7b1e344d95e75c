// Filter importance sampling beside a filter: samples placed with density
// |f| / integral |f| around the pixel centre, each weighted by
// sign(f) * integral |f| (the film's ImportanceSampled reconstruction sums
// w L / sum w over a pixel's own samples).
//
// The table: |f| averaged over cells of width r / 1024 along each separable
// axis (f = g(x) g(y), so |f| factorises), or along the radius of radial
// filters (mass 2 pi rho |g(rho)|); absIntegral() is its total (the square
// of the axis total for separable filters).
//
// Protocol: built once from a finished Filter, which must outlive it;
// immutable, safe to use from many threads at once.
#pragma once
#include <vector>

#include "core/math.h"
#include "filter/filter.h"

namespace aliaslab {

class FilterSampler {
 public:
  explicit FilterSampler(const Filter& filter);

  const Filter& filter() const { return *filter_; }
  /// Integral of |f| (numeric, over the table).
  double absIntegral() const { return absIntegral_; }
  /// Maps u in [0,1)^2 to an offset with density |f| / absIntegral() (up to
  /// the tabulation) and sets `weight` = sign(f(offset)) * absIntegral().
  /// Separable filters use u.x for dx and u.y for dy; radial ones u.x for
  /// the distance and u.y for the angle.
  Vec2 sample(const Vec2& u, float& weight) const;

 private:
  const Filter* filter_;
  bool radial_ = false;
  double lo_ = 0, cell_ = 0;  ///< first cell start and cell width
  std::vector<double> cdf_;   ///< cells + 1 cumulative masses, cdf[0] = 0
  double absIntegral_ = 0;
};

}  // namespace aliaslab
