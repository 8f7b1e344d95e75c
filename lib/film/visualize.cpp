// Pictures of samples, filters and error maps.
#include "film/visualize.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace aliaslab {
namespace {

const Color kDarkBlue(0.f, 0.f, 0.5f), kBlue(0.f, 0.f, 1.f);
const Color kGhost(0.75f, 0.55f, 0.15f);  ///< renderSamples: a block neighbour's sample offset (amber)

float channelMean(const Color& c) { return (c[0] + c[1] + c[2]) / 3.f; }

/// White at 0, red towards +1, blue towards -1.
Color diverging(float t) {
  t = std::clamp(std::isfinite(t) ? t : 0.f, -1.f, 1.f);
  const float a = 1.f - std::abs(t);
  return t >= 0 ? Color(1.f, a, a) : Color(a, a, 1.f);
}

}  // namespace

Image renderSamples(const SampleBuffer& samples, int zoom) {
  const int w = samples.width() * zoom, h = samples.height() * zoom;
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if ((x / zoom + y / zoom) % 2 == 0) img.set(x, y, Color::Constant(0.2f));
  // Neighbours' offsets: in each pixel, the sub-pixel offsets of the other pixels of its aligned 2x2
  // block as ghosts, so a correlated sampler's gap filling (or an independent one's clumps) shows.
  if (zoom >= 4) {
    for (int j = 0; j < samples.height(); ++j)
      for (int i = 0; i < samples.width(); ++i)
        for (const auto& [ni, nj] : {std::pair{i ^ 1, j}, std::pair{i, j ^ 1}, std::pair{i ^ 1, j ^ 1}}) {
          if (ni >= samples.width() || nj >= samples.height()) continue;
          const FilmSample* n = samples.pixel(ni, nj);
          for (int k = 0; k < samples.spp(); ++k) {
            const float ox = n[k].x - ni, oy = n[k].y - nj;  // offset inside its own pixel
            if (!(ox >= 0 && ox < 1 && oy >= 0 && oy < 1)) continue;
            const int x = std::min(int(std::floor((i + ox) * zoom)), (i + 1) * zoom - 1);
            const int y = std::min(int(std::floor((j + oy) * zoom)), (j + 1) * zoom - 1);
            img.set(x, y, kGhost);
          }
        }
  }
  for (const FilmSample& s : samples.samples()) {
    const float fx = std::floor(s.x * zoom), fy = std::floor(s.y * zoom);
    if (fx >= 0 && fy >= 0 && fx < w && fy < h) img.set(int(fx), int(fy), s.L);
  }
  return img;
}

Image renderFilter(const Filter& filter, int width, int height, int zoom) {
  Image img(width * zoom + 1, height * zoom + 1, kDarkBlue);
  const int R = classicSupport(filter), ci = width / 2, cj = height / 2;
  const float cx = ci + 0.5f, cy = cj + 0.5f;
  for (int j = std::max(0, cj - R); j <= std::min(height - 1, cj + R); ++j)
    for (int i = std::max(0, ci - R); i <= std::min(width - 1, ci + R); ++i)
      for (int y = j * zoom; y < (j + 1) * zoom; ++y)
        for (int x = i * zoom; x < (i + 1) * zoom; ++x)
          img.set(x, y, Color::Constant(filter.evalClassic(float(x) / zoom - cx, float(y) / zoom - cy)));
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x)
      if (x % zoom == 0 || y % zoom == 0) img.set(x, y, kBlue);
  return img;
}

Image plotSamplerPoints(const Sampler& sampler, int blocksX, int blocksY, int zoom) {
  Image img(blocksX * zoom + 1, blocksY * zoom + 1, Color::Constant(0.05f));
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x)
      if (x % zoom == 0 || y % zoom == 0) img.set(x, y, Color::Constant(0.3f));
  std::vector<Vec2> pts(sampler.spp());
  for (int py = 0; py < blocksY; ++py)
    for (int px = 0; px < blocksX; ++px) {
      sampler.generate(px, py, pts.data());
      for (const Vec2& p : pts) {
        const int x = std::clamp(int(std::floor((px + p.x()) * zoom)), 0, img.width() - 1);
        const int y = std::clamp(int(std::floor((py + p.y()) * zoom)), 0, img.height() - 1);
        img.set(x, y, Color::Ones());
      }
    }
  return img;
}

Image plotFilter(const Filter& filter, int size) {
  const int panel = size / 2;
  Image img(size, size + panel, Color::Zero());
  const float r = filter.radius();
  auto offset = [&](int k) { return -r + 2 * r * (k + 0.5f) / size; };

  // kernel, scaled by the largest |f| on the grid
  std::vector<float> f(size_t(size) * size);
  float peak = 1e-30f;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) peak = std::max(peak, std::abs(f[size_t(y) * size + x] = filter.eval(offset(x), offset(y))));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) img.set(x, panel + y, diverging(f[size_t(y) * size + x] / peak));

  // 1-D profile below: values in [-peak, peak] over the panel's height
  if (panel > 2) {
    auto row = [&](float v) { return std::clamp(int(std::lround((0.5f + 0.5f * v / peak) * (panel - 1))), 0, panel - 1); };
    for (int x = 0; x < size; ++x) img.set(x, row(0.f), Color::Constant(0.4f));
    int prev = row(filter.eval(offset(0), 0.f));
    for (int x = 0; x < size; ++x) {
      const int y = row(filter.eval(offset(x), 0.f));
      for (int t = std::min(prev, y); t <= std::max(prev, y); ++t) img.set(x, t, Color::Ones());
      prev = y;
    }
  }
  return img;
}

Image falseColor(const Image& signedError, float scale) {
  Image img(signedError.width(), signedError.height());
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) img.set(x, y, diverging(channelMean(signedError.get(x, y)) / scale));
  return img;
}

Image heatColor(const Image& value, float maxValue) {
  Image img(value.width(), value.height());
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      float t = channelMean(value.get(x, y)) / maxValue;
      t = std::clamp(std::isfinite(t) ? t : 1.f, 0.f, 1.f);
      img.set(x, y, Color(std::min(1.f, 3 * t), std::clamp(3 * t - 1, 0.f, 1.f), std::clamp(3 * t - 2, 0.f, 1.f)));
    }
  return img;
}

}  // namespace aliaslab
