// Sample buffers for the film's tests: hashed positions in each pixel (or filter-importance offsets), a constant
// and a noisy radiance field, and the largest channel difference of two images.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "core/hash.h"
#include "film/film.h"
#include "filter/filter_sampler.h"

namespace aliaslab::testing {

/// Random positions inside each pixel (or filter-importance offsets around
/// its centre when `importance` is given) with radiance field(x, y, hash).
template <class Field>
SampleBuffer makeSamples(int w, int h, int spp, uint64_t seed, Field&& field, const Filter* importance = nullptr) {
  SampleBuffer b(w, h, spp);
  const std::unique_ptr<FilterSampler> table = importance ? std::make_unique<FilterSampler>(*importance) : nullptr;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int k = 0; k < spp; ++k) {
        FilmSample& s = b.pixel(i, j)[k];
        const Vec2 u(toUnitFloat(hashWords(seed, i, j, k, 0)), toUnitFloat(hashWords(seed, i, j, k, 1)));
        if (importance) {
          const Vec2 o = table->sample(u, s.weight);
          s.x = i + 0.5f + o.x(), s.y = j + 0.5f + o.y();
        } else {
          s.x = i + u.x(), s.y = j + u.y();
        }
        s.L = field(s.x, s.y, hashWords(seed, i, j, k, 2));
      }
  return b;
}

inline const Color kConst(0.3f, 0.6f, 0.9f);
inline Color constant(float, float, uint64_t) { return kConst; }
inline Color noisy(float x, float y, uint64_t h) {
  return Color(toUnitFloat(h), 0.5f + 0.1f * std::sin(x), toUnitFloat(mix64(h)) * y);
}

inline double maxDiff(const Image& a, const Image& b) {
  double m = 0;
  for (int j = 0; j < a.height(); ++j)
    for (int i = 0; i < a.width(); ++i) m = std::max(m, double((a.get(i, j) - b.get(i, j)).abs().maxCoeff()));
  return m;
}

}  // namespace aliaslab::testing
