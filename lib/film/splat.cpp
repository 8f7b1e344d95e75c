// The fast weighted average. Per output band of kBand rows (the parallel
// work item), the samples of every source row that can reach the band, in
// memory order, in batches: one Filter::evalBatch call per batch (vectorised
// across samples) gives each sample's weights over the n x n pixel centres
// from its footprint's first column and row, n = ceil(2r) (a footprint at a
// generic position; the weights are zero beyond the support), then a 4-lane
// (r, g, b, 1) x w accumulation in double into a band buffer padded by n
// columns and rows, so the blocks are never clipped. The products are exact
// (float x float in double), so the AVX2 + FMA kernel, chosen once when the
// CPU has it, sums bit for bit like the SSE one. A sample whose footprint is
// wider than n (on a pixel boundary) is added on its own with eval(). The
// band is then added to the image's sums: every pixel's sum runs in sample
// order, for any thread count. Filters of one radius share the pass (one
// footprint per sample, one batch, then each filter's weights and
// accumulation into its own band buffer), which is what makes one more
// filter cheap in a sweep or a reference.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <new>
#include <utility>
#include <vector>

#include <sys/mman.h>

#include "core/parallel.h"
#include "film/film_impl.h"

namespace aliaslab::filmimpl {
namespace {

constexpr int kBatch = 128;  // samples per Filter::evalBatch call (a multiple of 4)
using Clock = std::chrono::steady_clock;
constexpr int kMaxBlock = 16; // largest n x n block (r <= 8); wider footprints sample by sample

/// (r, g, b, weight) in double: one AVX register, two SSE ones (aligned to 32 also without AVX).
using V4 = double __attribute__((vector_size(32)));
using F4 = float __attribute__((vector_size(16)));
struct alignas(32) Sum {
  V4 v = {};
};

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

/// n zeroed Sums in pages of their own, returned to the system when destroyed. The band buffers of a
/// fused pass (K at once per thread) held through the heap raised a 256 x 256 reference's peak by 4-9 MB:
/// glibc kept the freed blocks (results/study_speed.md).
class SumPages {
 public:
  explicit SumPages(size_t n) : n_(n), bytes_(std::max<size_t>(n * sizeof(Sum), 1)) {
    void* p = ::mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    data_ = static_cast<Sum*>(p);
    std::uninitialized_value_construct_n(data_, n);
  }
  SumPages(const SumPages&) = delete;
  SumPages& operator=(const SumPages&) = delete;
  ~SumPages() { ::munmap(data_, bytes_); }
  Sum* data() { return data_; }
  void clear() { std::fill(data_, data_ + n_, Sum{}); }

 private:
  size_t n_, bytes_;
  Sum* data_ = nullptr;
};

/// Samples waiting for one evalBatch call (padded to a multiple of 4).
struct Batch {
  alignas(16) float x[kBatch], y[kBatch], cx[kBatch], cy[kBatch];  ///< position, first pixel centre
  int at[kBatch];                                                   ///< first pixel's index in the band buffer
  int nx[kBatch], ny[kBatch];                                       ///< footprint columns and rows (<= n)
  F4 L[kBatch];                                                     ///< (r, g, b, 1)
};

/// buffer[at + b * width + a] += w(a, b) L for every sample of the batch (N: n known at compile time, 0: any),
/// w(a, b) = w[(b * n + a) * kBatch + s].
template <int N>
inline __attribute__((always_inline)) void accumulate(const Batch& batch, int count, const float* w, int n,
                                                      Sum* buffer, int width) {
  if (N) n = N;
  constexpr size_t stride = kBatch;  // evalBatch is always called for a whole batch: constant offsets
  for (int s = 0; s < count; ++s) {
    Sum* block = buffer + batch.at[s];
    const V4 L = __builtin_convertvector(batch.L[s], V4);
#pragma GCC unroll 8
    for (int b = 0; b < n; ++b)
#pragma GCC unroll 8
      for (int a = 0; a < n; ++a) block[b * width + a].v += static_cast<double>(w[(b * n + a) * stride + s]) * L;
  }
}
/// The same for Filter::unitWeights: w = 1 on the footprint's nx x ny pixels, 0 beyond (no weights read).
template <int N>
inline __attribute__((always_inline)) void accumulateUnit(const Batch& batch, int count, int n, Sum* buffer, int width) {
  if (N) n = N;
  for (int s = 0; s < count; ++s) {
    Sum* block = buffer + batch.at[s];
    const V4 L = __builtin_convertvector(batch.L[s], V4);
    V4 column[N ? N : kMaxBlock];  // L on the footprint's columns, 0 beyond
#pragma GCC unroll 8
    for (int a = 0; a < n; ++a) column[a] = L * static_cast<double>(a < batch.nx[s]);
#pragma GCC unroll 8
    for (int b = 0; b < n; ++b) {
      const double inRow = b < batch.ny[s];
#pragma GCC unroll 8
      for (int a = 0; a < n; ++a) block[b * width + a].v += column[a] * inRow;
    }
  }
}
template <int N>
__attribute__((target("avx2,fma"))) void accumulateAvx2(const Batch& b, int count, const float* w, int n, Sum* buf, int width) {
  w ? accumulate<N>(b, count, w, n, buf, width) : accumulateUnit<N>(b, count, n, buf, width);
}
template <int N>
void accumulateSse(const Batch& b, int count, const float* w, int n, Sum* buf, int width) {
  w ? accumulate<N>(b, count, w, n, buf, width) : accumulateUnit<N>(b, count, n, buf, width);
}

using Kernel = void (*)(const Batch&, int, const float*, int, Sum*, int);
/// The kernel for blocks of n x n (weights w, or none: unitWeights): unrolled for n <= 6, AVX2 when the CPU has it.
template <int... Ns>
Kernel pickKernel(int n, bool allowAvx2, std::integer_sequence<int, Ns...>) {
  static const bool cpuAvx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  const bool avx2 = cpuAvx2 && allowAvx2;
  Kernel k = avx2 ? accumulateAvx2<0> : accumulateSse<0>;
  ((k = n == Ns + 1 ? (avx2 ? accumulateAvx2<Ns + 1> : accumulateSse<Ns + 1>) : k), ...);
  return k;
}

}  // namespace

size_t addPlainSums(const SampleBuffer& samples, double* plain) {
  const int spp = samples.spp();
  size_t skipped = 0;
  for (int j = 0; j < samples.height(); ++j)
    for (int i = 0; i < samples.width(); ++i) {
      const FilmSample* s = samples.pixel(i, j);
      double* p = plain + 4 * (static_cast<size_t>(j) * samples.width() + i);
      for (int k = 0; k < spp; ++k)
        if (finiteSample(s[k])) p[0] += s[k].L[0], p[1] += s[k].L[1], p[2] += s[k].L[2], p[3] += 1;
        else ++skipped;
    }
  return skipped;
}

namespace {

/// A thread's work space in a pass: K band buffers one after the other, the weights, a batch.
struct Workspace {
  Workspace(size_t sums, size_t weights) : buffer(sums), w(weights) {}
  SumPages buffer;
  std::vector<float> w;
  Batch batch;
};

/// Work spaces of one size reused from band to band within one pass: at most one per thread. (Kept from
/// radius to radius, they raised a 256 x 256 reference's peak by 2.3 MB: results/study_speed.md.)
class WorkspacePool {
 public:
  WorkspacePool(size_t sums, size_t weights) : sums_(sums), weights_(weights) {}
  /// A work space with zeroed sums.
  std::unique_ptr<Workspace> take() {
    std::unique_ptr<Workspace> space;
    {
      std::lock_guard lock(mutex_);
      if (!free_.empty()) space = std::move(free_.back()), free_.pop_back();
    }
    if (!space) return std::make_unique<Workspace>(sums_, weights_);
    space->buffer.clear();
    return space;
  }
  void give(std::unique_ptr<Workspace> space) {
    std::lock_guard lock(mutex_);
    free_.push_back(std::move(space));
  }

 private:
  size_t sums_, weights_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<Workspace>> free_;
};

/// Per source row (the samples of one row of pixels): the least and greatest y (NaN ignored).
struct RowSpans {
  std::vector<float> ymin, ymax;
};

/// The fused pass for filters that share one radius (see splatAll).
void splatSameRadius(const SampleBuffer& samples, const RowSpans& spans, const std::vector<const Filter*>& filters,
                     const std::vector<double*>& sums, int threads, bool allowAvx2, double* ownSeconds) {
  const int W = samples.width(), H = samples.height(), K = static_cast<int>(filters.size());
  const size_t rowSamples = static_cast<size_t>(W) * samples.spp();
  const float r = filters[0]->radius();
  const int n = static_cast<int>(std::clamp(std::ceil(2 * r), 1.f, kMaxBlock + 1.f));  // > kMaxBlock: sample by sample
  const Kernel kernel = pickKernel(n, allowAvx2, std::make_integer_sequence<int, 6>());

  // per source row: the output rows its samples can reach (wider by one)
  std::vector<int> reachLo(H), reachHi(H);
  for (int sj = 0; sj < H; ++sj) {
    reachLo[sj] = static_cast<int>(std::clamp(spans.ymin[sj] - r - 1, -1.f, float(H))) - 1;
    reachHi[sj] = static_cast<int>(std::clamp(spans.ymax[sj] + r + 1, -1.f, float(H)));
  }

  const int bands = (H + kBand - 1) / kBand, pad = n <= kMaxBlock ? n : 0, width = W + pad;
  const size_t bandSize = static_cast<size_t>(kBand + pad) * width;
  std::vector<double> ownBand(ownSeconds ? static_cast<size_t>(bands) * K : 0, 0.0);  // per band: no races
  WorkspacePool pool(K * bandSize, static_cast<size_t>(pad) * pad * kBatch);
  parallelFor(bands, threads, [&](int band) {
    const int j0 = band * kBand, j1 = std::min(H, j0 + kBand);
    std::unique_ptr<Workspace> space = pool.take();
    auto buffer = [&](int f) { return space->buffer.data() + f * bandSize; };
    std::vector<float>& w = space->w;
    double* own = ownSeconds ? &ownBand[static_cast<size_t>(band) * K] : nullptr;
    Batch& b = space->batch;
    int count = 0;
    // each filter's own work on the batch: its weights (none for unitWeights) and the accumulation
    auto flush = [&] {
      if (!count) return;
      for (int s = count; s < kBatch; ++s) b.x[s] = b.y[s] = b.cx[s] = b.cy[s] = 0;
      auto t0 = own ? Clock::now() : Clock::time_point();
      for (int f = 0; f < K; ++f) {
        const bool unit = filters[f]->unitWeights();
        if (!unit) filters[f]->evalBatch(kBatch, b.x, b.y, b.cx, b.cy, n, w.data());
        kernel(b, count, unit ? nullptr : w.data(), n, buffer(f), width);
        if (own) {
          const auto t1 = Clock::now();
          own[f] += std::chrono::duration<double>(t1 - t0).count(), t0 = t1;
        }
      }
      count = 0;
    };
    // (local copies: the captured ones would be reloaded after every store into the batch)
    const float radius = r, lo = -r - 1, xHi = W + r + 1, yHi = H + r + 1;
    const int lastColumn = W - 1, lastRow = j1 - 1, block = pad, stride = width;
    for (int sj = 0; sj < H; ++sj) {
      if (reachHi[sj] < j0 || reachLo[sj] >= j1) continue;
      const FilmSample* row = samples.pixel(0, sj);
      for (size_t k = 0; k < rowSamples; ++k) {
        const FilmSample& q = row[k];
        if (!finiteSample(q) || !(q.x > lo && q.x < xHi && q.y > lo && q.y < yHi)) continue;
        int ilo, ihi, jlo, jhi;
        centresWithin(q.x, radius, ilo, ihi), centresWithin(q.y, radius, jlo, jhi);
        ilo = std::max(ilo, 0), ihi = std::min(ihi, lastColumn), jlo = std::max(jlo, j0), jhi = std::min(jhi, lastRow);
        if (ilo > ihi || jlo > jhi) continue;
        const F4 L = {q.L[0], q.L[1], q.L[2], 1.f};
        if (ihi - ilo >= block || jhi - jlo >= block) {  // wider than a block: on its own, in sample order
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
        b.cy[count] = static_cast<float>(jlo) + 0.5f, b.at[count] = (jlo - j0) * stride + ilo, b.L[count] = L;
        b.nx[count] = ihi - ilo + 1, b.ny[count] = jhi - jlo + 1;
        if (++count == kBatch) flush();
      }
    }
    flush();
    for (int f = 0; f < K; ++f)
      for (int j = j0; j < j1; ++j)
        for (int i = 0; i < W; ++i) {  // (sums need not be aligned for V4)
          double* sum = sums[f] + 4 * (static_cast<size_t>(j) * W + i);
          V4 v;
          std::memcpy(&v, sum, sizeof v);
          v += buffer(f)[(j - j0) * width + i].v;
          std::memcpy(sum, &v, sizeof v);
        }
    pool.give(std::move(space));
  });
  if (ownSeconds)
    for (int band = 0; band < bands; ++band)
      for (int f = 0; f < K; ++f) ownSeconds[f] += ownBand[static_cast<size_t>(band) * K + f];
}

}  // namespace

void splatAll(const SampleBuffer& samples, const std::vector<const Filter*>& filters, const std::vector<double*>& sums,
              int threads, double* ownSeconds, bool allowAvx2) {
  const int H = samples.height();
  const size_t rowSamples = static_cast<size_t>(samples.width()) * samples.spp();
  RowSpans spans{std::vector<float>(H), std::vector<float>(H)};
  parallelFor(H, threads, [&](int sj) {
    float ymin = kInf, ymax = -kInf;
    const FilmSample* row = samples.pixel(0, sj);
    for (size_t k = 0; k < rowSamples; ++k) ymin = std::min(ymin, row[k].y), ymax = std::max(ymax, row[k].y);
    spans.ymin[sj] = ymin, spans.ymax[sj] = ymax;
  });
  std::vector<bool> done(filters.size(), false);
  for (size_t first = 0; first < filters.size(); ++first) {
    if (done[first]) continue;
    std::vector<const Filter*> group;
    std::vector<double*> groupSums;
    std::vector<size_t> index;
    for (size_t k = first; k < filters.size(); ++k)
      if (!done[k] && filters[k]->radius() == filters[first]->radius())
        group.push_back(filters[k]), groupSums.push_back(sums[k]), index.push_back(k), done[k] = true;
    std::vector<double> own(group.size(), 0.0);
    splatSameRadius(samples, spans, group, groupSums, threads, allowAvx2, ownSeconds ? own.data() : nullptr);
    if (ownSeconds)
      for (size_t g = 0; g < group.size(); ++g) ownSeconds[index[g]] += own[g];
  }
}

void splatWeighted(const SampleBuffer& samples, const Filter& filter, double* sums, int threads, bool allowAvx2) {
  splatAll(samples, {&filter}, {sums}, threads, nullptr, allowAvx2);
}

}  // namespace aliaslab::filmimpl
