// Counter-based random numbers: every random choice in aliaslab is a pure
// function of (seed, pixel, sample index, dimension), never of a shared
// generator or the clock, so results do not depend on thread count or order.
#pragma once
#include <cstdint>

namespace aliaslab {

/// 64-bit finaliser (SplitMix64 / Stafford variant 13): a bijection with good avalanche.
constexpr uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// Hash of any number of 64-bit words.
constexpr uint64_t hashWords(uint64_t a) { return mix64(a + 0x9e3779b97f4a7c15ULL); }
template <class... Rest>
constexpr uint64_t hashWords(uint64_t a, Rest... rest) {
  return mix64(hashWords(a) ^ (hashWords(static_cast<uint64_t>(rest)...) + 0x632be59bd9b4e019ULL));
}

/// Seed of one pixel's stream.
constexpr uint64_t pixelSeed(uint64_t seed, int px, int py) {
  return hashWords(seed, static_cast<uint64_t>(static_cast<uint32_t>(px)),
                   static_cast<uint64_t>(static_cast<uint32_t>(py)));
}

/// Uniform float in [0, 1) from the top 24 bits of a hash.
constexpr float toUnitFloat(uint64_t h) { return static_cast<float>(h >> 40) * 0x1p-24f; }
/// Uniform double in [0, 1) from the top 53 bits.
constexpr double toUnitDouble(uint64_t h) { return static_cast<double>(h >> 11) * 0x1p-53; }

/// A tiny stateful stream over a hashed counter, for code that draws many
/// numbers in sequence from one (seed, pixel, ...) key.
class HashRng {
 public:
  explicit constexpr HashRng(uint64_t key) : key_(key) {}
  constexpr uint64_t nextU64() { return hashWords(key_, counter_++); }
  constexpr uint32_t nextU32() { return static_cast<uint32_t>(nextU64() >> 32); }
  constexpr float nextFloat() { return toUnitFloat(nextU64()); }
  constexpr double nextDouble() { return toUnitDouble(nextU64()); }
  /// Uniform integer in [0, n), n > 0 (Lemire's multiply, bias < 2^-32).
  constexpr uint32_t nextBelow(uint32_t n) {
    return static_cast<uint32_t>((static_cast<uint64_t>(nextU32()) * n) >> 32);
  }

 private:
  uint64_t key_;
  uint64_t counter_ = 0;
};

}  // namespace aliaslab
