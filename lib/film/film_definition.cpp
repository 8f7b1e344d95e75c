// The film's definition (film_definition.h): plain loops, no footprints, bands or kernels.
#include "film/film_definition.h"

#include <algorithm>
#include <cmath>

namespace aliaslab {
namespace {

bool finite(const FilmSample& s) { return std::isfinite(s.x) && std::isfinite(s.y) && s.L.allFinite(); }

/// The plain mean of pixel (i, j)'s own finite samples, 0 if it has none (or if the mean overflows float).
Color ownMean(const SampleBuffer& samples, int i, int j) {
  Eigen::Array3d sum = Eigen::Array3d::Zero();
  int n = 0;
  for (int k = 0; k < samples.count(i, j); ++k) {
    const FilmSample& s = samples.pixel(i, j)[k];
    if (finite(s)) sum += s.L.cast<double>(), ++n;
  }
  const Color mean = n > 0 ? Color((sum / n).cast<float>()) : Color::Zero();
  return mean.allFinite() ? mean : Color::Zero();
}

}  // namespace

Reconstruction reconstructDefinition(const SampleBuffer& samples, const Filter& filter) {
  Reconstruction out{Image(samples.width(), samples.height()), {}};
  for (const FilmSample& s : samples.samples()) out.stats.nonFiniteSamples += !finite(s);
  const double tolerance = std::max(1e-8 * std::abs(double(filter.eval(0, 0))), 1e-30);
  for (int j = 0; j < samples.height(); ++j)
    for (int i = 0; i < samples.width(); ++i) {
      Eigen::Array3d num = Eigen::Array3d::Zero();
      double den = 0;
      for (const FilmSample& s : samples.samples()) {
        if (!finite(s)) continue;
        const double area = samples.areaWeighted() ? double(s.weight) : 1.0;
        const double w = double(filter.eval(s.x - (i + 0.5f), s.y - (j + 0.5f))) * area;
        num += w * s.L.cast<double>(), den += w;
      }
      Color c = Color::Zero();
      bool fallback = std::abs(den) < tolerance;
      if (fallback) {
        ++out.stats.undefinedPixels;
      } else {
        c = (num / den).cast<float>();
        if (!c.allFinite()) ++out.stats.nanPixels, fallback = true;
      }
      if (fallback) c = ownMean(samples, i, j);
      if ((c < 0).any()) ++out.stats.negativePixels;
      out.image.set(i, j, c);
    }
  return out;
}

}  // namespace aliaslab
