// Integer building blocks shared by the samplers: conversion of 32-bit
// fixed-point coordinates to floats in [0,1), Kensler's hashed permutation
// and float (Correlated Multi-Jittered Sampling, 2013), bit reversal, the
// second Sobol' dimension (sobol, zsobol), and the hash behind the Owen
// scramble (Laine-Karras 2011, Burley 2020, with Vegdahl's improved
// constants). Internal to lib/sampling.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace aliaslab::sampling {

/// The largest float below 1 (0x1.fffffep-1): every coordinate is clamped to it.
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

/// min(v, largest float below 1); for coordinates computed in float.
inline float clampUnit(float v) { return std::min(v, kOneMinusEpsilon); }

/// A float in the real interval [k / count, (k + 1) / count) at fraction u
/// of stratum k (u in [0,1)), so floor(x * count) == k holds exactly even
/// where k / count is not a float; never 1. invCount = 1.0 / count (passed
/// in so the hot loops multiply instead of divide).
inline float stratumPoint(int k, float u, int count, double invCount) {
  float x = static_cast<float>((k + static_cast<double>(u)) * invCount);
  if (static_cast<double>(x) * count < k) x = std::nextafter(x, 1.f);
  else if (static_cast<double>(x) * count >= k + 1) x = std::nextafter(x, 0.f);
  return clampUnit(x);
}
inline float stratumPoint(int k, float u, int count) { return stratumPoint(k, u, count, 1.0 / count); }

/// 32-bit fixed point (v / 2^32) to float in [0,1): keeps the top 24 bits, so
/// the result is exact and never rounds up to 1.
constexpr float fixedToUnit(uint32_t v) { return static_cast<float>(v >> 8) * 0x1p-24f; }

/// The 32-bit key of a 64-bit hash (upper half).
constexpr uint32_t key32(uint64_t h) { return static_cast<uint32_t>(h >> 32); }

/// Bit mask covering [0, n): the smallest 2^k - 1 >= n - 1.
constexpr uint32_t permuteMask(uint32_t n) {
  uint32_t w = n - 1;
  w |= w >> 1; w |= w >> 2; w |= w >> 4; w |= w >> 8; w |= w >> 16;
  return w;
}

/// The cycle-walking hash of Kensler's permute(): a bijection of [0, n)
/// (w = permuteMask(n)), before the final rotation by p.
constexpr uint32_t kenslerWalk(uint32_t i, uint32_t n, uint32_t w, uint32_t p) {
  do {
    i ^= p; i *= 0xe170893d;
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8; i *= 0x0929eb3f;
    i ^= p >> 23;
    i ^= (i & w) >> 1; i *= 1 | p >> 27;
    i *= 0x6935fa69;
    i ^= (i & w) >> 11; i *= 0x74dcb303;
    i ^= (i & w) >> 2; i *= 0x9e501cc3;
    i ^= (i & w) >> 2; i *= 0xc860a3df;
    i &= w;
    i ^= i >> 5;
  } while (i >= n);
  return i;
}

/// Kensler's permute(): element i of a pseudo-random permutation of [0, n)
/// chosen by pattern p (a bijection for any n >= 1).
constexpr uint32_t kenslerPermute(uint32_t i, uint32_t n, uint32_t p) {
  return (kenslerWalk(i, n, permuteMask(n), p) + p) % n;
}

/// A fixed divisor d >= 1 with division and remainder of 32-bit values by
/// multiplication (Lemire, Kaser and Kurz 2019), for the hot loops.
struct Divisor {
  explicit Divisor(uint32_t divisor)
      : d(divisor), mask(permuteMask(divisor)), magic(divisor == 1 ? 0 : ~uint64_t{0} / divisor + 1) {}
  uint32_t div(uint32_t a) const {
    return d == 1 ? a : static_cast<uint32_t>((static_cast<unsigned __int128>(magic) * a) >> 64);
  }
  uint32_t mod(uint32_t a) const {
    return d == 1 ? 0 : static_cast<uint32_t>((static_cast<unsigned __int128>(magic * a) * d) >> 64);
  }
  uint32_t d, mask;
  uint64_t magic;
};

/// kenslerPermute() with a precomputed divisor: the same values, faster.
inline uint32_t kenslerPermute(uint32_t i, const Divisor& n, uint32_t p) {
  return n.mod(kenslerWalk(i, n.d, n.mask, p) + p);
}

/// Kensler's randfloat(): a hashed float in [0,1) for index i of pattern p.
constexpr float kenslerRandFloat(uint32_t i, uint32_t p) {
  i ^= p;
  i ^= i >> 17; i ^= i >> 10; i *= 0xb36534e5;
  i ^= i >> 12; i ^= i >> 21; i *= 0x93fc4795;
  i ^= 0xdf6e307f; i ^= i >> 17; i *= 1 | p >> 18;
  return fixedToUnit(i);
}

/// Reverses the 32 bits of v.
constexpr uint32_t reverseBits(uint32_t v) {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
  v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
  return (v >> 16) | (v << 16);
}

/// Second Sobol' dimension of index i as 32-bit fixed point.
constexpr uint32_t sobolDim1(uint32_t i) {
  uint32_t r = 0;
  for (uint32_t v = 1u << 31; i; i >>= 1, v ^= v >> 1)
    if (i & 1) r ^= v;
  return r;
}

/// Laine-Karras style hash in which output bit k depends only on input bits
/// 0..k: applied to bit-reversed values it is a nested uniform (Owen) scramble.
constexpr uint32_t laineKarrasPermute(uint32_t x, uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

}  // namespace aliaslab::sampling
