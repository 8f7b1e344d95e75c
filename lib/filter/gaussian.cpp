// gaussian: a radial Gaussian cut at the radius.
//
// | parameter     | meaning                                           | default |
// |---------------|---------------------------------------------------|---------|
// | (radius)      | radius of the disc support (independent of sigma) | sweep   |
// | sigma         | standard deviation, pixels (> 0)                  | 0.5     |
// | subtract_edge | 1: subtract exp(-r^2 / 2 sigma^2) so f(r) = 0;    | 0       |
// |               | 0: plain cut, f jumps to 0 at r (classic)         |         |
//
// f(dx, dy) = exp(-d^2 / 2 sigma^2) [- e_r] for d <= r, else 0. Integral over
// the disc: 2 pi sigma^2 (1 - e_r) [- e_r pi r^2], e_r = exp(-r^2 / 2 sigma^2).
// Non-negative, no ringing, a tunable blur; subtract the edge at small r /
// sigma ratios where the cut is visible. The classic reconstruction uses
// its course variant, course-gaussian (the course's uncut Gaussian).
#include "core/error.h"
#include "filter/filter_batch_impl.h"

namespace aliaslab::filterimpl {
namespace {

class GaussianFilter final : public RadialFilter<GaussianFilter> {
 public:
  GaussianFilter(float r, double sigma, bool subtract)
      : RadialFilter(r), sigma_(sigma), subtract_(subtract),
        k_(static_cast<float>(-0.5 / (sigma * sigma))),
        edge_(subtract ? std::exp(k_ * r * r) : 0.f) {}
  float g(float d) const { return std::exp(k_ * d * d) - edge_; }
  float k() const { return k_; }
  float edge() const { return edge_; }
  double integral() const override {
    const double r2 = double(radius()) * radius(), er = std::exp(-r2 / (2 * sigma_ * sigma_));
    return 2 * M_PI * sigma_ * sigma_ * (1 - er) - (subtract_ ? er * M_PI * r2 : 0.0);
  }
  std::string name() const override { return "gaussian"; }
  FilterParams params() const override { return {{"sigma", sigma_}, {"subtract_edge", subtract_ ? 1 : 0}}; }

 private:
  double sigma_;
  bool subtract_;
  float k_;     ///< -1 / (2 sigma^2)
  float edge_;  ///< subtracted edge value (0 unless subtract_edge)
};

/// The batch: per-axis exponentials, products cut to the disc as eval() rounds it; 8 lanes where the CPU has
/// AVX2 (exp8: Eigen's exp bit for bit).
class GaussianBatch final : public BatchKernel {
 public:
  explicit GaussianBatch(const GaussianFilter& f) : k_(f.k()), edge_(f.edge()), disc_(discBound(f.radius())) {}
  void eval(int count, const float* x, const float* y, const float* cx, const float* cy, int n,
            float* out) const override {
    const size_t stride = batchStride(count);
    Scratch scratch(4 * n * stride);
    float *dx2 = scratch.data(), *dy2 = dx2 + n * stride, *ex = dy2 + n * stride, *ey = ex + n * stride;
    size_t done = 0;  // samples done in 8 lanes
    if (eightLanes()) {
      done = squaredOffsets8(x, cx, n, stride, dx2), squaredOffsets8(y, cy, n, stride, dy2);
      weights8(dx2, dy2, ex, ey, n, stride, out);
    }
    squaredOffsets(x, cx, n, stride, dx2, done), squaredOffsets(y, cy, n, stride, dy2, done);
    for (int a = 0; a < n; ++a)
      for (size_t k = a * stride + done; k < (a + 1) * stride; k += 4)
        lanes(ex + k) = (lanes(dx2 + k) * k_).exp(), lanes(ey + k) = (lanes(dy2 + k) * k_).exp();
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a)
        for (size_t s = done; s < stride; s += 4) {
          const size_t i = a * stride + s, j = b * stride + s;
          lanes(out + (b * n + a) * stride + s) =
              keepLe(lanes(dx2 + i) + lanes(dy2 + j), disc_, lanes(ex + i) * lanes(ey + j) - edge_);
        }
  }

 private:
  /// The exponentials and weights in 8 lanes for the first stride rounded down to 8 samples.
  [[gnu::target("avx2")]] void weights8(const float* dx2, const float* dy2, float* ex, float* ey, int n,
                                          size_t stride, float* out) const {
    const size_t end = stride & ~size_t(7);
    for (int a = 0; a < n; ++a)
      for (size_t k = a * stride; k < a * stride + end; k += 8)
        store8(ex + k, exp8(load8(dx2 + k) * k_)), store8(ey + k, exp8(load8(dy2 + k) * k_));
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a)
        for (size_t s = 0; s < end; s += 8) {
          const size_t i = a * stride + s, j = b * stride + s;
          store8(out + (b * n + a) * stride + s,
                 keepLe8(load8(dx2 + i) + load8(dy2 + j), disc_, load8(ex + i) * load8(ey + j) - edge_));
        }
  }
  float k_, edge_, disc_;
};

}  // namespace

std::shared_ptr<const BatchKernel> gaussianBatch(const Filter& f) {
  const auto* g = dynamic_cast<const GaussianFilter*>(&f);
  return g ? std::make_shared<GaussianBatch>(*g) : nullptr;
}

std::unique_ptr<Filter> makeGaussian(float r, const FilterParams& p) {
  const double sigma = p.at("sigma"), sub = p.at("subtract_edge");
  // -1 / (2 sigma^2) and 2 pi sigma^2 stay finite in float and double (fuzz_cli found sigma = 6e199)
  requireRange("gaussian", "sigma", sigma, 1e-3, 1e3);
  if (sub != 0 && sub != 1)
    throw OptionError("filter-param", "gaussian subtract_edge must be 0 or 1, got " + std::to_string(sub));
  return std::make_unique<GaussianFilter>(r, sigma, sub == 1);
}

}  // namespace aliaslab::filterimpl
