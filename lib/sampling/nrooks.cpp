// nrooks: Latin hypercube sampling ("n-rooks", Shirley 1991).
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | x_i = (i + u_i) / spp, y_i = (P(i) + v_i) / spp:            |
// |            | exactly one point in each of the spp columns and rows of   |
// |            | width 1/spp, no 2-D stratification                         |
// | randomness | x_i in column i, y_i in row P(i), P a uniformly random     |
// |            | permutation (Fisher-Yates, draws from HashRng(pixelSeed)); |
// |            | (u_i, v_i) from hash(pixelSeed, i). Not Kensler's hashed   |
// |            | permute(): at powers of two its low bits follow the index, |
// |            | so the x and y strata's parities were coupled (at spp 4    |
// |            | the checkerboard of 1/4-cells gave Var = sigma^2, 4x the   |
// |            | bound; tests/contract/sampler_bound_test.cpp)              |
// | counts     | any spp >= 1, no warning                                   |
// | bound      | Var <= sigma^2 / (spp - 1) (Owen 1997, Latin hypercube):   |
// |            | varianceBound spp / (spp - 1), 1 at spp = 1                |
// | use it     | when 1-D projections matter most (thin horizontal or       |
// |            | vertical features); 2-D clumping makes it worse than       |
// |            | jittered on generic edges.                                 |
#include <utility>

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
    const int n = spp();
    const double inv = 1.0 / n;
    for (int i = 0; i < n; ++i) {
      const uint64_t h = hashWords(key, static_cast<uint64_t>(i));
      out[i] = Vec2(stratumPoint(i, fixedToUnit(static_cast<uint32_t>(h >> 32)), n, inv),
                    stratumPoint(i, fixedToUnit(static_cast<uint32_t>(h)), n, inv));
    }
    // the rows paired with the columns by a uniformly random permutation: swap the y's (Fisher-Yates)
    HashRng rng(hashWords(key, 0x6e726f6f6b7379ULL));
    for (int i = n - 1; i > 0; --i) std::swap(out[i].y(), out[rng.nextBelow(static_cast<uint32_t>(i + 1))].y());
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
