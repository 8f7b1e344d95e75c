// course-gaussian: the course's Gaussian, uncut over the square it gathers.
//
// | parameter | meaning                                       | default |
// |-----------|-----------------------------------------------|---------|
// | (radius)  | half-width of the square support              | natural |
// | sigma     | standard deviation, pixels (> 0)              | 0.5     |
//
// f(dx, dy) = exp(-(dx^2 + dy^2) / 2 sigma^2) for |dx|, |dy| <= r, else 0:
// separable, g(x) = exp(-x^2 / 2 sigma^2), with no edge term. Its natural
// radius is the course's integer support plus half a pixel,
// ceil(2 sigma - 0.5) + 0.5, so the classic gather over the samples of
// pixels i-R..i+R (R = ceil(r - 0.5)) sees it uncut, as the course writes
// it. Integral (sigma sqrt(2 pi) erf(r / (sigma sqrt 2)))^2. This is the
// classic reconstruction's variant of gaussian (makeCourseVariant); as a
// filter of its own it is the Gaussian cut to a square.
#include "filter/filter_impl.h"

namespace aliaslab::filterimpl {
namespace {

class CourseGaussianFilter final : public SeparableFilter<CourseGaussianFilter> {
 public:
  CourseGaussianFilter(float r, double sigma)
      : SeparableFilter(r), sigma_(sigma), k_(static_cast<float>(-0.5 / (sigma * sigma))) {}
  float g(float x) const { return std::exp(k_ * x * x); }
  /// g(dx) g(dy) as the course writes it: one exponential of the summed exponents.
  float product(float dx, float dy) const { return std::exp(k_ * (dx * dx + dy * dy)); }
  double integral() const override {
    const double axis = sigma_ * std::sqrt(2 * M_PI) * std::erf(radius() / (sigma_ * M_SQRT2));
    return axis * axis;
  }
  std::string name() const override { return "course-gaussian"; }
  FilterParams params() const override { return {{"sigma", sigma_}}; }

 private:
  double sigma_;
  float k_;  ///< -1 / (2 sigma^2)
};

}  // namespace

std::unique_ptr<Filter> makeCourseGaussian(float r, const FilterParams& p) {
  requireRange("course-gaussian", "sigma", p.at("sigma"), 1e-3, 1e3);
  return std::make_unique<CourseGaussianFilter>(r, p.at("sigma"));
}

}  // namespace aliaslab::filterimpl
