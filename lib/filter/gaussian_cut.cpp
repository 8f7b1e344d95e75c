// gaussian-cut: the fixed-sigma radial Gaussian cut at the radius (the
// Gaussian of the course and of earlier studies).
//
// | parameter     | meaning                                           | default |
// |---------------|---------------------------------------------------|---------|
// | (radius)      | radius of the disc support (independent of sigma) | 3 sigma |
// | sigma         | standard deviation, pixels (> 0)                  | 0.5     |
// | subtract_edge | 1: subtract exp(-r^2 / 2 sigma^2) so f(r) = 0;    | 0       |
// |               | 0: plain cut, f jumps to 0 at r (classic)         |         |
//
// gaussian (gaussian.cpp) with sigma fixed: f(dx, dy) = exp(-d^2 / 2 sigma^2)
// [- e_r] for d <= r, else 0, so the radius only cuts it and its blur hardly
// changes beyond r = 2 sigma. Not one of the study's filters (filterNames()),
// in allFilterNames(). The classic reconstruction uses course-gaussian.
#include "filter/filter_impl.h"

namespace aliaslab::filterimpl {

std::unique_ptr<Filter> makeGaussianCut(float r, const FilterParams& p) {
  return makeGaussianNamed("gaussian-cut", r, p.at("sigma"), p.at("subtract_edge"));
}

}  // namespace aliaslab::filterimpl
