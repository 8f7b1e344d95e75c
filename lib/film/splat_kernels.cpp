// The splat's accumulation kernels: a batch's (r, g, b, 1) x w added over n x n blocks of a band buffer, in
// runs for n <= 2, unrolled for n <= 6, in SSE and in AVX2 + FMA builds (the same sums bit for bit), the AVX2
// kernels for two filters at once (pairAvx2), and the choice among them (pickKernel, pickPairKernel). Called
// through pointers from the pass in splat_pass.cpp.
#include <cstddef>
#include <utility>

#include <immintrin.h>

#include "core/cpu.h"
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
inline __attribute__((always_inline)) void addRuns(const Batch& batch, int count, BandBuffer band, Add&& add) {
  Sum* const buffer = band.sums;
  const int width = band.width;
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

/// buffer[at + b * width + a] += w(a, b) L for every sample of the batch (N: n known at compile time, 0: any),
/// w(a, b) = w[(b * n + a) * kBatch + s]; in runs for n <= 2 (addRuns).
template <int N>
inline __attribute__((always_inline)) void accumulate(const Batch& batch, int count, const float* w,
                                                      BandBuffer band) {
  constexpr size_t stride = kBatch;  // FilterBatch::eval is always called for a whole batch: constant offsets
  if constexpr (N == 1 || N == 2) {
    addRuns<N>(batch, count, band, [w](V4& sum, int p, int t, const V4& L) __attribute__((always_inline)) {
      sum += static_cast<double>(w[p * stride + t]) * L;
    });
  } else {  // larger blocks: enough independent sums per sample
    Sum* const buffer = band.sums;
    const int width = band.width, n = N ? N : band.n;
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
inline __attribute__((always_inline)) void accumulateUnit(const Batch& batch, int count, BandBuffer band) {
  if constexpr (N == 1 || N == 2) {
    addRuns<N>(batch, count, band, [&batch](V4& sum, int p, int t, const V4& L) __attribute__((always_inline)) {
      sum += L * static_cast<double>(p % N < batch.nx[t]) * static_cast<double>(p / N < batch.ny[t]);
    });
  } else {
    Sum* const buffer = band.sums;
    const int width = band.width, n = N ? N : band.n;
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
__attribute__((target("avx2,fma"))) void accumulateAvx2(const Batch& b, int count, const float* w, BandBuffer band) {
  w ? accumulate<N>(b, count, w, band) : accumulateUnit<N>(b, count, band);
}
template <int N>
void accumulateSse(const Batch& b, int count, const float* w, BandBuffer band) {
  w ? accumulate<N>(b, count, w, band) : accumulateUnit<N>(b, count, band);
}

/// Two filters' accumulate<N> at once (AVX2 + FMA, 2 <= N <= 6): sample by sample, w0 into band0 then w1 into
/// band1. Each sum takes the same additions in the same order as accumulate<N> gives it; what changes is that
/// consecutive samples' updates of one sum (a load that waits for the previous sample's store, then the
/// multiply-add) alternate with the other filter's, independent ones. The product of a float weight and a float
/// radiance is exact in double, so the fused multiply-add rounds as the SSE build's multiply then add.
template <int N>
__attribute__((target("avx2,fma"))) void pairAvx2(const Batch& batch, int count, const float* w0, const float* w1,
                                                  BandBuffer band0, BandBuffer band1) {
  double* const base0 = reinterpret_cast<double*>(band0.sums);
  double* const base1 = reinterpret_cast<double*>(band1.sums);
  const ptrdiff_t rowStep = 4 * static_cast<ptrdiff_t>(band0.width);
  for (int s = 0; s < count; ++s) {
    const ptrdiff_t at = 4 * static_cast<ptrdiff_t>(batch.at[s]);
    double *row0 = base0 + at, *row1 = base1 + at;
    const __m256d L = _mm256_cvtps_pd(_mm_load_ps(reinterpret_cast<const float*>(&batch.L[s])));
#pragma GCC unroll 8
    for (int b = 0; b < N; ++b, row0 += rowStep, row1 += rowStep)
#pragma GCC unroll 8
      for (int a = 0; a < N; ++a) {
        const size_t k = static_cast<size_t>(b * N + a) * kBatch + s;
        const __m256d v0 = _mm256_set1_pd(static_cast<double>(w0[k])), v1 = _mm256_set1_pd(static_cast<double>(w1[k]));
        _mm256_store_pd(row0 + 4 * a, _mm256_fmadd_pd(v0, L, _mm256_load_pd(row0 + 4 * a)));
        _mm256_store_pd(row1 + 4 * a, _mm256_fmadd_pd(v1, L, _mm256_load_pd(row1 + 4 * a)));
      }
  }
}

/// pickKernel for n among Ns + 1 (unrolled), else the kernel for any n.
template <int... Ns>
Kernel pickKernelOf(int n, std::integer_sequence<int, Ns...>) {
  const CpuFeatures cpu = cpuFeatures();
  const bool avx2 = cpu.avx2 && cpu.fma;
  Kernel k = avx2 ? accumulateAvx2<0> : accumulateSse<0>;
  ((k = n == Ns + 1 ? (avx2 ? accumulateAvx2<Ns + 1> : accumulateSse<Ns + 1>) : k), ...);
  return k;
}

}  // namespace

Kernel pickKernel(int n) { return pickKernelOf(n, std::make_integer_sequence<int, 6>()); }

PairKernel pickPairKernel(int n) {
  const CpuFeatures cpu = cpuFeatures();
  if (!cpu.avx2 || !cpu.fma) return nullptr;
  switch (n) {
    case 2: return pairAvx2<2>;
    case 3: return pairAvx2<3>;
    case 4: return pairAvx2<4>;
    case 5: return pairAvx2<5>;
    case 6: return pairAvx2<6>;
    default: return nullptr;
  }
}

}  // namespace aliaslab::filmimpl
