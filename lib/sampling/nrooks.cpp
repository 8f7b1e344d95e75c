// nrooks: Latin hypercube sampling ("n-rooks", Shirley 1991).
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | x_i = (P_x(i) + u_i) / spp, y_i = (P_y(i) + v_i) / spp:     |
// |            | exactly one point in each of the spp columns and rows of   |
// |            | width 1/spp, no 2-D stratification                         |
// | randomness | P_x, P_y: Kensler's hashed permute() of [0, spp) with two   |
// |            | 32-bit patterns from hash(pixelSeed); (u_i, v_i) from       |
// |            | hash(pixelSeed, i)                                         |
// | counts     | any spp >= 1, no warning                                   |
// | bound      | Var <= sigma^2 / (spp - 1) (Owen 1997, Latin hypercube):   |
// |            | varianceBound spp / (spp - 1), 1 at spp = 1                |
// | use it     | when 1-D projections matter most (thin horizontal or       |
// |            | vertical features); 2-D clumping makes it worse than       |
// |            | jittered on generic edges.                                 |
#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

class NRooksSampler final : public Sampler {
 public:
  using Sampler::Sampler;

  void generate(int px, int py, Vec2* out) const override {
    const uint64_t key = pixelSeed(seed(), px, py);
    const uint32_t permX = key32(hashWords(key, 0x6e726f6f6b7378ULL));
    const uint32_t permY = key32(hashWords(key, 0x6e726f6f6b7379ULL));
    const uint32_t n = static_cast<uint32_t>(spp());
    for (uint32_t i = 0; i < n; ++i) {
      const uint64_t h = hashWords(key, static_cast<uint64_t>(i));
      out[i] = Vec2(stratumPoint(kenslerPermute(i, n, permX), fixedToUnit(static_cast<uint32_t>(h >> 32)), spp()),
                    stratumPoint(kenslerPermute(i, n, permY), fixedToUnit(static_cast<uint32_t>(h)), spp()));
    }
  }
  std::string name() const override { return "nrooks"; }
  double varianceBound() const override { return spp() > 1 ? double(spp()) / (spp() - 1) : 1.0; }
  std::string describe() const override {
    return "nrooks: Latin hypercube, " + std::to_string(spp()) + " rows and columns";
  }
};

}  // namespace

std::unique_ptr<Sampler> makeNRooksSampler(int spp, uint64_t seed) {
  return std::make_unique<NRooksSampler>(spp, seed);
}

}  // namespace aliaslab::sampling
