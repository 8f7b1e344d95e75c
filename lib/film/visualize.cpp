// Pictures of the film: its samples and its filters.
#include "film/visualize.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/format.h"
#include "core/picture_kit.h"

namespace aliaslab {
namespace {

const Color kDarkBlue(0.f, 0.f, 0.5f), kBlue(0.f, 0.f, 1.f);
const Color kGhost(0.75f, 0.55f, 0.15f);  ///< renderSamples: a block neighbour's sample offset (amber)

/// sign(t) sqrt(|t|): lobes of a few per cent of the peak get a visible tint.
float signedSqrt(float t) { return std::copysign(std::sqrt(std::abs(t)), t); }

}  // namespace

Image renderFilterSigned(const Filter& filter, int width, int height, int zoom) {
  const int W = width * zoom + 1, H = height * zoom + 1;
  const float cx = width / 2 + 0.5f, cy = height / 2 + 0.5f;
  std::vector<float> f(static_cast<size_t>(W) * H);
  float peak = 0.f;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const float v = filter.eval(float(x) / zoom - cx, float(y) / zoom - cy);
      f[static_cast<size_t>(y) * W + x] = v;
      if (std::isfinite(v)) peak = std::max(peak, std::abs(v));
    }
  if (!(peak > 0.f)) peak = 1.f;
  Image img(W, H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      img.set(x, y, x % zoom == 0 || y % zoom == 0 ? Color::Constant(0.55f)
                                                   : divergingColor(signedSqrt(f[static_cast<size_t>(y) * W + x] / peak)));
  // the bar is linear in the weight, its colours through the same signed square root
  return withColorBar(img, [](float t) { return divergingColor(signedSqrt(2 * t - 1)); }, "-" + formatNumber(peak),
                      "0", "+" + formatNumber(peak));
}

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

Image renderSamplesMarked(const SampleBuffer& samples, int zoom, int strataColumns, int strataRows) {
  const int w = samples.width() * zoom, h = samples.height() * zoom;
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if ((x / zoom + y / zoom) % 2 == 0) img.set(x, y, Color::Constant(0.2f));
  if (strataColumns > 0 && strataRows > 0) {
    const Color line(0.1f, 0.2f, 0.45f);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        // a stratum boundary crosses this image pixel: floor of the stratum index changes within it
        const bool vx = std::floor(double(x) * strataColumns / zoom) != std::floor(double(x + 1) * strataColumns / zoom);
        const bool vy = std::floor(double(y) * strataRows / zoom) != std::floor(double(y + 1) * strataRows / zoom);
        if (vx || vy) img.set(x, y, line);
      }
  }
  if (zoom >= 4)
    for (const FilmSample& s : samples.samples()) {
      const float fx = std::floor(s.x * zoom), fy = std::floor(s.y * zoom);
      if (!(fx >= 0 && fy >= 0 && fx < w && fy < h)) continue;
      const Color ring = channelMean(s.L) < 0.5f ? Color::Ones() : Color::Zero();
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int x = int(fx) + dx, y = int(fy) + dy;
          if ((dx || dy) && x >= 0 && y >= 0 && x < w && y < h) img.set(x, y, ring);
        }
    }
  for (const FilmSample& s : samples.samples()) {
    const float fx = std::floor(s.x * zoom), fy = std::floor(s.y * zoom);
    if (fx >= 0 && fy >= 0 && fx < w && fy < h) img.set(int(fx), int(fy), s.L);
  }
  return img;
}

Image renderFilter(const Filter& given, int width, int height, int zoom) {
  const std::unique_ptr<Filter> course = makeCourseVariant(given);
  const Filter& filter = course ? *course : given;
  Image img(width * zoom + 1, height * zoom + 1, kDarkBlue);
  const int R = classicSupport(filter), ci = width / 2, cj = height / 2;
  const float cx = ci + 0.5f, cy = cj + 0.5f;
  for (int j = std::max(0, cj - R); j <= std::min(height - 1, cj + R); ++j)
    for (int i = std::max(0, ci - R); i <= std::min(width - 1, ci + R); ++i)
      for (int y = j * zoom; y < (j + 1) * zoom; ++y)
        for (int x = i * zoom; x < (i + 1) * zoom; ++x)
          img.set(x, y, Color::Constant(filter.eval(float(x) / zoom - cx, float(y) / zoom - cy)));
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x)
      if (x % zoom == 0 || y % zoom == 0) img.set(x, y, kBlue);
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
    for (int x = 0; x < size; ++x) img.set(x, panel + y, divergingColor(f[size_t(y) * size + x] / peak));

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

}  // namespace aliaslab
