// mitchell: the Mitchell-Netravali cubic family (separable).
//
// | parameter | meaning                                        | default |
// |-----------|------------------------------------------------|---------|
// | (radius)  | half-width of the square support               | sweep   |
// | B         | blur: B = 1 is the cubic B-spline, [-10, 10]   | 1/3     |
// | C         | ringing: C = 1/2 with B = 0 is Catmull-Rom,    | 1/3     |
// |           | [-10, 10]                                      |         |
//
// f(dx, dy) = m(2 dx / r) m(2 dy / r): the cubic m with natural support
// [-2, 2] stretched to [-r, r]. m integrates to 1 for every B, C, so the
// integral is (r / 2)^2. B = C = 1/3 (Mitchell and Netravali's advice) has
// small negative lobes: sharper than the Gaussian with little ringing; the
// usual radius is 2.
#include "filter/filter_batch_impl.h"

namespace aliaslab::filterimpl {
namespace {

class MitchellFilter final : public SeparableFilter<MitchellFilter> {
 public:
  MitchellFilter(const std::string& name, float r, double B, double C, bool showParams)
      : SeparableFilter(r), name_(name), B_(B), C_(C), show_(showParams), scale_(2.f / r),
        p0_((6 - 2 * B) / 6), p2_((-18 + 12 * B + 6 * C) / 6), p3_((12 - 9 * B - 6 * C) / 6),
        q0_((8 * B + 24 * C) / 6), q1_((-12 * B - 48 * C) / 6), q2_((6 * B + 30 * C) / 6), q3_((-B - 6 * C) / 6) {}
  float g(float x) const {
    const float t = std::abs(x * scale_);
    if (t < 1.f) return p0_ + t * t * (p2_ + t * p3_);
    if (t < 2.f) return q0_ + t * (q1_ + t * (q2_ + t * q3_));
    return 0.f;
  }
  Lanes g4(const Lanes& x) const {  // both pieces, then the choice: bit for bit g
    const Lanes t = (x * scale_).abs();
    const Lanes inner = p0_ + t * t * (p2_ + t * p3_), outer = q0_ + t * (q1_ + t * (q2_ + t * q3_));
    return ifLess(t, 1.f, inner, ifLess(t, 2.f, outer, Lanes::Zero()));
  }
  ALIASLAB_AVX2 Pack8 g8(const Pack8& x) const {  // the same in 8 lanes
    const Pack8 t = abs8(x * scale_);
    const Pack8 inner = p0_ + t * t * (p2_ + t * p3_), outer = q0_ + t * (q1_ + t * (q2_ + t * q3_));
    return ifLess8(t, 1.f, inner, ifLess8(t, 2.f, outer, Pack8{}));
  }
  double integral() const override { return 0.25 * double(radius()) * radius(); }
  std::string name() const override { return name_; }
  FilterParams params() const override {
    if (!show_) return {};
    return {{"B", B_}, {"C", C_}};
  }

 private:
  std::string name_;
  double B_, C_;
  bool show_;
  float scale_;  ///< natural support / radius
  float p0_, p2_, p3_, q0_, q1_, q2_, q3_;
};

}  // namespace

std::shared_ptr<const BatchKernel> mitchellBatch(const Filter& f) { return batchFor<MitchellFilter>(f); }

std::unique_ptr<Filter> makeMitchellNamed(const std::string& name, float r, double B, double C, bool showParams) {
  return std::make_unique<MitchellFilter>(name, r, B, C, showParams);
}

std::unique_ptr<Filter> makeMitchell(float r, const FilterParams& p) {
  const double B = p.at("B"), C = p.at("C");
  requireRange("mitchell", "B", B, -10, 10);
  requireRange("mitchell", "C", C, -10, 10);
  return makeMitchellNamed("mitchell", r, B, C, true);
}

}  // namespace aliaslab::filterimpl
