// uniform: a regular grid, each point at its cell centre.
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | centres ((c + 1/2) / m, (r + 1/2) / n) of the m x n grid    |
// |            | of gridShape(spp), row by row                              |
// | randomness | none: identical in every pixel and for every seed (that is |
// |            | the point: its error is all aliasing, none of it noise)    |
// | counts     | any spp: the gridShape m x n grid (m n = spp, 8 -> 2x4,    |
// |            | 7 -> 1x7); warning() says so when spp is not a square      |
// | use it     | to show aliasing (moire, jaggies) and for supersampling;   |
// |            | never as a default.                                        |
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

class UniformSampler final : public Sampler {
 public:
  UniformSampler(int spp, uint64_t seed) : Sampler(spp, seed) { gridShape(spp, m_, n_); }

  void generate(int px, int py, Vec2* out) const override {
    for (int r = 0; r < n_; ++r)
      for (int c = 0; c < m_; ++c)
        *out++ = Vec2(clampUnit((c + 0.5f) / m_), clampUnit((r + 0.5f) / n_));
  }
  std::string name() const override { return "uniform"; }
  std::string describe() const override {
    return "uniform " + gridLabel(spp()) + " cell centres" + (m_ == n_ ? "" : " (spp " + std::to_string(spp()) + " is not square)");
  }
  std::string warning() const override { return gridWarning("uniform", spp()); }

 private:
  int m_ = 1, n_ = 1;  ///< columns, rows
};

}  // namespace

std::unique_ptr<Sampler> makeUniformSampler(int spp, uint64_t seed) {
  return std::make_unique<UniformSampler>(spp, seed);
}

}  // namespace aliaslab::sampling
