// hann: the Hann-windowed sinc (separable).
//
// | parameter | meaning                                        | default |
// |-----------|------------------------------------------------|---------|
// | (radius)  | half-width of the square support               | sweep   |
// | tau       | lobes of the sinc inside the support (>= 1)    | 3       |
//
// g(x) = sinc(x') * 0.5 (1 + cos(pi x / r)), x' = tau x / r: the same sinc
// as lanczos under a raised-cosine window, which falls to 0 smoothly at r.
// Integral numeric (computed once). Slightly softer ringing than Lanczos.
#include "filter/filter_batch_impl.h"

namespace aliaslab::filterimpl {
namespace {

class HannFilter final : public SeparableFilter<HannFilter> {
 public:
  HannFilter(float r, double tau)
      : SeparableFilter(r), tau_(tau), scale_(static_cast<float>(tau / r)), invR_(1.f / r) {
    const double i1 = integrate([&](double x) { return g(static_cast<float>(x)); }, -r, r, 1024);
    integral_ = i1 * i1;
  }
  // by trig::sincPi and cosPi, the same code for g, g4 and g8 (bit for bit)
  template <class T>
  [[gnu::always_inline]] T gt(const T& x) const {
    return trig::sincPi(T(x * scale_)) * (0.5f * (1.f + trig::cosPi(T(x * invR_))));
  }
  float g(float x) const { return gt(x); }
  Lanes g4(const Lanes& x) const { return gt(x); }
  ALIASLAB_AVX2 Pack8 g8(const Pack8& x) const { return gt(x); }
  double integral() const override { return integral_; }
  std::string name() const override { return "hann"; }
  FilterParams params() const override { return {{"tau", tau_}}; }

 private:
  double tau_;
  float scale_, invR_;
  double integral_;
};

}  // namespace

std::shared_ptr<const BatchKernel> hannBatch(const Filter& f) { return batchFor<HannFilter>(f); }

std::unique_ptr<Filter> makeHann(float r, const FilterParams& p) {
  requireRange("hann", "tau", p.at("tau"), 1, 1e3);
  return std::make_unique<HannFilter>(r, p.at("tau"));
}

}  // namespace aliaslab::filterimpl
