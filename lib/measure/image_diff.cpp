#include "measure/image_diff.h"

#include <algorithm>
#include <cmath>

namespace aliaslab {

ImageDifference imageDifference(const Image& a, const Image& b) {
  const size_t n = static_cast<size_t>(a.width()) * a.height() * 3;
  double sum = 0, sum2 = 0, rel = 0, maxAbs = 0;
  for (size_t i = 0; i < n; ++i) {
    const double d = double(a.data()[i]) - b.data()[i];
    sum += d, sum2 += d * d, maxAbs = std::max(maxAbs, std::abs(d));
    rel += d * d / (double(b.data()[i]) * b.data()[i] + 0.01);
  }
  ImageDifference r;
  r.mse = sum2 / n, r.relmse = rel / n, r.bias = sum / n, r.maxAbs = maxAbs;
  r.spread = std::sqrt(std::max(0.0, r.mse - r.bias * r.bias));
  r.psnr = r.mse > 0 ? 10 * std::log10(1 / r.mse) : INFINITY;
  return r;
}

Image differenceImage(const Image& a, const Image& b) {
  Image d(a.width(), a.height());
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) d.set(x, y, a.get(x, y) - b.get(x, y));
  return d;
}

}  // namespace aliaslab
