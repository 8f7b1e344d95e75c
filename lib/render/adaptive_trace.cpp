// Adaptive sampling: the three methods and the area weights; see adaptive.h. The state they share (Work:
// the samples, the budget, the rounds that trace them) is in adaptive_work.h.
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "render/adaptive_work.h"

namespace aliaslab {

namespace {

using adaptiveimpl::Request;
using adaptiveimpl::Work;

int capOf(const AdaptiveSampler& a) {
  return static_cast<int>(std::max<double>(a.spp(), std::llround(a.params().cap * a.spp())));
}

/// Gives up to `step` samples to pixels in `order` whose priority exceeds `above`, up to the cap and the budget.
/// Returns the samples given (0: no candidate).
long long allot(const Work& w, const std::vector<long long>& order, const std::vector<double>& priority, double above,
                int step, int cap, long long budget, std::vector<int>& add) {
  add.assign(w.pixels(), 0);
  long long given = 0;
  for (long long p : order) {
    if (!(priority[p] > above) || given >= budget) break;
    const long long g = std::min<long long>({step, cap - w.count(p), budget - given});
    if (g > 0) add[p] = static_cast<int>(g), given += g;
  }
  return given;
}

// Mitchell: contrast of the 3x3 neighbourhood against per-channel thresholds.
void runContrast(Work& w, const AdaptiveSampler& a, int W, int H) {
  const AdaptiveParams& prm = a.params();
  const int n0 = std::clamp(static_cast<int>(std::lround(prm.first * a.spp())), 1, a.spp()), cap = capOf(a);
  w.tracePixels(std::vector<int>(w.pixels(), n0));
  std::vector<Color> lo, hi;
  std::vector<double> ratio(w.pixels());
  std::vector<int> add;
  while (w.left() > 0) {
    w.pixelRanges(lo, hi);
    for (int j = 0; j < H; ++j)
      for (int i = 0; i < W; ++i) {
        Color l = Color::Constant(INFINITY), h = Color::Constant(-INFINITY);
        for (int y = std::max(0, j - 1); y <= std::min(H - 1, j + 1); ++y)
          for (int x = std::max(0, i - 1); x <= std::min(W - 1, i + 1); ++x) {
            const size_t q = static_cast<size_t>(y) * W + x;
            l = l.min(lo[q]), h = h.max(hi[q]);
          }
        double r = 0;
        for (int c = 0; c < 3; ++c) {
          const double sum = double(h[c]) + l[c];
          if (sum > 1e-30 && std::isfinite(sum)) r = std::max(r, (double(h[c]) - l[c]) / sum / prm.contrast[c]);
        }
        ratio[static_cast<size_t>(j) * W + i] = r;
      }
    if (allot(w, w.rank(ratio), ratio, 1.0, n0, cap, w.left(), add) == 0) {
      w.spendEvenly(ratio);
      break;
    }
    w.tracePixels(add);
  }
}

// Error-driven: the estimated standard error of each pixel's mean.
void runError(Work& w, const AdaptiveSampler& a, long long budget) {
  const AdaptiveParams& prm = a.params();
  const int n0 = std::clamp(static_cast<int>(std::lround(prm.first * a.spp())), std::min(2, a.spp()), a.spp());
  const int cap = capOf(a);
  const long long perRound = std::max<long long>(n0, std::llround(prm.round * static_cast<double>(budget)));
  w.tracePixels(std::vector<int>(w.pixels(), n0));
  std::vector<double> se(w.pixels());
  std::vector<int> add;
  while (w.left() > 0) {
    for (long long p = 0; p < w.pixels(); ++p) {
      const auto& s = w.samples(p);
      const double n = static_cast<double>(s.size());
      double mean[3] = {0, 0, 0}, var = 0;
      for (const FilmSample& f : s)
        for (int c = 0; c < 3; ++c) mean[c] += f.L[c] / n;
      for (const FilmSample& f : s)
        for (int c = 0; c < 3; ++c) var += (f.L[c] - mean[c]) * (f.L[c] - mean[c]);
      se[p] = n > 1 && std::isfinite(var) ? std::sqrt(var / 3 / (n - 1) / n) : 0.0;
    }
    if (allot(w, w.rank(se), se, 0.0, n0, cap, std::min(w.left(), perRound), add) == 0) {
      w.spendEvenly(se);
      break;
    }
    w.tracePixels(add);
  }
}

/// A cell of a pixel's quadtree as one number (level, cx, cy).
uint64_t cellKey(int level, int cx, int cy) {
  return (static_cast<uint64_t>(level) << 48) | (static_cast<uint64_t>(cx) << 24) | static_cast<uint64_t>(cy);
}

// Whitted: split cells whose samples differ by more than the threshold. Returns each pixel's split cells.
std::vector<std::vector<uint64_t>> runSubdivision(Work& w, const AdaptiveSampler& a, int W) {
  std::vector<std::vector<uint64_t>> splits(w.pixels());
  const AdaptiveParams& prm = a.params();
  const int n0 = std::min(4, a.spp());
  w.tracePixels(std::vector<int>(w.pixels(), n0));
  struct Cell {
    long long p;
    Request r;
    double diff = 0;
  };
  std::vector<Cell> level;
  for (long long p = 0; p < w.pixels(); ++p) level.push_back({p, {0, 0, 0, n0}});
  for (int d = 0; d < prm.depth && w.left() > 0 && !level.empty(); ++d) {
    // each cell's spread: max over channels of (max - min) of the pixel's samples inside it
    std::vector<Cell> split;
    for (Cell& c : level) {
      const double side = std::ldexp(1.0, -c.r.level);
      const double x0 = static_cast<double>(c.p % W) + c.r.cx * side, y0 = static_cast<double>(c.p / W) + c.r.cy * side;
      Color lo = Color::Constant(INFINITY), hi = Color::Constant(-INFINITY);
      int inCell = 0;
      for (const FilmSample& s : w.samples(c.p))
        if (s.x >= x0 && s.x < x0 + side && s.y >= y0 && s.y < y0 + side && s.L.allFinite())
          lo = lo.min(s.L), hi = hi.max(s.L), ++inCell;
      c.diff = inCell >= 2 ? static_cast<double>((hi - lo).maxCoeff()) : 0.0;
      if (c.diff > prm.threshold) split.push_back(c);
    }
    // largest difference first; equal ones in the pixel-hash order (no bias towards the first rows)
    std::stable_sort(split.begin(), split.end(), [&](const Cell& a, const Cell& b) {
      return a.diff != b.diff ? a.diff > b.diff : w.hash(a.p) < w.hash(b.p);
    });
    // children, 4 points each, largest difference first, as long as the budget pays a whole split (16)
    std::vector<std::vector<Request>> requests(w.pixels());
    std::vector<Cell> next;
    long long budget = w.left();
    for (const Cell& c : split) {
      if (budget < 16) break;
      budget -= 16;
      splits[c.p].push_back(cellKey(c.r.level, c.r.cx, c.r.cy));
      for (int k = 0; k < 4; ++k) {
        const Request child{c.r.level + 1, 2 * c.r.cx + (k & 1), 2 * c.r.cy + (k >> 1), 4};
        requests[c.p].push_back(child);
        next.push_back({c.p, child});
      }
    }
    if (next.empty()) break;
    w.trace(requests);
    level = std::move(next);
  }
  // what is left goes evenly, first to the pixels with the largest spread
  std::vector<Color> lo, hi;
  w.pixelRanges(lo, hi);
  std::vector<double> spread(w.pixels());
  for (long long p = 0; p < w.pixels(); ++p)
    spread[p] = w.count(p) > 1 ? static_cast<double>((hi[p] - lo[p]).maxCoeff()) : 0.0;
  w.spendEvenly(spread);
  return splits;
}

/// Sets each sample's weight to the area it stands for: its leaf cell's area (the pixel's, 1, when nothing was
/// split) over the samples in that leaf.
void setAreaWeights(SampleBuffer& b, const std::vector<std::vector<uint64_t>>& splits) {
  for (int j = 0; j < b.height(); ++j)
    for (int i = 0; i < b.width(); ++i) {
      const size_t p = static_cast<size_t>(j) * b.width() + i;
      FilmSample* s = b.pixel(i, j);
      const int n = b.count(i, j);
      std::vector<uint64_t> leaf(n);
      std::vector<int> level(n);
      for (int k = 0; k < n; ++k) {
        int d = 0;
        auto key = [&](int depth) {
          return cellKey(depth, static_cast<int>(std::ldexp(s[k].x - i, depth)),
                         static_cast<int>(std::ldexp(s[k].y - j, depth)));
        };
        while (!splits.empty() && std::find(splits[p].begin(), splits[p].end(), key(d)) != splits[p].end()) ++d;
        leaf[k] = key(d), level[k] = d;
      }
      for (int k = 0; k < n; ++k)
        s[k].weight = static_cast<float>(std::ldexp(1.0, -2 * level[k]) /
                                         static_cast<double>(std::count(leaf.begin(), leaf.end(), leaf[k])));
    }
  b.setAreaWeighted(true);
}

}  // namespace

SampleBuffer traceAdaptive(const Tracer& tracer, const AdaptiveSampler& sampler, int width, int height, int threads,
                           const Progress& progress) {
  if (!tracer.scene().camera) throw InputError(tracer.scene().path + ": the scene has no camera");
  Work w(tracer, sampler, width, height, threads, progress);
  std::vector<std::vector<uint64_t>> splits;  // subdivision only: each pixel's split cells
  switch (sampler.method()) {
    case AdaptiveMethod::Contrast: runContrast(w, sampler, width, height); break;
    case AdaptiveMethod::Error: runError(w, sampler, static_cast<long long>(sampler.spp()) * width * height); break;
    case AdaptiveMethod::Subdivision: splits = runSubdivision(w, sampler, width); break;
  }
  std::vector<int> counts(w.pixels());
  for (long long p = 0; p < w.pixels(); ++p) counts[p] = w.count(p);
  SampleBuffer out(width, height, counts);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const auto& s = w.samples(static_cast<long long>(j) * width + i);
      std::copy(s.begin(), s.end(), out.pixel(i, j));
    }
  setAreaWeights(out, splits);
  return out;
}

}  // namespace aliaslab
