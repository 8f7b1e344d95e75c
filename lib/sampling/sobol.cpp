// sobol: Owen-scrambled Sobol' (0,2)-sequence, first spp points per pixel.
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | indices i = 0 .. spp-1: x = van der Corput (bit reversal   |
// |            | of i), y = second Sobol' dimension (generator matrix of    |
// |            | x + 1: direction numbers v_{k+1} = v_k ^ (v_k >> 1)), both |
// |            | in 32-bit fixed point                                      |
// | scramble   | nested uniform (Owen) scrambling by the hash-based         |
// |            | Laine-Karras permutation on bit-reversed values (Burley    |
// |            | 2020, Vegdahl's constants), an independent 32-bit seed per |
// |            | pixel and per dimension from hash(pixelSeed, dimension)    |
// | order      | not shuffled: point i is index i (order does not matter to |
// |            | a pixel's set; the set is the first spp points)            |
// | structure  | at spp = 2^k every prefix of 2^j points is a (0,j,2)-net:  |
// |            | each elementary interval of area 2^-j holds one point      |
// | counts     | any spp: the first spp points; warning() says the net      |
// |            | property holds only at powers of two                       |
// | bound      | at spp = 2^m a scrambled (0,m,2)-net: Var <= 2 sigma^2/spp |
// |            | for nested uniform scrambling (Owen 1997); varianceBound 2 |
// |            | there, none at other counts. The hash approximates the     |
// |            | scramble: every study checks the bound (study/records/contract.h)  |
// | progressive| yes: point i does not depend on spp                        |
// | use it     | the default low-discrepancy choice: RMSE ~ N^-3/4 on edges |
// |            | at powers of two; fast (target >= 50 M points/s/core).     |
#include <vector>

#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

class SobolSampler final : public Sampler {
 public:
  SobolSampler(int spp, uint64_t seed) : Sampler(spp, seed), dim1Reversed_(spp) {
    // Unscrambled y in bit-reversed form, so a point costs two hashes and two reversals.
    for (int i = 0; i < spp; ++i) dim1Reversed_[i] = reverseBits(sobolDim1(static_cast<uint32_t>(i)));
  }

  void generate(int px, int py, Vec2* out) const override { generatePrefix(px, py, spp(), out); }
  void generatePrefix(int px, int py, int count, Vec2* out) const override {
    const uint64_t key = pixelSeed(seed(), px, py);
    const uint32_t seedX = key32(hashWords(key, 0)), seedY = key32(hashWords(key, 1));
    const int n = count;
    for (int i = 0; i < n; ++i) {
      // van der Corput reversed back is i itself.
      const uint32_t x = reverseBits(laineKarrasPermute(static_cast<uint32_t>(i), seedX));
      const uint32_t y = reverseBits(laineKarrasPermute(dim1Reversed_[i], seedY));
      out[i] = Vec2(fixedToUnit(x), fixedToUnit(y));
    }
  }
  std::string name() const override { return "sobol"; }
  double varianceBound() const override { return (spp() & (spp() - 1)) == 0 ? 2.0 : 0.0; }
  bool progressive() const override { return true; }
  std::string describe() const override {
    return "sobol Owen-scrambled, first " + std::to_string(spp()) + " points" +
           ((spp() & (spp() - 1)) ? " (not a power of two)" : "");
  }
  std::string warning() const override {
    if ((spp() & (spp() - 1)) == 0) return {};
    return "sobol: spp " + std::to_string(spp()) +
           " is not a power of two; using the first spp points, the (0,2)-net property holds only at powers of two";
  }

 private:
  std::vector<uint32_t> dim1Reversed_;  ///< reverseBits(second Sobol' dimension of i), i < spp
};

}  // namespace

std::unique_ptr<Sampler> makeSobolSampler(int spp, uint64_t seed) {
  return std::make_unique<SobolSampler>(spp, seed);
}

}  // namespace aliaslab::sampling
