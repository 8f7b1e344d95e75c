// tent: the classic radial cone.
//
// | parameter | meaning                        | default |
// |-----------|--------------------------------|---------|
// | (radius)  | radius of the disc support     | sweep   |
//
// f(dx, dy) = max(0, 1 - d / r), d = sqrt(dx^2 + dy^2) (radial, not the
// separable product of two 1-D tents). Integral pi r^2 / 3. A cheap
// non-negative low-pass: smoother than the box, blurrier than Mitchell.
#include "filter/filter_batch_impl.h"

namespace aliaslab::filterimpl {
namespace {

class TentFilter final : public RadialFilter<TentFilter> {
 public:
  explicit TentFilter(float r) : RadialFilter(r), invR_(1.f / r) {}
  float g(float d) const { return std::max(0.f, 1.f - d * invR_); }
  // 0 beyond r up to rounding (1 - d / r <= 0 there)
  Lanes g4(const Lanes& d) const { return (1.f - d * invR_).max(0.f); }
  ALIASLAB_AVX2 Pack8 g8(const Pack8& d) const {
    const Pack8 v = 1.f - d * invR_;
    return v > 0.f ? v : Pack8{};
  }
  double integral() const override { return M_PI * double(radius()) * radius() / 3.0; }
  std::string name() const override { return "tent"; }

 private:
  float invR_;
};

}  // namespace

std::shared_ptr<const BatchKernel> tentBatch(const Filter& f) { return batchFor<TentFilter>(f); }

std::unique_ptr<Filter> makeTent(float r, const FilterParams&) { return std::make_unique<TentFilter>(r); }

}  // namespace aliaslab::filterimpl
