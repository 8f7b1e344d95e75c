// random: independent uniform points (the Monte Carlo baseline).
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | spp independent uniform points in [0,1)^2                  |
// | randomness | point i of pixel p: the two 32-bit halves of               |
// |            | hash(pixelSeed(seed, p), i) give x and y (24 bits each)     |
// | counts     | any spp >= 1, no warning                                   |
// | bound      | Var = sigma^2 / spp exactly (varianceBound 1)              |
// | progressive| yes: point i does not depend on spp                        |
// | use it     | as the reference for error slopes (RMSE ~ N^-1/2); it turns |
// |            | all aliasing into noise, at the highest noise of all.      |
#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

class RandomSampler final : public Sampler {
 public:
  using Sampler::Sampler;

  void generate(int px, int py, Vec2* out) const override { generatePrefix(px, py, spp(), out); }
  void generatePrefix(int px, int py, int count, Vec2* out) const override {
    const uint64_t key = pixelSeed(seed(), px, py);
    for (int i = 0; i < count; ++i) {
      const uint64_t h = hashWords(key, static_cast<uint64_t>(i));
      out[i] = Vec2(fixedToUnit(static_cast<uint32_t>(h >> 32)), fixedToUnit(static_cast<uint32_t>(h)));
    }
  }
  std::string name() const override { return "random"; }
  double varianceBound() const override { return 1; }
  bool progressive() const override { return true; }
  std::string describe() const override { return "random: " + std::to_string(spp()) + " independent uniform points"; }
};

}  // namespace

std::unique_ptr<Sampler> makeRandomSampler(int spp, uint64_t seed) {
  return std::make_unique<RandomSampler>(spp, seed);
}

}  // namespace aliaslab::sampling
