// Adaptive sampling: the pilot-then-allocate methods (contrast, error) and the entry point; see adaptive.h.
// Subdivision is in adaptive_subdiv.cpp; the state they share (Work: the samples, the budget, the rounds that
// trace them) in adaptive_work.h.
//
// Both methods here run in two rounds: a pilot of n0 samples per pixel, then one allocation of the rest of the
// budget decided from the pilot alone, traced as fresh samples (at least one per pixel). See docs/adaptive.md,
// "Bias", for why each way is unbiased:
// - a progressive base (AdaptiveSampler::progressive): the pilot is points 0 .. n0-1 of each pixel's own
//   sequence, the fresh samples its points n0 .. n0+m-1, every sample of the pixel weighs 1 / (n0 + m) (the plain
//   mean); the neighbourhoods that decide m leave the pixel's own pilot out.
// - otherwise: the fresh samples are a new draw of the base; the pilot keeps the fixed share alpha = n0 / spp of
//   its pixel's estimate and the fresh samples the rest, 1 - alpha, whatever the allocation.
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "render/adaptive/adaptive_work.h"

namespace aliaslab {

namespace {

using adaptiveimpl::dilate;
using adaptiveimpl::neighbourMax;
using adaptiveimpl::Work;

/// Fresh samples per pixel allowed at most: cap * spp in all, less the pilot (at least 1).
int freshCap(const AdaptiveSampler& a, int n0) {
  return std::max(1, static_cast<int>(std::llround(a.params().cap * a.spp())) - n0);
}

/// The pilot: n0 samples per pixel, each of weight 1 / spp (its share alpha / n0). Returns alpha. The last
/// round when n0 = spp (nothing left to allocate).
/// With a progressive base the pilot is each pixel's points 0 .. n0-1, weighed again by traceFresh.
double tracePilot(Work& w, const AdaptiveSampler& a, int n0) {
  const std::vector<int> first(a.progressive() ? w.pixels() : 0, 0);
  w.tracePixels(std::vector<int>(w.pixels(), n0), std::vector<double>(w.pixels(), double(n0) / a.spp()),
                n0 == a.spp(), a.progressive() ? &first : nullptr);
  return double(n0) / a.spp();
}

/// The fresh round, the last: fresh[p] >= 1 samples in every pixel. A progressive base: each pixel's points
/// n0 .. n0 + fresh[p] - 1, every sample of the pixel (the pilot's too) of weight 1 / (n0 + fresh[p]). Otherwise
/// a new draw of the base sharing 1 - alpha of the pixel's estimate.
void traceFresh(Work& w, const AdaptiveSampler& a, const std::vector<int>& fresh, int n0) {
  if (!a.progressive()) {
    w.tracePixels(fresh, std::vector<double>(w.pixels(), 1.0 - double(n0) / a.spp()), true);
    return;
  }
  std::vector<double> share(w.pixels());
  std::vector<float> earlier(w.pixels());
  for (long long p = 0; p < w.pixels(); ++p) {
    share[p] = double(fresh[p]) / (n0 + fresh[p]);
    earlier[p] = static_cast<float>(1.0 / (n0 + fresh[p]));
  }
  w.setEarlierWeights(std::move(earlier));
  const std::vector<int> first(w.pixels(), n0);
  w.tracePixels(fresh, share, true, &first);
}

// Mitchell: contrast of the 3x3 neighbourhood of the pilot against per-channel thresholds.
void runContrast(Work& w, const AdaptiveSampler& a, int W, int H) {
  const AdaptiveParams& prm = a.params();
  const int n0 = std::clamp(static_cast<int>(std::lround(prm.first * a.spp())), 1, a.spp());
  tracePilot(w, a, n0);
  if (n0 == a.spp()) return;
  const bool own = !a.progressive();  // whether a pixel's own pilot enters its neighbourhood
  std::vector<Color> lo, hi;
  w.pixelRanges(lo, hi);
  std::vector<double> ratio(w.pixels());
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      Color l = Color::Constant(INFINITY), h = Color::Constant(-INFINITY);
      for (int y = std::max(0, j - 1); y <= std::min(H - 1, j + 1); ++y)
        for (int x = std::max(0, i - 1); x <= std::min(W - 1, i + 1); ++x) {
          if (!own && x == i && y == j) continue;
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
  // one fresh sample everywhere; the marked pixels an equal share up to the cap (one more to the first ones
  // in rank order where the share does not divide); the rest evenly
  std::vector<int> fresh(w.pixels(), 1);
  long long left = w.left() - w.pixels();
  const int cap = freshCap(a, n0);
  long long marked = 0;
  for (double r : ratio) marked += r > 1.0;
  const std::vector<long long> order = w.rank(ratio, marked);
  if (marked > 0) {
    const long long each = std::min<long long>(cap - 1, left / marked);
    const long long extra = each < cap - 1 ? left - each * marked : 0;
    for (long long k = 0; k < marked; ++k) {
      const long long g = each + (k < extra ? 1 : 0);
      fresh[order[k]] += static_cast<int>(g), left -= g;
    }
  }
  const std::vector<int> even = w.evenly(left, ratio);
  for (long long p = 0; p < w.pixels(); ++p) fresh[p] += even[p];
  traceFresh(w, a, fresh, n0);
}

// Error-driven: fresh samples in proportion to the pilot's standard deviation (dilated over 3 x 3), between
// a floor and the cap: the allocation n_p ~ sigma_p that minimises the summed variance sum sigma_p^2 / n_p.
void runError(Work& w, const AdaptiveSampler& a, int W, int H) {
  const AdaptiveParams& prm = a.params();
  const int n0 = std::clamp(static_cast<int>(std::lround(prm.first * a.spp())), std::min(2, a.spp()), a.spp());
  tracePilot(w, a, n0);
  if (n0 == a.spp()) return;
  std::vector<double> sd(w.pixels(), 0.0);
  for (long long p = 0; p < w.pixels(); ++p) {
    const double n = static_cast<double>(w.count(p));
    double mean[3] = {0, 0, 0}, var = 0;
    w.forSamples(p, [&](const FilmSample& f) {
      for (int c = 0; c < 3; ++c) mean[c] += f.L[c] / n;
    });
    w.forSamples(p, [&](const FilmSample& f) {
      for (int c = 0; c < 3; ++c) var += (f.L[c] - mean[c]) * (f.L[c] - mean[c]);
    });
    sd[p] = n > 1 && std::isfinite(var) ? std::sqrt(var / 3 / (n - 1)) : 0.0;
  }
  sd = a.progressive() ? neighbourMax(sd, W, H) : dilate(sd, W, H);  // progressive: its own pilot left out
  const long long budget = w.left();
  const int lowest = std::clamp(static_cast<int>(std::lround(prm.floor * (a.spp() - n0))), 1, a.spp() - n0);
  const int cap = std::max(lowest, freshCap(a, n0));
  const auto fresh0 = [&](double lambda, double s) {
    const double want = std::min<double>(cap, lambda * s - n0);
    return std::max(lowest, static_cast<int>(std::floor(std::max(0.0, want))));
  };
  // The total depends on sd only: each distinct value once, with how many pixels have it (the dilation repeats
  // values, flat regions share 0), so the search sums fewer terms and finds the same integer totals.
  std::vector<std::pair<double, long long>> distinct;
  {
    std::vector<double> sorted(sd);
    std::sort(sorted.begin(), sorted.end());
    for (double s : sorted)
      if (distinct.empty() || distinct.back().first != s) distinct.push_back({s, 1});
      else ++distinct.back().second;
  }
  const auto allot = [&](double lambda) {
    long long total = 0;
    for (const auto& [s, k] : distinct) total += k * fresh0(lambda, s);
    return total;
  };
  // the largest lambda whose allocation fits the budget (the total grows with lambda)
  double lo = 0, hi = 1;
  while (hi < 1e12 && allot(hi) <= budget) hi *= 2;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (allot(mid) <= budget ? lo : hi) = mid;
  }
  std::vector<int> fresh(w.pixels());
  long long used = 0;
  for (long long p = 0; p < w.pixels(); ++p) used += fresh[p] = fresh0(lo, sd[p]);
  const std::vector<int> even = w.evenly(budget - used, sd);
  for (long long p = 0; p < w.pixels(); ++p) fresh[p] += even[p];
  traceFresh(w, a, fresh, n0);
}

}  // namespace

SampleBuffer traceAdaptive(const Tracer& tracer, const AdaptiveSampler& sampler, int width, int height, int threads,
                           const Progress& progress) {
  if (!tracer.scene().camera) throw InputError(tracer.scene().path + ": the scene has no camera");
  Work w(tracer, sampler, width, height, threads, progress);
  switch (sampler.method()) {
    case AdaptiveMethod::Contrast: runContrast(w, sampler, width, height); break;
    case AdaptiveMethod::Error: runError(w, sampler, width, height); break;
    case AdaptiveMethod::Subdivision: adaptiveimpl::runSubdivision(w, sampler); break;
  }
  return w.gather();
}

}  // namespace aliaslab
