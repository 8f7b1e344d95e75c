// The film benches' sample buffer: size x size pixels of spp samples, placed in pixel (i, j) by
// place(i, j, u) (u: spp points in [0,1)^2, relative to the pixel's corner), with hashed radiance.
#pragma once
#include <vector>

#include "core/hash.h"
#include "film/film.h"

namespace aliaslab {

template <class Place>
SampleBuffer benchSamples(int size, int spp, Place&& place) {
  SampleBuffer s(size, size, spp);
  std::vector<Vec2> u(spp);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      place(i, j, u.data());
      for (int k = 0; k < spp; ++k) {
        FilmSample& f = s.pixel(i, j)[k];
        f.x = i + u[k].x(), f.y = j + u[k].y();
        f.L = Color(toUnitFloat(hashWords(1, i, j, k, 2)), toUnitFloat(hashWords(1, i, j, k, 3)), 0.5f);
      }
    }
  return s;
}

}  // namespace aliaslab
