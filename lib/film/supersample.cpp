// Supersample then downsample: k x k sub-pixel cells, 3x3 binomial blur, box average.
#include <cmath>

#include "core/error.h"
#include "core/parallel.h"
#include "film/film_impl.h"

namespace aliaslab::filmimpl {
namespace {

/// One pass of [1 2 1] along x (dir 0) or y (dir 1), renormalised over the taps inside the image.
std::vector<double> binomialPass(const std::vector<double>& in, int w, int h, int dir) {
  std::vector<double> out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sum[3] = {0, 0, 0}, wsum = 0;
      for (int t = -1; t <= 1; ++t) {
        const int xx = dir == 0 ? x + t : x, yy = dir == 1 ? y + t : y;
        if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
        const double wt = t == 0 ? 2 : 1;
        const double* p = &in[3 * (size_t(yy) * w + xx)];
        for (int c = 0; c < 3; ++c) sum[c] += wt * p[c];
        wsum += wt;
      }
      for (int c = 0; c < 3; ++c) out[3 * (size_t(y) * w + x) + c] = sum[c] / wsum;
    }
  return out;
}

}  // namespace

Reconstruction reconstructSupersample(const SampleBuffer& samples, int threads) {
  const int W = samples.width(), H = samples.height(), spp = samples.spp();
  if (samples.variable())
    throw OptionError("reconstruction", "supersample needs the same square count k*k in every pixel; an adaptive "
                                          "sample set varies it");
  const int k = static_cast<int>(std::lround(std::sqrt(double(spp))));
  if (k * k != spp)
    throw OptionError("spp", "supersample reconstruction needs a square sample count k*k, got " +
                                   std::to_string(spp));
  const int fw = W * k, fh = H * k;
  Reconstruction out{Image(W, H), {}};

  // fine image by position: mean of the samples in each cell
  std::vector<double> cell(4 * size_t(fw) * fh, 0.0), plain(4 * size_t(W) * H, 0.0);
  out.stats.nonFiniteSamples = addPlainSums(samples, plain.data());
  for (const FilmSample& s : samples.samples()) {
    if (!finiteSample(s)) continue;
    const int fx = std::clamp(static_cast<int>(std::floor(std::clamp(s.x * k, -1.f, float(fw)))), 0, fw - 1);
    const int fy = std::clamp(static_cast<int>(std::floor(std::clamp(s.y * k, -1.f, float(fh)))), 0, fh - 1);
    double* c = &cell[4 * (size_t(fy) * fw + fx)];
    c[0] += s.L[0], c[1] += s.L[1], c[2] += s.L[2], c[3] += 1;
  }
  std::vector<double> fine(3 * size_t(fw) * fh);
  for (int y = 0; y < fh; ++y)
    for (int x = 0; x < fw; ++x) {
      const double* c = &cell[4 * (size_t(y) * fw + x)];
      const double* q = c[3] > 0 ? c : &plain[4 * (size_t(y / k) * W + x / k)];  // empty cell: pixel mean
      for (int ch = 0; ch < 3; ++ch) fine[3 * (size_t(y) * fw + x) + ch] = q[3] > 0 ? q[ch] / q[3] : 0.0;
    }
  fine = binomialPass(binomialPass(fine, fw, fh, 0), fw, fh, 1);

  // k x k block average
  std::vector<size_t> nan(H, 0);
  parallelFor(H, threads, [&](int j) {
    for (int i = 0; i < W; ++i) {
      double sum[3] = {0, 0, 0};
      for (int y = j * k; y < (j + 1) * k; ++y)
        for (int x = i * k; x < (i + 1) * k; ++x)
          for (int ch = 0; ch < 3; ++ch) sum[ch] += fine[3 * (size_t(y) * fw + x) + ch];
      Color c(float(sum[0] / spp), float(sum[1] / spp), float(sum[2] / spp));
      if (!c.allFinite()) {  // overflow: the pixel's plain mean, counted below
        const double* q = &plain[4 * (size_t(j) * W + i)];
        c = q[3] > 0 ? Color(float(q[0] / q[3]), float(q[1] / q[3]), float(q[2] / q[3])) : Color::Zero();
        if (!c.allFinite()) c = Color::Zero();
        ++nan[j];
      }
      out.image.set(i, j, c);
    }
  });
  for (int j = 0; j < H; ++j) out.stats.nanPixels += nan[j];
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const Color c = out.image.get(i, j);
      if (plain[4 * (size_t(j) * W + i) + 3] == 0) ++out.stats.undefinedPixels;
      if ((c < 0).any()) ++out.stats.negativePixels;
    }
  return out;
}

}  // namespace aliaslab::filmimpl
