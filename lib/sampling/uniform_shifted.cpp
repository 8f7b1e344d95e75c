// uniform-shifted: the regular grid of uniform, shifted as a whole by one
// random offset per seed: a Cranley-Patterson rotation of the pixel's lattice
// (a randomised lattice).
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | ((c + u) / m, (r + v) / n) for every cell (c, r) of the    |
// |            | m x n grid of gridShape(spp), row by row                   |
// | randomness | (u, v) in [0,1)^2 = the two halves of hash(seed): one      |
// |            | offset (u / m, v / n) of the whole image's grid per seed,  |
// |            | the same in every pixel (correlatedAcrossPixels)           |
// | counts     | any spp, as uniform (8 -> 2x4, 7 -> 1x7); warning() says   |
// |            | so when spp is not a square                                |
// | what it is | an estimator of its own: the points move, the pixels and   |
// |            | their filters stay put. Unbiased for each pixel's integral |
// |            | over seeds, but without the centred grid's symmetry (the   |
// |            | midpoint rule's), so on content smooth within a pixel its  |
// |            | variance falls only as 1/N, like random sampling. It is    |
// |            | NOT the fixed grid's expectation over alignments: that     |
// |            | moves the scene against points and pixels together, and   |
// |            | the sweep measures it with camera offsets (study/          |
// |            | alignment.h, docs/science.md "The grid and alignment").    |
// |            | Its structured error changes seed to seed, so it counts as |
// |            | noise.                                                     |
#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

class UniformShiftedSampler final : public Sampler {
 public:
  UniformShiftedSampler(int spp, uint64_t seed) : Sampler(spp, seed) {
    gridShape(spp, m_, n_);
    const uint64_t h = hashWords(seed, 0x5a1f7ULL);
    u_ = fixedToUnit(static_cast<uint32_t>(h >> 32)), v_ = fixedToUnit(static_cast<uint32_t>(h));
  }

  void generate(int, int, Vec2* out) const override {
    for (int r = 0; r < n_; ++r)
      for (int c = 0; c < m_; ++c) *out++ = Vec2(stratumPoint(c, u_, m_), stratumPoint(r, v_, n_));
  }
  std::string name() const override { return "uniform-shifted"; }
  std::string describe() const override {
    return "uniform-shifted " + gridLabel(spp()) + " grid, one offset per seed" +
           (m_ == n_ ? "" : " (spp " + std::to_string(spp()) + " is not square)");
  }
  std::string warning() const override { return gridWarning("uniform-shifted", spp()); }
  bool correlatedAcrossPixels() const override { return true; }

 private:
  int m_ = 1, n_ = 1;  ///< columns, rows
  float u_ = 0, v_ = 0;  ///< the offset in cells, in [0,1)
};

}  // namespace

std::unique_ptr<Sampler> makeUniformShiftedSampler(int spp, uint64_t seed) {
  return std::make_unique<UniformShiftedSampler>(spp, seed);
}

}  // namespace aliaslab::sampling
