// cmj: correlated multi-jittered sampling (Kensler 2013).
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | one point in each cell of the m x n grid of gridShape(spp) |
// |            | and one in each of the spp columns and rows of width 1/spp |
// | method     | Kensler's cmj(): the sub-column of a cell depends only on  |
// |            | its row and the sub-row only on its column (the same      |
// |            | permute() for every row / column: "correlated" shuffles),  |
// |            | jitter from randfloat(); the sample order is permuted too  |
// | randomness | per-pixel pattern index p = 32 bits of pixelSeed(seed, px, |
// |            | py), hashed with Kensler's constants per use; the m + n    |
// |            | shuffled sub-strata are computed once per pixel (a         |
// |            | thread_local table), the rest point by point               |
// | counts     | any spp: the gridShape m x n grid (m n = spp exactly, 8 -> |
// |            | 2x4, 7 -> 1x7); warning() says so when spp is not a square |
// |            | (Kensler's alternative, a larger grid with empty cells, is |
// |            | not used: every cell holds exactly one point)              |
// | use it     | the best of the grid family; fast (target >= 20 M points/s)|
#include <vector>

#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

int gridColumns(int spp) {
  int m, n;
  gridShape(spp, m, n);
  return m;
}

class CmjSampler final : public Sampler {
 public:
  CmjSampler(int spp, uint64_t seed)
      : Sampler(spp, seed), m_(gridColumns(spp)), n_(spp / m_), inv_(1.0 / spp), count_(spp), columns_(m_), rows_(n_) {}

  void generate(int px, int py, Vec2* out) const override {
    const uint32_t p = key32(pixelSeed(seed(), px, py));
    const uint32_t m = static_cast<uint32_t>(m_), n = static_cast<uint32_t>(n_);
    const uint32_t pOrder = p * 0x51633e2du, pX = p * 0xa511e9b3u, pY = p * 0x63d83595u;
    const uint32_t pJx = p * 0xa399d265u, pJy = p * 0x711ad6a5u;
    // The correlated shuffles: one permute() per column and per row, not per point.
    thread_local std::vector<uint32_t> subRows, subCols;
    subRows.resize(m), subCols.resize(n);
    for (uint32_t c = 0; c < m; ++c) subRows[c] = kenslerPermute(c, columns_, pX);  // y sub-stratum of column c
    for (uint32_t r = 0; r < n; ++r) subCols[r] = kenslerPermute(r, rows_, pY);     // x sub-stratum of row r
    for (uint32_t i = 0; i < count_.d; ++i) {
      const uint32_t s = kenslerPermute(i, count_, pOrder);
      const uint32_t row = columns_.div(s), col = s - row * m;
      out[i] = Vec2(stratumPoint(static_cast<int>(col * n + subCols[row]), kenslerRandFloat(s, pJx), spp(), inv_),
                    stratumPoint(static_cast<int>(row * m + subRows[col]), kenslerRandFloat(s, pJy), spp(), inv_));
    }
  }
  std::string name() const override { return "cmj"; }
  std::string describe() const override {
    return "cmj " + gridLabel(spp()) + " correlated multi-jittered" +
           (m_ == n_ ? "" : " (spp " + std::to_string(spp()) + " is not square)");
  }
  std::string warning() const override { return gridWarning("cmj", spp()); }

 private:
  int m_, n_;                          ///< columns, rows of gridShape(spp)
  double inv_;                         ///< 1 / spp
  Divisor count_, columns_, rows_;     ///< spp, m, n as fast divisors
};

}  // namespace

std::unique_ptr<Sampler> makeCmjSampler(int spp, uint64_t seed) {
  return std::make_unique<CmjSampler>(spp, seed);
}

}  // namespace aliaslab::sampling
