// hammersley: the Hammersley set (i/N, base-2 radical inverse) randomised per pixel.
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | for i = 0 .. N-1 (N = spp): x = (i + u) / N, y = radical   |
// |            | inverse of i in base 2 with every digit XORed with a bit   |
// |            | of a per-pixel mask (random digit permutation in base 2)   |
// | convention | x = (i + u)/N with one offset u in [0,1) per pixel: the    |
// |            | deterministic i/N shifted inside its 1/N column. At N = 2^k |
// |            | this equals permuting every binary digit of i/N (including |
// |            | its trailing zeros): XOR of the first k digits of x only   |
// |            | relabels the points, which the y mask already covers       |
// | randomness | u, the y mask and the output order (Kensler permute() of   |
// |            | the indices, so point k is not tied to column k) from      |
// |            | hash(pixelSeed, tag)                                       |
// | structure  | one point in each 1/N column of x for every N; each 2^-j   |
// |            | interval of y holds floor or ceil of N/2^j points; at      |
// |            | N = 2^k a (0,k,2)-net in base 2 (every elementary interval |
// |            | of area 1/N holds one point)                               |
// | counts     | any spp >= 1, no warning                                   |
// | use it     | a fixed-count low-discrepancy set (not progressive).       |
#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

class HammersleySampler final : public Sampler {
 public:
  using Sampler::Sampler;

  void generate(int px, int py, Vec2* out) const override {
    const uint64_t key = pixelSeed(seed(), px, py);
    const uint64_t h = hashWords(key, 0x68616d6dULL);
    const float u = fixedToUnit(static_cast<uint32_t>(h));
    const uint32_t maskY = key32(h);
    const uint32_t order = key32(hashWords(key, 0x6f726465ULL));
    const uint32_t n = static_cast<uint32_t>(spp());
    for (uint32_t k = 0; k < n; ++k) {
      const uint32_t i = kenslerPermute(k, n, order);
      out[k] = Vec2(stratumPoint(static_cast<int>(i), u, spp()), fixedToUnit(reverseBits(i) ^ maskY));
    }
  }
  std::string name() const override { return "hammersley"; }
  std::string describe() const override {
    return "hammersley N=" + std::to_string(spp()) + ", x=(i+u)/N, y=digit-scrambled base-2 radical inverse";
  }
};

}  // namespace

std::unique_ptr<Sampler> makeHammersleySampler(int spp, uint64_t seed) {
  return std::make_unique<HammersleySampler>(spp, seed);
}

}  // namespace aliaslab::sampling
