// jittered: stratified sampling, one uniform point in each grid cell.
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | ((c + u) / m, (r + v) / n) for every cell (c, r) of the    |
// |            | m x n grid of gridShape(spp), row by row                   |
// | randomness | (u, v) = the two halves of hash(pixelSeed, cell index)     |
// | counts     | any spp: the gridShape m x n grid (8 -> 2x4, 7 -> 1x7);    |
// |            | warning() says so when spp is not a square. A prime spp    |
// |            | gives 1 x spp strips: stratified in y only                 |
// | bound      | Var <= sigma^2 / spp (varianceBound 1): never worse than   |
// |            | random, at any spp (equal-area strata)                     |
// | use it     | the classic cheap improvement over random (Cook 1986):     |
// |            | RMSE ~ N^-3/4 on edges at square counts.                   |
#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

class JitteredSampler final : public Sampler {
 public:
  JitteredSampler(int spp, uint64_t seed) : Sampler(spp, seed) { gridShape(spp, m_, n_); }

  void generate(int px, int py, Vec2* out) const override {
    const uint64_t key = pixelSeed(seed(), px, py);
    for (int r = 0, i = 0; r < n_; ++r)
      for (int c = 0; c < m_; ++c, ++i) {
        const uint64_t h = hashWords(key, static_cast<uint64_t>(i));
        const float u = fixedToUnit(static_cast<uint32_t>(h >> 32)), v = fixedToUnit(static_cast<uint32_t>(h));
        out[i] = Vec2(stratumPoint(c, u, m_), stratumPoint(r, v, n_));
      }
  }
  std::string name() const override { return "jittered"; }
  std::string describe() const override {
    return "jittered " + gridLabel(spp()) + " strata" + (m_ == n_ ? "" : " (spp " + std::to_string(spp()) + " is not square)");
  }
  std::string warning() const override { return gridWarning("jittered", spp()); }
  // One independent uniform point in each of spp equal-area strata (any m x n grid): Var = (1/spp^2) sum of the
  // strata's variances <= sigma^2 / spp, the between-strata part of sigma^2 removed.
  double varianceBound() const override { return 1; }

 private:
  int m_ = 1, n_ = 1;  ///< columns, rows
};

}  // namespace

std::unique_ptr<Sampler> makeJitteredSampler(int spp, uint64_t seed) {
  return std::make_unique<JitteredSampler>(spp, seed);
}

}  // namespace aliaslab::sampling
