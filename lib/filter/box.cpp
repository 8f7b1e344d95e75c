// box: the pixel-area filter when r = 0.5.
//
// | parameter | meaning                         | default |
// |-----------|---------------------------------|---------|
// | (radius)  | half-width of the square support| sweep   |
//
// f(dx, dy) = 1 where |dx| <= r and |dy| <= r (square support, closed), else 0.
// Integral 4 r^2. Use it as the reference for "pixel area" (r = 0.5) and as
// the sharpest, most aliasing-prone baseline; larger radii are a plain blur.
#include "filter/filter_batch_impl.h"

namespace aliaslab::filterimpl {
namespace {

class BoxFilter final : public SeparableFilter<BoxFilter> {
 public:
  using SeparableFilter::SeparableFilter;
  float g(float) const { return 1.f; }
  Lanes g4(const Lanes&) const { return Lanes::Ones(); }
  double integral() const override { return 4.0 * radius() * radius(); }
  std::string name() const override { return "box"; }
};

}  // namespace

/// Unit weights: the film skips them.
std::shared_ptr<const BatchKernel> boxBatch(const Filter& f) { return batchFor<BoxFilter>(f, true); }

std::unique_ptr<Filter> makeBox(float r, const FilterParams&) { return std::make_unique<BoxFilter>(r); }

}  // namespace aliaslab::filterimpl
