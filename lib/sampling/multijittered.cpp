// multijittered: multi-jittered sampling (Chiu, Shirley and Wang 1994).
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | one point in each cell of the m x n grid of gridShape(spp) |
// |            | AND one in each of the spp columns and rows of width 1/spp |
// |            | (jittered and n-rooks at once)                             |
// | method     | canonical arrangement: cell (c, r) takes x sub-column r and |
// |            | y sub-row c; then the x sub-columns are shuffled among the |
// |            | cells of each column and the y sub-rows among the cells of |
// |            | each row (Fisher-Yates), then jittered inside the          |
// |            | 1/spp x 1/spp sub-cell                                     |
// | randomness | shuffles and jitter from HashRng(hash(pixelSeed, tag))     |
// | counts     | any spp: the gridShape m x n grid (8 -> 2x4, 7 -> 1x7,      |
// |            | which degenerates to n-rooks with 1 x 7 strata); warning() |
// |            | says so when spp is not a square                           |
// | use it     | a better jittered at the same count; see also cmj (faster, |
// |            | correlated shuffles, usually lower error).                 |
#include <utility>
#include <vector>

#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

class MultiJitteredSampler final : public Sampler {
 public:
  MultiJitteredSampler(int spp, uint64_t seed) : Sampler(spp, seed) { gridShape(spp, m_, n_); }

  void generate(int px, int py, Vec2* out) const override {
    const int count = spp();
    HashRng rng(hashWords(pixelSeed(seed(), px, py), 0x6d6a6974ULL));
    // Canonical arrangement: point i = r m + c sits in sub-column r and sub-row c.
    std::vector<int> subX(count), subY(count);
    for (int r = 0; r < n_; ++r)
      for (int c = 0; c < m_; ++c) subX[r * m_ + c] = r, subY[r * m_ + c] = c;
    // Shuffle sub-columns within each column (over its n cells).
    for (int c = 0; c < m_; ++c)
      for (int r = n_ - 1; r > 0; --r) std::swap(subX[r * m_ + c], subX[rng.nextBelow(r + 1) * m_ + c]);
    // Shuffle sub-rows within each row (over its m cells).
    for (int r = 0; r < n_; ++r)
      for (int c = m_ - 1; c > 0; --c) std::swap(subY[r * m_ + c], subY[r * m_ + rng.nextBelow(c + 1)]);
    // Jitter inside the fine strata: x in column c, y in row r.
    for (int r = 0, i = 0; r < n_; ++r)
      for (int c = 0; c < m_; ++c, ++i) {
        const float u = rng.nextFloat(), v = rng.nextFloat();
        out[i] = Vec2(stratumPoint(c * n_ + subX[i], u, count), stratumPoint(r * m_ + subY[i], v, count));
      }
  }
  std::string name() const override { return "multijittered"; }
  std::string describe() const override {
    return "multijittered " + gridLabel(spp()) + " strata + " + std::to_string(spp()) + " rows/columns" +
           (m_ == n_ ? "" : " (spp " + std::to_string(spp()) + " is not square)");
  }
  std::string warning() const override { return gridWarning("multijittered", spp()); }

 private:
  int m_ = 1, n_ = 1;  ///< columns, rows
};

}  // namespace

std::unique_ptr<Sampler> makeMultiJitteredSampler(int spp, uint64_t seed) {
  return std::make_unique<MultiJitteredSampler>(spp, seed);
}

}  // namespace aliaslab::sampling
