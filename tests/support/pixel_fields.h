// Fields f(x, y, c) over the pixels and channels of the constructed images in the metric tests: their mean
// over every value (rows, then columns, then channels, summed in double).
#pragma once

namespace aliaslab::testing {

template <class F>
double meanOverPixels(int width, int height, F f) {
  double s = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) s += f(x, y, c);
  return s / (width * height * 3.0);
}

}  // namespace aliaslab::testing
