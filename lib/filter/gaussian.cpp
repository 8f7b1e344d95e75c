// gaussian: a radial Gaussian whose width follows the radius.
//
// | parameter     | meaning                                           | default |
// |---------------|---------------------------------------------------|---------|
// | (radius)      | radius r of the disc support                      | sweep   |
// | sigma         | standard deviation, pixels; 0: r / 3, the width   | 0       |
// |               | follows the radius (pbrt-v4's proportion); > 0:   |         |
// |               | this sigma at any r, cut at r                     |         |
// | subtract_edge | 1: subtract exp(-r^2 / 2 sigma^2) so f(r) = 0;    | 0       |
// |               | 0: plain cut, f jumps to 0 at r (classic)         |         |
//
// f(dx, dy) = exp(-d^2 / 2 sigma^2) [- e_r] for d <= r, else 0. Integral over
// the disc: 2 pi sigma^2 (1 - e_r) [- e_r pi r^2], e_r = exp(-r^2 / 2 sigma^2).
// Non-negative, no ringing, a tunable blur. By default sigma = r / 3: the
// radius is the width as for every other filter (natural radius 1.5, sigma
// 0.5), and the cut sits at 3 sigma (e_r = 0.011). params() reports the sigma
// in use. The fixed-sigma Gaussian cut at r (sigma 0.5 unless given) is
// gaussian-cut (gaussian_cut.cpp), the same class under its own name. The
// classic reconstruction uses the course variant, course-gaussian (the
// course's uncut Gaussian) with the sigma in use.
#include "core/error.h"
#include "filter/filter_batch_impl.h"

namespace aliaslab::filterimpl {
namespace {

class GaussianFilter final : public RadialFilter<GaussianFilter> {
 public:
  GaussianFilter(std::string name, float r, double sigma, bool subtract)
      : RadialFilter(r), name_(std::move(name)), sigma_(sigma), subtract_(subtract),
        k_(static_cast<float>(-0.5 / (sigma * sigma))),
        edge_(subtract ? std::exp(k_ * r * r) : 0.f) {}
  float g(float d) const { return std::exp(k_ * d * d) - edge_; }
  float k() const { return k_; }
  float edge() const { return edge_; }
  double integral() const override {
    const double r2 = double(radius()) * radius(), er = std::exp(-r2 / (2 * sigma_ * sigma_));
    return 2 * M_PI * sigma_ * sigma_ * (1 - er) - (subtract_ ? er * M_PI * r2 : 0.0);
  }
  std::string name() const override { return name_; }
  FilterParams params() const override { return {{"sigma", sigma_}, {"subtract_edge", subtract_ ? 1 : 0}}; }

 private:
  std::string name_;  ///< gaussian or gaussian-cut
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

namespace {
bool subtractEdge(const std::string& name, double value) {
  if (value != 0 && value != 1)
    throw OptionError("filter-param", name + " subtract_edge must be 0 or 1, got " + std::to_string(value));
  return value == 1;
}
}  // namespace

std::unique_ptr<Filter> makeGaussianNamed(const std::string& name, float r, double sigma, double subtract) {
  // -1 / (2 sigma^2) and 2 pi sigma^2 stay finite in float and double (fuzz_cli found sigma = 6e199)
  requireRange(name, "sigma", sigma, 1e-3, 1e3);
  return std::make_unique<GaussianFilter>(name, r, sigma, subtractEdge(name, subtract));
}

std::unique_ptr<Filter> makeGaussian(float r, const FilterParams& p) {
  // sigma 0: r / 3, finite in -1 / (2 sigma^2) for every radius makeFilter takes ([1e-3, 1024])
  if (p.at("sigma") == 0)
    return std::make_unique<GaussianFilter>("gaussian", r, double(r) / 3, subtractEdge("gaussian", p.at("subtract_edge")));
  return makeGaussianNamed("gaussian", r, p.at("sigma"), p.at("subtract_edge"));
}

}  // namespace aliaslab::filterimpl
