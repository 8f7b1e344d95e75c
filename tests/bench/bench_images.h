// The measure benches' images: a smooth pattern plus hashed noise, size x size, distinct per seed.
#pragma once
#include <cmath>
#include <cstdint>

#include "core/hash.h"
#include "core/image.h"

namespace aliaslab {

/// s = 0.5 + 0.3 sin(0.002 x^2 + 0.001 y^2) per pixel, channels (s, 0.8 s, 0.6 s), each plus noise x (u - 0.5),
/// u uniform in [0, 1) from HashRng(seed).
inline Image benchPattern(uint64_t seed, double noise, int size) {
  Image im(size, size);
  HashRng rng(seed);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double s = 0.5 + 0.3 * std::sin(0.002 * x * x + 0.001 * y * y);
      auto v = [&](double k) { return static_cast<float>(k * s + noise * (rng.nextDouble() - 0.5)); };
      im.set(x, y, Color(v(1.0), v(0.8), v(0.6)));
    }
  return im;
}

}  // namespace aliaslab
