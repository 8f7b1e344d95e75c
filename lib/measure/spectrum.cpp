#include "measure/spectrum.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "measure/spectrum_dft.h"

namespace aliaslab {

namespace {
using spectrumimpl::Complex;
using spectrumimpl::dft2;
using spectrumimpl::binOf;


}  // namespace

double blurGain(double rho, double sigma) {
  constexpr double pi = 3.14159265358979323846;
  return std::exp(-4 * pi * pi * sigma * sigma * rho * rho);
}

double frequencyRadius(int u, int v, int width, int height) {
  const double fu = (u < (width + 1) / 2 ? u : u - width) / static_cast<double>(width);
  const double fv = (v < (height + 1) / 2 ? v : v - height) / static_cast<double>(height);
  return std::hypot(fu, fv);
}

double RadialSpectrum::total() const {
  double t = 0;
  for (double e : energy) t += e;
  return t;
}

std::vector<double> powerSpectrum(const Image& image) {
  const size_t n = static_cast<size_t>(image.width()) * image.height();
  const double scale = 1.0 / (3.0 * static_cast<double>(n) * static_cast<double>(n));
  std::vector<double> p(n, 0.0);
  std::vector<Complex> e;
  for (int c = 0; c < 3; ++c) {
    dft2(image, nullptr, c, e);
    for (size_t i = 0; i < n; ++i) p[i] += std::norm(e[i]) * scale;
  }
  return p;
}

RadialSpectrum radialSpectrum(const Image& image) {
  RadialSpectrum r;
  const auto p = powerSpectrum(image);
  const int w = image.width(), h = image.height();
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      const int b = binOf(frequencyRadius(u, v, w, h));
      r.energy[b] += p[static_cast<size_t>(v) * w + u], ++r.count[b];
    }
  return r;
}

}  // namespace aliaslab
