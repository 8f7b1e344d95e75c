// blackmanharris: the 4-term Blackman-Harris window (separable).
//
// | parameter | meaning                          | default |
// |-----------|----------------------------------|---------|
// | (radius)  | half-width of the square support | sweep   |
//
// g(x) = a0 + a1 cos(pi x / r) + a2 cos(2 pi x / r) + a3 cos(3 pi x / r) on
// [-r, r] with (a0, a1, a2, a3) = (0.35875, 0.48829, 0.14128, 0.01168):
// the centred form of the classic window, 1 at 0 and 6e-5 at the edge.
// Non-negative, integral (2 r a0)^2 (the cosines integrate to 0). A smooth
// Gaussian-like blur with a compact support; a good default at r = 1.5-2.
#include "filter/filter_batch_impl.h"

namespace aliaslab::filterimpl {
namespace {

constexpr float a0 = 0.35875f, a1 = 0.48829f, a2 = 0.14128f, a3 = 0.01168f;

class BlackmanHarrisFilter final : public SeparableFilter<BlackmanHarrisFilter> {
 public:
  explicit BlackmanHarrisFilter(float r) : SeparableFilter(r), w_(kPi / r) {}
  float g(float x) const {
    const float c = std::cos(w_ * x);  // cos(2t), cos(3t) by Chebyshev recurrences
    const float c2 = 2 * c * c - 1, c3 = c * (2 * c2 - 1);
    return a0 + a1 * c + a2 * c2 + a3 * c3;
  }
  Lanes g4(const Lanes& x) const {
    const Lanes c = (x * w_).cos(), c2 = 2 * c * c - 1, c3 = c * (2 * c2 - 1);
    return a0 + a1 * c + a2 * c2 + a3 * c3;
  }
  // g4 in 8 lanes: cos8 is Eigen's cos bit for bit, then the same operations
  ALIASLAB_AVX2 Pack8 g8(const Pack8& x) const {
    const Pack8 c = cos8(x * w_), c2 = 2.f * c * c - 1.f, c3 = c * (2.f * c2 - 1.f);
    return a0 + a1 * c + a2 * c2 + a3 * c3;
  }
  double integral() const override {
    const double s = 2.0 * radius() * 0.35875;
    return s * s;
  }
  std::string name() const override { return "blackmanharris"; }

 private:
  float w_;  ///< pi / r
};

}  // namespace

std::shared_ptr<const BatchKernel> blackmanHarrisBatch(const Filter& f) { return batchFor<BlackmanHarrisFilter>(f); }

std::unique_ptr<Filter> makeBlackmanHarris(float r, const FilterParams&) {
  return std::make_unique<BlackmanHarrisFilter>(r);
}

}  // namespace aliaslab::filterimpl
