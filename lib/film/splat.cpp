// The fast weighted average. Per output band of rows (the parallel work
// item), per source pixel that can reach the band, one tile covering the
// union of its samples' footprints; per sample one Filter::evalFootprint call
// over the sample's own footprint (vectorised weights, no virtual call per
// pixel) and a 4-lane (r, g, b, w) accumulation into the tile (Acc: float
// or double lanes; double is used: exact products, and float measured no
// faster); the tile is added to the image's double sums once per source
// pixel, so every pixel's sum has a fixed order for any thread count.
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "core/parallel.h"
#include "film/film_impl.h"

namespace aliaslab::filmimpl {
namespace {

constexpr int kBand = 32;        // output rows per parallel work item
constexpr float kMargin = 1e-3f; // widens footprints so boundary samples always reach the exact test

/// Pixels [lo, hi] of an axis of `n` pixels whose centre c + 0.5 satisfies |p - c - 0.5| <= r (widened).
inline void footprint(float p, float r, int n, int& lo, int& hi) {
  lo = static_cast<int>(std::ceil(std::max(-1.f, p - 0.5f - r - kMargin)));
  hi = static_cast<int>(std::floor(std::min(static_cast<float>(n), p - 0.5f + r + kMargin)));
  lo = std::max(lo, 0);
  hi = std::min(hi, n - 1);
}

/// footprint() trimmed to the centres with |p - (c + 0.5f)| <= r exactly as eval() rounds it.
inline void exactFootprint(float p, float r, int n, int& lo, int& hi) {
  footprint(p, r, n, lo, hi);
  while (lo <= hi && std::abs(p - (static_cast<float>(lo) + 0.5f)) > r) ++lo;
  while (hi >= lo && std::abs(p - (static_cast<float>(hi) + 0.5f)) > r) --hi;
}

/// Bounding box of a pixel's finite samples (empty: xmin > xmax).
struct Box {
  float xmin = kInf, xmax = -kInf, ymin = kInf, ymax = -kInf;
};

template <class Acc>
void splat(const SampleBuffer& samples, const Filter& filter, double* sums, int threads) {
  using Scalar = typename Acc::Scalar;
  const int W = samples.width(), H = samples.height(), spp = samples.spp();
  const float r = filter.radius();

  // per source pixel: the box of its samples; per source row: the output rows it can reach
  std::vector<Box> boxes(static_cast<size_t>(W) * H);
  parallelFor(H, threads, [&](int sj) {
    for (int si = 0; si < W; ++si) {
      const FilmSample* s = samples.pixel(si, sj);
      Box& b = boxes[static_cast<size_t>(sj) * W + si];
      for (int k = 0; k < spp; ++k)
        if (finiteSample(s[k]))
          b.xmin = std::min(b.xmin, s[k].x), b.xmax = std::max(b.xmax, s[k].x), b.ymin = std::min(b.ymin, s[k].y),
          b.ymax = std::max(b.ymax, s[k].y);
    }
  });
  std::vector<int> reachLo(H, H), reachHi(H, -1);
  for (int sj = 0; sj < H; ++sj) {
    float ymin = kInf, ymax = -kInf;
    for (int si = 0; si < W; ++si) {
      const Box& b = boxes[static_cast<size_t>(sj) * W + si];
      ymin = std::min(ymin, b.ymin), ymax = std::max(ymax, b.ymax);
    }
    if (ymin <= ymax) {
      int lo, hi;
      footprint(ymin, r, H, lo, hi), reachLo[sj] = lo;
      footprint(ymax, r, H, lo, hi), reachHi[sj] = hi;
    }
  }

  const int bands = (H + kBand - 1) / kBand;
  parallelFor(bands, threads, [&](int band) {
    const int j0 = band * kBand, j1 = std::min(H, j0 + kBand);
    std::vector<float> w;
    std::vector<Acc, Eigen::aligned_allocator<Acc>> tile;
    for (int sj = 0; sj < H; ++sj) {
      if (reachHi[sj] < j0 || reachLo[sj] >= j1) continue;
      for (int si = 0; si < W; ++si) {
        const Box& box = boxes[static_cast<size_t>(sj) * W + si];
        if (!(box.xmin <= box.xmax)) continue;
        int ti0, ti1, tj0, tj1, unused;
        footprint(box.xmin, r, W, ti0, unused), footprint(box.xmax, r, W, unused, ti1);
        footprint(box.ymin, r, H, tj0, unused), footprint(box.ymax, r, H, unused, tj1);
        tj0 = std::max(tj0, j0), tj1 = std::min(tj1, j1 - 1);
        if (ti0 > ti1 || tj0 > tj1) continue;
        const int tnx = ti1 - ti0 + 1, tny = tj1 - tj0 + 1;
        tile.assign(static_cast<size_t>(tnx) * tny, Acc::Zero());

        // each sample over its own footprint
        const FilmSample* s = samples.pixel(si, sj);
        for (int k = 0; k < spp; ++k) {
          const FilmSample& smp = s[k];
          if (!finiteSample(smp)) continue;
          int ilo, ihi, jlo, jhi;
          exactFootprint(smp.x, r, W, ilo, ihi);
          exactFootprint(smp.y, r, H, jlo, jhi);
          jlo = std::max(jlo, j0), jhi = std::min(jhi, j1 - 1);
          if (ilo > ihi || jlo > jhi) continue;
          const int nx = ihi - ilo + 1, ny = jhi - jlo + 1, stride = Filter::footprintStride(nx);
          if (w.size() < static_cast<size_t>(stride) * ny) w.resize(static_cast<size_t>(stride) * ny);
          filter.evalFootprint(smp.x, smp.y, ilo, nx, jlo, ny, w.data());
          const Acc L(Scalar(smp.L[0]), Scalar(smp.L[1]), Scalar(smp.L[2]), Scalar(1));
          for (int b = 0; b < ny; ++b) {
            Acc* row = tile.data() + static_cast<size_t>(jlo - tj0 + b) * tnx + (ilo - ti0);
            const float* wr = w.data() + static_cast<size_t>(b) * stride;
            for (int a = 0; a < nx; ++a) row[a] += Scalar(wr[a]) * L;
          }
        }
        for (int b = 0; b < tny; ++b) {
          double* out = sums + 4 * (static_cast<size_t>(tj0 + b) * W + ti0);
          const Acc* row = tile.data() + static_cast<size_t>(b) * tnx;
          for (int a = 0; a < tnx; ++a, out += 4) Eigen::Map<Eigen::Array4d>(out) += row[a].template cast<double>();
        }
      }
    }
  });
}

}  // namespace

size_t countNonFinite(const SampleBuffer& samples) {
  size_t n = 0;
  for (const FilmSample& s : samples.samples()) n += !finiteSample(s);
  return n;
}

void addPlainSums(const SampleBuffer& samples, double* plain) {
  const int spp = samples.spp();
  for (int j = 0; j < samples.height(); ++j)
    for (int i = 0; i < samples.width(); ++i) {
      const FilmSample* s = samples.pixel(i, j);
      double* p = plain + 4 * (static_cast<size_t>(j) * samples.width() + i);
      for (int k = 0; k < spp; ++k)
        if (finiteSample(s[k])) p[0] += s[k].L[0], p[1] += s[k].L[1], p[2] += s[k].L[2], p[3] += 1;
    }
}

void splatWeighted(const SampleBuffer& samples, const Filter& filter, double* sums, int threads) {
  splat<Eigen::Array4d>(samples, filter, sums, threads);
}

}  // namespace aliaslab::filmimpl
