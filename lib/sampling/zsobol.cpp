// zsobol: one Owen-scrambled Sobol' sequence shared by the whole image,
// indexed by the pixel's Morton code (after Ahmed and Wonka 2020).
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | index      | pixel (px, py): the low 16 bits of each, interleaved into  |
// |            | a 32-bit Morton code z (x bits even, y bits odd); sample i |
// |            | of the pixel: the 64-bit index (z << L) | i, L = log2 of   |
// |            | the next power of two >= spp                               |
// | shuffle    | the index is read as base-4 digits (the lowest one base 2  |
// |            | when L is odd); every digit is replaced by its image under |
// |            | one of the 24 permutations of {0,1,2,3} (the base-2 digit: |
// |            | flipped or not), chosen by hash(seed, digit position,      |
// |            | all digits above it). This maps every aligned block of     |
// |            | 4^j indices onto an aligned block of 4^j indices           |
// | points     | the low 32 bits of the shuffled index s: x = van der       |
// |            | Corput(s), y = second Sobol' dimension of s, both Owen-    |
// |            | scrambled with ONE seed-derived scramble for the image     |
// |            | (a per-pixel scramble would break the shared sequence)     |
// | structure  | at spp = 2^k a pixel's points are an aligned block of 2^k  |
// |            | Sobol' points: a (0,k,2)-net. An aligned 2^j x 2^j block   |
// |            | of pixels is an aligned block of 4^j 2^k points, so the    |
// |            | sub-pixel offsets of all its samples overlaid form a       |
// |            | (0,2j+k,2)-net: neighbours fill each other's gaps and the  |
// |            | error moves to high screen frequencies                     |
// | counts     | any spp: a pixel takes the samples i = 0 .. spp-1 of its   |
// |            | block of 2^L (a subset chosen by the digit shuffle: whole  |
// |            | aligned sub-blocks first); warning() says the net          |
// |            | properties hold only at powers of two                      |
// | period     | pixels 65536 apart in x or y share the Morton code         |
// | cost       | one hash per base-4 digit: the pixel's 16 once per pixel,  |
// |            | the sample's L/2 per point; about 1/6 of sobol's speed     |
// |            | (results/spectrum_ordering.md), negligible beside tracing  |
// | use it     | pbrt-v4's default: per-pixel quality of sobol plus blue-   |
// |            | noise-like error across pixels; correlatedAcrossPixels().  |
#include <array>
#include <bit>
#include <vector>

#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

/// sobolDim1 is linear over GF(2) in the bits of i: kDim1Bytes[b][v] = sobolDim1(v << 8b), XORed byte by byte.
constexpr std::array<std::array<uint32_t, 256>, 4> kDim1Bytes = [] {
  std::array<std::array<uint32_t, 256>, 4> t{};
  for (int b = 0; b < 4; ++b)
    for (uint32_t v = 0; v < 256; ++v) t[b][v] = sobolDim1(v << (8 * b));
  return t;
}();

inline uint32_t sobolDim1Fast(uint32_t i) {
  return kDim1Bytes[0][i & 0xff] ^ kDim1Bytes[1][(i >> 8) & 0xff] ^ kDim1Bytes[2][(i >> 16) & 0xff] ^
         kDim1Bytes[3][i >> 24];
}

/// Spreads the low 16 bits of v to the even bit positions.
constexpr uint32_t spreadBits(uint32_t v) {
  v &= 0xffffu;
  v = (v | (v << 8)) & 0x00ff00ffu;
  v = (v | (v << 4)) & 0x0f0f0f0fu;
  v = (v | (v << 2)) & 0x33333333u;
  v = (v | (v << 1)) & 0x55555555u;
  return v;
}

/// The 24 permutations of {0, 1, 2, 3}, two bits per entry (entry d at bits 2d .. 2d+1).
constexpr std::array<uint8_t, 24> kPermutations = [] {
  std::array<uint8_t, 24> p{};
  int n = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 4; ++c)
        for (int d = 0; d < 4; ++d)
          if (a != b && a != c && a != d && b != c && b != d && c != d)
            p[n++] = static_cast<uint8_t>(a | b << 2 | c << 4 | d << 6);
  return p;
}();

class ZSobolSampler final : public Sampler {
 public:
  ZSobolSampler(int spp, uint64_t seed)
      : Sampler(spp, seed),
        log2N_(std::bit_width(static_cast<uint32_t>(spp - 1))),
        digitKey_(hashWords(seed, 0x7a736f626cULL)),
        scrambleX_(key32(hashWords(seed, 0x7a73ULL, 0))),
        scrambleY_(key32(hashWords(seed, 0x7a73ULL, 1))) {}

  void generate(int px, int py, Vec2* out) const override {
    const uint64_t z = spreadBits(static_cast<uint32_t>(px)) | spreadBits(static_cast<uint32_t>(py)) << 1;
    // The pixel's digits (above the sample digits) do not depend on the sample: shuffle them once.
    const uint64_t pixelPart = shuffleDigits(z << log2N_, log2N_, 32 + log2N_);
    for (int i = 0; i < spp(); ++i) {
      const uint64_t index = (z << log2N_) | static_cast<uint64_t>(i);
      const uint32_t s = static_cast<uint32_t>(pixelPart | shuffleDigits(index, 0, log2N_));
      const uint32_t x = reverseBits(laineKarrasPermute(s, scrambleX_));  // van der Corput of s, scrambled
      const uint32_t y = reverseBits(laineKarrasPermute(reverseBits(sobolDim1Fast(s)), scrambleY_));
      out[i] = Vec2(fixedToUnit(x), fixedToUnit(y));
    }
  }
  std::string name() const override { return "zsobol"; }
  std::string describe() const override {
    return "zsobol Morton-indexed Owen-scrambled Sobol', " + std::to_string(spp()) + " of 2^" +
           std::to_string(log2N_) + " points per pixel";
  }
  std::string warning() const override {
    if ((spp() & (spp() - 1)) == 0) return {};
    return "zsobol: spp " + std::to_string(spp()) + " is not a power of two; each pixel takes " +
           std::to_string(spp()) + " of its block of " + std::to_string(1 << log2N_) +
           " points, the (0,2)-net properties hold only at powers of two";
  }
  bool correlatedAcrossPixels() const override { return true; }

 private:
  /// The shuffled digits of `index` at bit positions [from, to) (others zero). Digits are base 4 from
  /// bit position log2N_ & 1 up; when log2N_ is odd, bit 0 is a base-2 digit.
  uint64_t shuffleDigits(uint64_t index, int from, int to) const {
    uint64_t out = 0;
    int shift = from;
    if (shift == 0 && (log2N_ & 1) && to > 0) {
      const uint64_t flip = hashWords(digitKey_, 0, index >> 1) & 1;
      out |= (index & 1) ^ flip;
      shift = 1;
    }
    for (; shift < to; shift += 2) {
      const uint64_t digit = (index >> shift) & 3;
      const uint64_t above = index >> (shift + 2);
      const uint8_t perm = kPermutations[hashWords(digitKey_, static_cast<uint64_t>(shift) + 1, above) % 24];
      out |= static_cast<uint64_t>((perm >> (2 * digit)) & 3) << shift;
    }
    return out;
  }

  int log2N_;          ///< L: bits of the sample index inside a pixel
  uint64_t digitKey_;  ///< key of the digit permutations
  uint32_t scrambleX_, scrambleY_;  ///< the image's Owen scrambles
};

}  // namespace

std::unique_ptr<Sampler> makeZSobolSampler(int spp, uint64_t seed) {
  return std::make_unique<ZSobolSampler>(spp, seed);
}

}  // namespace aliaslab::sampling
