// halton: the Halton sequence in bases 2 and 3 with random digit permutations.
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | indices i = 0 .. spp-1 in every pixel: x = radical inverse |
// |            | of i in base 2, y = radical inverse of i in base 3, each   |
// |            | digit d replaced by pi_d(digit) (also the infinitely many  |
// |            | leading-zero digits, so no point sits on a 2^-k / 3^-k grid)|
// | randomness | base 2: pi_d = XOR with a random bit (32 digits, one mask  |
// |            | word); base 3: pi_d one of the 6 permutations of {0,1,2}   |
// |            | per digit d (20 digits); all from hash(pixelSeed, tag)     |
// | structure  | for spp = 2^a 3^b every box of size 2^-a x 3^-b holds      |
// |            | exactly one point; in any prefix each 2^-j (3^-j) interval |
// |            | of x (y) holds floor or ceil of spp / 2^j (spp / 3^j)      |
// | counts     | any spp >= 1, no warning                                   |
// | progressive| yes: point i does not depend on spp                        |
// | use it     | a low-discrepancy pattern that is good at any count, not  |
// |            | only powers of two.                                        |
#include <array>
#include <cstdint>

#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

constexpr int kDigits3 = 20;     ///< base-3 digits used: 3^20 > 2^31 >= any index
constexpr int kExactDigits3 = 13;  ///< leading digits placed exactly in float (3^13 strata)

constexpr uint64_t pow3(int e) { return e == 0 ? 1 : 3 * pow3(e - 1); }
constexpr uint8_t kPerm3[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

class HaltonSampler final : public Sampler {
 public:
  using Sampler::Sampler;

  void generate(int px, int py, Vec2* out) const override { generatePrefix(px, py, spp(), out); }
  void generatePrefix(int px, int py, int count, Vec2* out) const override {
    const uint64_t key = pixelSeed(seed(), px, py);
    const uint32_t mask2 = key32(hashWords(key, 0x68616c32ULL));
    HashRng rng(hashWords(key, 0x68616c33ULL));
    std::array<uint8_t, kDigits3> perm;
    for (uint8_t& p : perm) p = static_cast<uint8_t>(rng.nextBelow(6));
    // Contribution of the permuted leading zeros from digit d on (digits beyond i's length).
    std::array<uint64_t, kDigits3 + 1> zeroTail{};
    for (int d = kDigits3 - 1; d >= 0; --d) zeroTail[d] = zeroTail[d + 1] + kPerm3[perm[d]][0] * pow3(kDigits3 - 1 - d);
    constexpr uint64_t kLow = pow3(kDigits3 - kExactDigits3);
    for (int i = 0; i < count; ++i) {
      // Base 3: digit d of i (least significant first) becomes digit d of y after the point.
      uint64_t v = 0, weight = pow3(kDigits3 - 1);
      uint32_t rest = static_cast<uint32_t>(i);
      int d = 0;
      for (; rest; ++d, weight /= 3, rest /= 3) v += kPerm3[perm[d]][rest % 3] * weight;
      v += zeroTail[d];
      // Place the leading digits exactly (stratum of 3^-13), the rest as jitter.
      const float y = stratumPoint(static_cast<int>(v / kLow), static_cast<float>(v % kLow) / kLow,
                                   static_cast<int>(pow3(kExactDigits3)));
      out[i] = Vec2(fixedToUnit(reverseBits(static_cast<uint32_t>(i)) ^ mask2), y);
    }
  }
  std::string name() const override { return "halton"; }
  bool progressive() const override { return true; }
  std::string describe() const override {
    return "halton bases 2,3, random digit permutations, indices 0.." + std::to_string(spp() - 1);
  }
};

}  // namespace

std::unique_ptr<Sampler> makeHaltonSampler(int spp, uint64_t seed) {
  return std::make_unique<HaltonSampler>(spp, seed);
}

}  // namespace aliaslab::sampling
