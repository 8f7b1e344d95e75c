// lanczos: the Lanczos-windowed sinc (separable).
//
// | parameter | meaning                                        | default |
// |-----------|------------------------------------------------|---------|
// | (radius)  | half-width of the square support               | sweep   |
// | tau       | lobes of the sinc inside the support (>= 1)    | 3       |
//
// g(x) = sinc(x') sinc(x' / tau), x' = tau x / r, sinc(t) = sin(pi t)/(pi t):
// tau lobes of the sinc stretched to [-r, r]. At its natural support
// (r = tau) it is the classic Lanczos-tau, whose 3-lobe version has minimum
// -0.1473 and integral 0.99706 over [-3, 3]. Integral numeric (computed
// once). The sharpest filter here, closest to the ideal low-pass; rings at
// edges (negative lobes, possible negative pixels).
#include "filter/filter_batch_impl.h"

namespace aliaslab::filterimpl {
namespace {

class LanczosFilter final : public SeparableFilter<LanczosFilter> {
 public:
  LanczosFilter(float r, double tau)
      : SeparableFilter(r), tau_(tau), scale_(static_cast<float>(tau / r)), invTau_(static_cast<float>(1 / tau)) {
    const double i1 = integrate([&](double x) { return g(static_cast<float>(x)); }, -r, r, 1024);
    integral_ = i1 * i1;
  }
  // by trig::reduced, the same code for g, g4 and g8 (bit for bit)
  template <class T>
  [[gnu::always_inline]] T gt(const T& x) const {
    const T t = x * scale_, u = t * invTau_;
    T f, h;
    const T q = trig::reduced(t, f, trig::kSinc) * trig::reduced(u, h, trig::kSinc);
    return q * ((f * h + 1e-30f) / (t * u + 1e-30f));  // sinc(t) sinc(u): f / t and h / u in one division; 1 at 0
  }
  float g(float x) const { return gt(x); }
  Lanes g4(const Lanes& x) const { return gt(x); }
  ALIASLAB_AVX2 Pack8 g8(const Pack8& x) const { return gt(x); }
  double integral() const override { return integral_; }
  std::string name() const override { return "lanczos"; }
  FilterParams params() const override { return {{"tau", tau_}}; }

 private:
  double tau_;
  float scale_, invTau_;
  double integral_;
};

}  // namespace

std::shared_ptr<const BatchKernel> lanczosBatch(const Filter& f) { return batchFor<LanczosFilter>(f); }

std::unique_ptr<Filter> makeLanczos(float r, const FilterParams& p) {
  requireRange("lanczos", "tau", p.at("tau"), 1, 1e3);
  return std::make_unique<LanczosFilter>(r, p.at("tau"));
}

}  // namespace aliaslab::filterimpl
