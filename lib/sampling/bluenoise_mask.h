// Blue-noise dither masks made by void-and-cluster (Ulichney 1993), for the
// bluenoise-dither sampler wrapper.
//
// A mask is a kMaskSize x kMaskSize tile (64 x 64, tiled over the image) of
// ranks: every value 0 .. kMaskSize^2 - 1 appears exactly once, and the
// pixels holding the first n ranks form, for every n, an evenly spread
// (blue-noise) pattern on the torus, so the ranks / kMaskSize^2 vary fast
// from pixel to pixel and have little energy at low screen frequencies.
//
// Construction, for a mask key (from the seed and the channel):
//   energy  E(p) = sum over set pixels q of exp(-d(p,q)^2 / (2 sigma^2)),
//           d the toroidal distance, sigma = 1.5 pixels (Ulichney's value);
//   1. prototype: 10 % of the pixels set at random (key), then repeatedly
//      move the tightest cluster (set pixel of highest E) to the largest
//      void (empty pixel of lowest E) until the pixel moved comes straight
//      back;
//   2. ranks of the prototype's pixels: remove the tightest cluster again
//      and again, giving it rank = number of set pixels left;
//   3. ranks of the rest: from the prototype, fill the largest void again
//      and again, giving it rank = number of set pixels before it. (Ulichney
//      switches to clusters of the empty pixels after half; with a kernel
//      summed over the whole torus the two choices are the same pixel.)
// Ties go to the lowest pixel index, so a mask is a pure function of its key.
// A mask costs a few tens of milliseconds; blueNoiseMask() caches it.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

namespace aliaslab::sampling {

inline constexpr int kMaskSize = 64;  ///< a power of two

/// The void-and-cluster rank mask of `key`, row-major (index y * kMaskSize + x).
std::vector<uint16_t> makeVoidAndClusterMask(uint64_t key);

/// The mask of (seed, channel), built once per process and cached (thread-safe).
std::shared_ptr<const std::vector<uint16_t>> blueNoiseMask(uint64_t seed, int channel);

}  // namespace aliaslab::sampling
