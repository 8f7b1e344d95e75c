// catmullrom: the Catmull-Rom spline, Mitchell-Netravali with B = 0, C = 1/2.
//
// | parameter | meaning                          | default |
// |-----------|----------------------------------|---------|
// | (radius)  | half-width of the square support | sweep   |
//
// No shape parameters (use mitchell with B, C for the family). Separable,
// natural support [-2, 2] stretched to [-r, r], integral (r / 2)^2, minimum
// -2/27 = -0.07407 at |x| = 4/3 natural units: the sharpest of the cubics,
// with visible ringing at edges.
#include "filter/filter_impl.h"

namespace aliaslab::filterimpl {

std::unique_ptr<Filter> makeCatmullRom(float r, const FilterParams&) {
  return makeMitchellNamed("catmullrom", r, 0.0, 0.5, false);
}

}  // namespace aliaslab::filterimpl
