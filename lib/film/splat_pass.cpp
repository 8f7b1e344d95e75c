// The splat's pass per radius (splatSameRadius, protocol at the top of splat.cpp): per output band, the
// samples of every source row that can reach it, set up one by one or 8 at a time (setup8, AVX2) into
// batches, each filter's weights and accumulation kernel run on every batch, then the band's sums added
// into the image's. The per-sample set-up stays in this one file with the loop that calls it.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <memory>
#include <vector>

#include <immintrin.h>

#include "core/cpu.h"
#include "core/parallel.h"
#include "film/splat_workspace.h"

namespace aliaslab::filmimpl {
namespace {

using Clock = std::chrono::steady_clock;

/// Whether the pixel centre i + 0.5 is within r of p, as eval() rounds it.
inline bool inside(float p, float r, int i) { return std::abs(p - (static_cast<float>(i) + 0.5f)) <= r; }

/// The pixel centres within r of p as eval() rounds |p - (i + 0.5f)| <= r: i in [lo, hi] (lo > hi: none).
/// For |p| >= r + 2 (and |p| < 2^22) the float differences p - c near both ends are exact (multiples of
/// ulp(p), smaller than |p|), so the bounds are the real ones, computed exactly in double; nearer 0 the
/// float estimate (off by at most one) is corrected in two branch-free steps.
inline void centresWithin(float p, float r, int& lo, int& hi) {
  if (std::abs(p) >= r + 2 && r < 1e8f) {  // (p is within r + 1 of the image: no int overflow)
    lo = static_cast<int>(std::ceil(static_cast<double>(p) - 0.5 - r));
    hi = static_cast<int>(std::floor(static_cast<double>(p) - 0.5 + r));
    return;
  }
  auto index = [](float v) { return static_cast<int>(std::clamp(v, -4.f, 1e9f)); };  // any radius
  lo = index(std::ceil(p - 0.5f - r)) - 1, hi = index(std::floor(p - 0.5f + r)) + 1;
  for (int step = 0; step < 2; ++step) lo += !inside(p, r, lo), hi -= !inside(p, r, hi);
}

/// What one band does with the footprints of a sample (the parameters of the set-up in splatSameRadius).
struct Reach {
  float radius, lo, xHi, yHi;  ///< the radius; positions outside (lo, xHi) x (lo, yHi) reach no pixel
  int lastColumn, j0, lastRow;  ///< clamp of the footprints: columns [0, lastColumn], rows [j0, lastRow]
  int block, stride;            ///< n (footprints up to n x n go in a batch) and the band buffer's width
  bool weighted;                ///< SampleBuffer::areaWeighted: (w r, w g, w b, w) with w = FilmSample::weight
};

static_assert(sizeof(FilmSample) == 6 * sizeof(float) && offsetof(FilmSample, y) == sizeof(float) &&
                  offsetof(FilmSample, L) == 2 * sizeof(float),
              "setup8 reads FilmSample as 6 floats: x, y, L, weight");

/// centresWithin's bounds in double for 8 positions: first = ceil(p - 0.5 - r), last = floor(p - 0.5 + r).
[[gnu::target("avx2"), gnu::always_inline]] inline void bounds8(__m256 p, float radius, __m256i& first, __m256i& last) {
  const __m256d half = _mm256_set1_pd(0.5), r = _mm256_set1_pd(radius);
  const __m256d a = _mm256_sub_pd(_mm256_cvtps_pd(_mm256_castps256_ps128(p)), half);
  const __m256d z = _mm256_sub_pd(_mm256_cvtps_pd(_mm256_extractf128_ps(p, 1)), half);
  constexpr int up = _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC, down = _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC;
  first = _mm256_setr_m128i(_mm256_cvttpd_epi32(_mm256_round_pd(_mm256_sub_pd(a, r), up)),
                            _mm256_cvttpd_epi32(_mm256_round_pd(_mm256_sub_pd(z, r), up)));
  last = _mm256_setr_m128i(_mm256_cvttpd_epi32(_mm256_round_pd(_mm256_add_pd(a, r), down)),
                           _mm256_cvttpd_epi32(_mm256_round_pd(_mm256_add_pd(z, r), down)));
}

/// The set-up of 8 consecutive samples at once (AVX2), the scalar loop's operations lane by lane:
/// 0 = every one of them is skipped; 1 = all 8 go in the batch, written at b[count .. count + 7]; 2 = some
/// other mix (the caller takes them one by one). Only for footprints at |p| >= r + 2 on both axes,
/// where centresWithin computes the bounds in double.
[[gnu::target("avx2")]] int setup8(const FilmSample* q, Reach c, Batch& b, int count) {
  // (x, y) of each sample as one 64-bit load, then x and y apart (faster than two gathers)
  auto pair = [q](int s) {
    double v;
    std::memcpy(&v, &q[s].x, sizeof v);
    return v;
  };
  const __m256 p0 = _mm256_castpd_ps(_mm256_setr_pd(pair(0), pair(1), pair(2), pair(3)));  // x0 y0 x1 y1 x2 y2 x3 y3
  const __m256 p1 = _mm256_castpd_ps(_mm256_setr_pd(pair(4), pair(5), pair(6), pair(7)));
  // per 128-bit half: x0 x1 x4 x5 | x2 x3 x6 x7, then the 64-bit pieces in order
  const __m256 x = _mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(_mm256_shuffle_ps(p0, p1, 0x88)), 0xd8));
  const __m256 y = _mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(_mm256_shuffle_ps(p0, p1, 0xdd)), 0xd8));
  const __m256 lo = _mm256_set1_ps(c.lo);
  const __m256 in = _mm256_and_ps(
      _mm256_and_ps(_mm256_cmp_ps(x, lo, _CMP_GT_OQ), _mm256_cmp_ps(x, _mm256_set1_ps(c.xHi), _CMP_LT_OQ)),
      _mm256_and_ps(_mm256_cmp_ps(y, lo, _CMP_GT_OQ), _mm256_cmp_ps(y, _mm256_set1_ps(c.yHi), _CMP_LT_OQ)));
  const int inMask = _mm256_movemask_ps(in);
  if (inMask == 0) return 0;  // no position in range (NaN and inf fail too)
  if (inMask != 0xff) return 2;
  const __m256 absMask = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff)), near = _mm256_set1_ps(c.radius + 2);
  if (_mm256_movemask_ps(_mm256_or_ps(_mm256_cmp_ps(_mm256_and_ps(x, absMask), near, _CMP_LT_OQ),
                                      _mm256_cmp_ps(_mm256_and_ps(y, absMask), near, _CMP_LT_OQ))))
    return 2;  // near 0: centresWithin's float branch
  __m256i ilo, ihi, jlo, jhi;
  bounds8(x, c.radius, ilo, ihi), bounds8(y, c.radius, jlo, jhi);
  ilo = _mm256_max_epi32(ilo, _mm256_setzero_si256()), ihi = _mm256_min_epi32(ihi, _mm256_set1_epi32(c.lastColumn));
  jlo = _mm256_max_epi32(jlo, _mm256_set1_epi32(c.j0)), jhi = _mm256_min_epi32(jhi, _mm256_set1_epi32(c.lastRow));
  const int empty = _mm256_movemask_ps(
      _mm256_castsi256_ps(_mm256_or_si256(_mm256_cmpgt_epi32(ilo, ihi), _mm256_cmpgt_epi32(jlo, jhi))));
  if (empty == 0xff) return 0;  // none reaches a pixel of the band
  if (empty) return 2;
  const __m256i last = _mm256_set1_epi32(c.block - 1), spanX = _mm256_sub_epi32(ihi, ilo), spanY = _mm256_sub_epi32(jhi, jlo);
  if (_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_or_si256(_mm256_cmpgt_epi32(spanX, last), _mm256_cmpgt_epi32(spanY, last)))))
    return 2;  // wider than a block: on its own
  // radiance: (r, g, b, weight) of each sample, finite in r, g, b (finiteSample), stored as (r, g, b, 1), or
  // area-weighted as (w r, w g, w b, w) with a finite w
  __m128 L[8], bad = _mm_setzero_ps();
  for (int s = 0; s < 8; ++s) L[s] = _mm_loadu_ps(&q[s].L[0]), bad = _mm_or_ps(bad, _mm_sub_ps(L[s], L[s]));
  if (_mm_movemask_ps(_mm_cmpneq_ps(bad, _mm_setzero_ps())) & (c.weighted ? 15 : 7)) return 2;  // NaN or inf
  const __m128 one = _mm_set1_ps(1.f);
  for (int s = 0; s < 8; ++s) {
    const __m128 w = c.weighted ? _mm_shuffle_ps(L[s], L[s], 0xff) : one;
    _mm_storeu_ps(reinterpret_cast<float*>(&b.L[count + s]), _mm_blend_ps(_mm_mul_ps(L[s], w), w, 8));
  }
  _mm256_storeu_ps(b.x + count, x), _mm256_storeu_ps(b.y + count, y);
  const __m256 halfPixel = _mm256_set1_ps(0.5f);
  _mm256_storeu_ps(b.cx + count, _mm256_add_ps(_mm256_cvtepi32_ps(ilo), halfPixel));
  _mm256_storeu_ps(b.cy + count, _mm256_add_ps(_mm256_cvtepi32_ps(jlo), halfPixel));
  const __m256i at = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_sub_epi32(jlo, _mm256_set1_epi32(c.j0)),
                                                         _mm256_set1_epi32(c.stride)), ilo);
  const __m256i unit = _mm256_set1_epi32(1);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(b.at + count), at);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(b.nx + count), _mm256_add_epi32(spanX, unit));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(b.ny + count), _mm256_add_epi32(spanY, unit));
  return 1;
}

/// What every band of one radius's pass shares, set up once (makePass).
struct RadiusPass {
  const SampleBuffer& samples;
  const SplatTargets& targets;
  std::vector<FilterBatch> weights;  ///< each filter's vectorised weights
  std::vector<int> reachLo, reachHi;  ///< per source row: the output rows its samples can reach (wider by one)
  float r;
  int n;               ///< block size; > kMaxBlock: sample by sample
  int pad, width;      ///< band buffer's padding (n, or 0) and width W + pad
  size_t bandSize;     ///< Sums per filter's band buffer
  Kernel kernel;
  PairKernel pair;     ///< two weighted filters at once (null: kernel twice)
  bool vectorSetup;    ///< setup8 where the CPU has AVX2 (r <= 8: centresWithin's bounds fit)
};

RadiusPass makePass(const SampleBuffer& samples, const RowSpans& spans, const SplatTargets& targets) {
  const int W = samples.width(), H = samples.height();
  const float r = targets.filters[0]->radius();
  const int n = static_cast<int>(std::clamp(std::ceil(2 * r), 1.f, kMaxBlock + 1.f));
  const int pad = n <= kMaxBlock ? n : 0;
  RadiusPass pass{samples, targets, {}, std::vector<int>(H), std::vector<int>(H), r, n, pad, W + pad,
                  static_cast<size_t>(kBand + pad) * (W + pad), pickKernel(n), pickPairKernel(n),
                  cpuFeatures().avx2 && n <= kMaxBlock};
  for (const Filter* f : targets.filters) pass.weights.emplace_back(*f);
  for (int sj = 0; sj < H; ++sj) {
    pass.reachLo[sj] = static_cast<int>(std::clamp(spans.ymin[sj] - r - 1, -1.f, float(H))) - 1;
    pass.reachHi[sj] = static_cast<int>(std::clamp(spans.ymax[sj] + r + 1, -1.f, float(H)));
  }
  return pass;
}

/// Band `band`'s sums into the image's, each band buffer left zero for the next band (read and cleared in one
/// pass, then the padding the blocks reached beyond the band's rows and columns).
void addBandToImage(const RadiusPass& pass, int band, Workspace& space) {
  const int W = pass.samples.width(), j0 = band * kBand, j1 = std::min(pass.samples.height(), j0 + kBand);
  const int width = pass.width;
  for (size_t f = 0; f < pass.targets.filters.size(); ++f) {
    Sum* buffer = space.buffer.data() + f * pass.bandSize;
    for (int j = j0; j < j1; ++j) {
      Sum* line = buffer + static_cast<size_t>(j - j0) * width;
      for (int i = 0; i < W; ++i) {  // (sums need not be aligned for V4)
        double* sum = pass.targets.sums[f] + 4 * (static_cast<size_t>(j) * W + i);
        V4 v = {};  // overwrite: 0.0 + the band's sum, as if sum had been zeroed (it is not read)
        if (!pass.targets.overwrite) std::memcpy(&v, sum, sizeof v);
        v += line[i].v;
        std::memcpy(sum, &v, sizeof v);
        line[i] = Sum{};
      }
      std::fill(line + W, line + width, Sum{});
    }
    std::fill(buffer + static_cast<size_t>(j1 - j0) * width, buffer + pass.bandSize, Sum{});
  }
}

/// Band `band` of the pass: the samples of every source row that can reach it, set up one by one or 8 at a
/// time into batches, each filter's weights and kernel run on every full batch, into the work space's band
/// buffers. own (if not null, K entries, added to): each filter's seconds.
void splatBand(const RadiusPass& pass, int band, Workspace& space, double* own) {
  const SampleBuffer& samples = pass.samples;
  const std::vector<const Filter*>& filters = pass.targets.filters;
  const int W = samples.width(), H = samples.height(), K = static_cast<int>(filters.size());
  const int n = pass.n, width = pass.width;
  const Kernel kernel = pass.kernel;
  const PairKernel pair = pass.pair;
  const bool vectorSetup = pass.vectorSetup;
  const int j0 = band * kBand, j1 = std::min(H, j0 + kBand);
  auto buffer = [&](int f) { return space.buffer.data() + f * pass.bandSize; };
  std::vector<float>& w = space.w;
  Batch& b = space.batch;
  int count = 0;
  // each filter's own work on the batch: its weights (none for unitWeights) and the accumulation
  auto flush = [&] {
    if (!count) return;
    for (int s = count; s < kBatch; ++s) b.x[s] = b.y[s] = b.cx[s] = b.cy[s] = 0;
    auto t0 = own ? Clock::now() : Clock::time_point();
    auto lap = [&](int f, int g = -1) {  // the time since the last lap: to filter f, or half each to f and g
      if (!own) return;
      const auto t1 = Clock::now();
      const double seconds = std::chrono::duration<double>(t1 - t0).count();
      if (g < 0) own[f] += seconds;
      else own[f] += seconds / 2, own[g] += seconds / 2;
      t0 = t1;
    };
    float* const w1 = w.data() + w.size() / 2;  // the second filter's weights of a pair
    for (int f = 0; f < K; ++f) {
      const bool unit = pass.weights[f].unitWeights();
      if (pair && !unit && f + 1 < K && !pass.weights[f + 1].unitWeights()) {  // two filters at once
        pass.weights[f].eval(kBatch, b.x, b.y, b.cx, b.cy, n, w.data()), lap(f);
        pass.weights[f + 1].eval(kBatch, b.x, b.y, b.cx, b.cy, n, w1), lap(f + 1);
        pair(b, count, w.data(), w1, BandBuffer{buffer(f), width, n}, BandBuffer{buffer(f + 1), width, n});
        lap(f, f + 1), ++f;
        continue;
      }
      if (!unit) pass.weights[f].eval(kBatch, b.x, b.y, b.cx, b.cy, n, w.data());
      kernel(b, count, unit ? nullptr : w.data(), BandBuffer{buffer(f), width, n});
      lap(f);
    }
    count = 0;
  };
  // (a local copy, passed to setup8 by value: captured values would be reloaded after every store into
  // the batch)
  const Reach c{pass.r, -pass.r - 1, W + pass.r + 1, H + pass.r + 1, W - 1, j0, j1 - 1, pass.pad, width,
                samples.areaWeighted()};
  for (int sj = 0; sj < H; ++sj) {
    if (pass.reachHi[sj] < j0 || pass.reachLo[sj] >= j1) continue;
    const FilmSample* row = samples.pixel(0, sj);
    const size_t rowSamples = samples.rowCount(sj);
    size_t k = 0, next = 0;  // next: where the 8-sample set-up may go on (after a group taken one by one)
    for (; k < rowSamples; ++k) {
      if (vectorSetup && k == next && k + 8 <= rowSamples) {
        if (count > kBatch - 8) flush();
        const int status = setup8(row + k, c, b, count);
        if (status != 2) {  // all 8 skipped or all 8 in the batch
          if (status == 1 && (count += 8) == kBatch) flush();
          k += 7, next = k + 1;
          continue;
        }
        next = k + 8;  // these 8 one by one
      }
      const FilmSample& q = row[k];
      if (!finiteSample(q) || !(q.x > c.lo && q.x < c.xHi && q.y > c.lo && q.y < c.yHi)) continue;
      if (c.weighted && !std::isfinite(q.weight)) continue;
      int ilo, ihi, jlo, jhi;
      centresWithin(q.x, c.radius, ilo, ihi), centresWithin(q.y, c.radius, jlo, jhi);
      ilo = std::max(ilo, 0), ihi = std::min(ihi, c.lastColumn), jlo = std::max(jlo, c.j0), jhi = std::min(jhi, c.lastRow);
      if (ilo > ihi || jlo > jhi) continue;
      const float qw = c.weighted ? q.weight : 1.f;
      const F4 L = {qw * q.L[0], qw * q.L[1], qw * q.L[2], qw};
      if (ihi - ilo >= c.block || jhi - jlo >= c.block) {  // wider than a block: on its own, in sample order
        flush();
        for (int f = 0; f < K; ++f)
          for (int j = jlo; j <= jhi; ++j)
            for (int i = ilo; i <= ihi; ++i)
              buffer(f)[(j - j0) * width + i].v +=
                  static_cast<double>(filters[f]->eval(q.x - (static_cast<float>(i) + 0.5f),
                                                       q.y - (static_cast<float>(j) + 0.5f))) *
                  __builtin_convertvector(L, V4);
        continue;
      }
      b.x[count] = q.x, b.y[count] = q.y, b.cx[count] = static_cast<float>(ilo) + 0.5f;
      b.cy[count] = static_cast<float>(jlo) + 0.5f, b.at[count] = (jlo - j0) * c.stride + ilo, b.L[count] = L;
      b.nx[count] = ihi - ilo + 1, b.ny[count] = jhi - jlo + 1;
      if (++count == kBatch) flush();
    }
  }
  flush();
}

}  // namespace

/// The fused pass for filters that share one radius (see splatAll): per band, splatBand then addBandToImage.
void splatSameRadius(const SampleBuffer& samples, const RowSpans& spans, const SplatTargets& targets, int threads) {
  const RadiusPass pass = makePass(samples, spans, targets);
  const int K = static_cast<int>(targets.filters.size()), bands = (samples.height() + kBand - 1) / kBand;
  double* ownSeconds = targets.ownSeconds;
  std::vector<double> ownBand(ownSeconds ? static_cast<size_t>(bands) * K : 0, 0.0);  // per band: no races
  const size_t weights = (pass.pair ? 2 : 1) * static_cast<size_t>(pass.pad) * pass.pad * kBatch;  // a pair: two
  WorkspacePool pool(K * pass.bandSize, weights);
  parallelFor(bands, threads, [&](int band) {
    std::unique_ptr<Workspace> space = pool.take();
    splatBand(pass, band, *space, ownSeconds ? &ownBand[static_cast<size_t>(band) * K] : nullptr);
    addBandToImage(pass, band, *space);
    pool.give(std::move(space));
  });
  if (ownSeconds)
    for (int band = 0; band < bands; ++band)
      for (int f = 0; f < K; ++f) ownSeconds[f] += ownBand[static_cast<size_t>(band) * K + f];
}

}  // namespace aliaslab::filmimpl
