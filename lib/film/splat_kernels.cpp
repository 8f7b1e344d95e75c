// The splat's accumulation kernels: a batch's (r, g, b, 1) x w added over n x n blocks of a band buffer, in
// runs for n <= 2, unrolled for n <= 6, in SSE and in AVX2 + FMA builds (the same sums bit for bit), and the
// choice among them (pickKernel); for SplatPath::Runs, the kernels over a batch in first-pixel order with double weights,
// every run of equal first pixels in registers (pickRunKernel). Called through a pointer from the pass in
// splat_pass.cpp.
#include <cstddef>
#include <utility>

#include <immintrin.h>

#include "film/splat_impl.h"

namespace aliaslab::filmimpl {
namespace {

/// For n = N <= 2: add(sum, p, t, L_t) adds sample t's contribution to the sum of pixel p (row-major in the
/// N x N block), for every pixel and sample, run by run. A run is the samples with the same first pixel (a
/// pixel's samples at small radii); it adds into registers: each pixel's sum is loaded once, takes the run's
/// contributions in sample order and is stored once. The same additions as one sample at a time, without
/// the store-to-load round trip that chained them (measured: a third less time at n = 1; larger blocks
/// gained nothing).
template <int N, class Add>
inline __attribute__((always_inline)) void addRuns(const Batch& batch, int count, Sum* buffer, int width,
                                                   Add&& add) {
  for (int s = 0; s < count;) {
    int e = s + 1;
    while (e < count && batch.at[e] == batch.at[s]) ++e;
    Sum* block = buffer + batch.at[s];
    V4 acc[N * N];
#pragma GCC unroll 4
    for (int p = 0; p < N * N; ++p) acc[p] = block[(p / N) * width + p % N].v;
    for (int t = s; t < e; ++t) {
      const V4 L = __builtin_convertvector(batch.L[t], V4);
#pragma GCC unroll 4
      for (int p = 0; p < N * N; ++p) add(acc[p], p, t, L);
    }
#pragma GCC unroll 4
    for (int p = 0; p < N * N; ++p) block[(p / N) * width + p % N].v = acc[p];
    s = e;
  }
}

/// SplatPath::Runs for n = N <= 6 over a batch in the order of its first pixels (Batch::order), run by run
/// (the samples with the same first pixel) and block row by block row: each row's N sums are loaded once per run and stored once, and
/// take the run's contributions w(a, b, t) L_t (L_t from Batch::LD) in S interleaved partial sums (samples
/// t = s, s + S, ... in the first, s + 1, s + S + 1, ... in the next), which are then added in that order:
/// independent chains of additions instead of one chain per pixel. w(a, b, t) = wd[(b * N + a) * kBatch + t]
/// (the float weights in double: each product exact, so the FMA of the AVX2 build rounds like the SSE
/// build's multiply and add), or 1 on the footprint (unit weights, wd null).
template <int N>
inline __attribute__((always_inline)) void accumulateRuns(const Batch& batch, int count, const double* wd,
                                                          Sum* buffer, int width) {
  constexpr size_t stride = kBatch;
  constexpr int S = N <= 2 ? 4 : 2;
  auto weight = [&](int a, int b, int t) __attribute__((always_inline)) {
    const int q = batch.order[t];
    return wd ? wd[(b * N + a) * stride + q]
              : static_cast<double>(a < batch.nx[q]) * static_cast<double>(b < batch.ny[q]);
  };
  for (int s = 0; s < count;) {
    int e = s + 1;
    while (e < count && batch.sortedAt[e] == batch.sortedAt[s]) ++e;
    Sum* block = buffer + batch.sortedAt[s];
    for (int b = 0; b < N; ++b) {
      Sum* line = block + b * width;
      V4 acc[S][N];
#pragma GCC unroll 8
      for (int a = 0; a < N; ++a) {
        acc[0][a] = line[a].v;
#pragma GCC unroll 4
        for (int k = 1; k < S; ++k) acc[k][a] = V4{};
      }
      int t = s;
      for (; t + S <= e; t += S)
#pragma GCC unroll 4
        for (int k = 0; k < S; ++k)
#pragma GCC unroll 8
          for (int a = 0; a < N; ++a) acc[k][a] += weight(a, b, t + k) * batch.LD[t + k].v;
      for (int k = 0; t < e; ++t, ++k)
#pragma GCC unroll 8
        for (int a = 0; a < N; ++a) acc[k][a] += weight(a, b, t) * batch.LD[t].v;
#pragma GCC unroll 8
      for (int a = 0; a < N; ++a) {
        V4 sum = acc[0][a];
#pragma GCC unroll 4
        for (int k = 1; k < S; ++k) sum += acc[k][a];
        line[a].v = sum;
      }
    }
    s = e;
  }
}

/// buffer[at + b * width + a] += w(a, b) L for every sample of the batch (N: n known at compile time, 0: any),
/// w(a, b) = w[(b * n + a) * kBatch + s]; in runs for n <= 2 (addRuns).
template <int N>
inline __attribute__((always_inline)) void accumulate(const Batch& batch, int count, const float* w, int n,
                                                      Sum* buffer, int width) {
  constexpr size_t stride = kBatch;  // FilterBatch::eval is always called for a whole batch: constant offsets
  if constexpr (N == 1 || N == 2) {
    addRuns<N>(batch, count, buffer, width, [w](V4& sum, int p, int t, const V4& L) __attribute__((always_inline)) {
      sum += static_cast<double>(w[p * stride + t]) * L;
    });
  } else {  // larger blocks: enough independent sums per sample
    if (N) n = N;
    for (int s = 0; s < count; ++s) {
      Sum* block = buffer + batch.at[s];
      const V4 L = __builtin_convertvector(batch.L[s], V4);
#pragma GCC unroll 8
      for (int b = 0; b < n; ++b)
#pragma GCC unroll 8
        for (int a = 0; a < n; ++a) block[b * width + a].v += static_cast<double>(w[(b * n + a) * stride + s]) * L;
    }
  }
}
/// The same for FilterBatch::unitWeights: w = 1 on the footprint's nx x ny pixels, 0 beyond (no weights read).
template <int N>
inline __attribute__((always_inline)) void accumulateUnit(const Batch& batch, int count, int n, Sum* buffer, int width) {
  if constexpr (N == 1 || N == 2) {
    addRuns<N>(batch, count, buffer, width, [&batch](V4& sum, int p, int t, const V4& L) __attribute__((always_inline)) {
      sum += L * static_cast<double>(p % N < batch.nx[t]) * static_cast<double>(p / N < batch.ny[t]);
    });
  } else {
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
}
template <int N>
__attribute__((target("avx2,fma"))) void accumulateAvx2(const Batch& b, int count, const float* w, int n, Sum* buf, int width) {
  w ? accumulate<N>(b, count, w, n, buf, width) : accumulateUnit<N>(b, count, n, buf, width);
}
template <int N>
void accumulateSse(const Batch& b, int count, const float* w, int n, Sum* buf, int width) {
  w ? accumulate<N>(b, count, w, n, buf, width) : accumulateUnit<N>(b, count, n, buf, width);
}

template <int N>
__attribute__((target("avx2,fma"))) void runsAvx2(const Batch& b, int count, const double* wd, Sum* buf, int width) {
  accumulateRuns<N>(b, count, wd, buf, width);
}
template <int N>
void runsSse(const Batch& b, int count, const double* wd, Sum* buf, int width) {
  accumulateRuns<N>(b, count, wd, buf, width);
}

/// pickKernel for n among Ns + 1 (unrolled), else the kernel for any n.
template <int... Ns>
Kernel pickKernelOf(int n, bool allowAvx2, std::integer_sequence<int, Ns...>) {
  static const bool cpuAvx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  const bool avx2 = cpuAvx2 && allowAvx2;
  Kernel k = avx2 ? accumulateAvx2<0> : accumulateSse<0>;
  ((k = n == Ns + 1 ? (avx2 ? accumulateAvx2<Ns + 1> : accumulateSse<Ns + 1>) : k), ...);
  return k;
}

}  // namespace

Kernel pickKernel(int n, bool allowAvx2) { return pickKernelOf(n, allowAvx2, std::make_integer_sequence<int, 6>()); }

namespace {
[[gnu::target("avx2")]] void widenAvx2(const float* w, double* wd, size_t count) {
  size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    const __m256 v = _mm256_loadu_ps(w + i);
    _mm256_storeu_pd(wd + i, _mm256_cvtps_pd(_mm256_castps256_ps128(v)));
    _mm256_storeu_pd(wd + i + 4, _mm256_cvtps_pd(_mm256_extractf128_ps(v, 1)));
  }
  for (; i < count; ++i) wd[i] = w[i];
}
void widenSse(const float* w, double* wd, size_t count) {
  size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    const __m128 v = _mm_loadu_ps(w + i);
    _mm_storeu_pd(wd + i, _mm_cvtps_pd(v)), _mm_storeu_pd(wd + i + 2, _mm_cvtps_pd(_mm_movehl_ps(v, v)));
  }
  for (; i < count; ++i) wd[i] = w[i];
}
}  // namespace

void widenWeights(const float* w, double* wd, int n, int count, bool allowAvx2) {
  static const bool cpuAvx2 = __builtin_cpu_supports("avx2");
  const size_t used = static_cast<size_t>(count + 7) & ~size_t(7);  // each weight's first samples, in 8s
  for (int p = 0; p < n * n; ++p) {
    const size_t at = static_cast<size_t>(p) * kBatch;
    cpuAvx2 && allowAvx2 ? widenAvx2(w + at, wd + at, used) : widenSse(w + at, wd + at, used);
  }
}

RunKernel pickRunKernel(int n, bool allowAvx2) {
  static const bool cpuAvx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  const bool avx2 = cpuAvx2 && allowAvx2;
  constexpr RunKernel avx2Kernels[] = {runsAvx2<1>, runsAvx2<2>, runsAvx2<3>, runsAvx2<4>, runsAvx2<5>, runsAvx2<6>};
  constexpr RunKernel sseKernels[] = {runsSse<1>, runsSse<2>, runsSse<3>, runsSse<4>, runsSse<5>, runsSse<6>};
  if (n < 1 || n > kMaxRunBlock) return nullptr;
  return avx2 ? avx2Kernels[n - 1] : sseKernels[n - 1];
}

}  // namespace aliaslab::filmimpl
