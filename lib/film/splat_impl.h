// Private to lib/film's splat (splat.cpp, splat_pass.cpp, splat_kernels.cpp): the band buffer's cells, the
// batch of samples waiting for one FilterBatch::eval call, the accumulation kernels' signature and the pass
// per radius. The protocol of the splat is at the top of splat.cpp.
#pragma once
#include <vector>

#include "film/film_impl.h"

namespace aliaslab::filmimpl {

constexpr int kBatch = 128;  // samples per FilterBatch::eval call (a multiple of 4)
constexpr int kMaxBlock = 16; // largest n x n block (r <= 8); wider footprints sample by sample

/// (r, g, b, weight) in double: one AVX register, two SSE ones (aligned to 32 also without AVX).
using V4 = double __attribute__((vector_size(32)));
using F4 = float __attribute__((vector_size(16)));
struct alignas(32) Sum {
  V4 v = {};
};

/// Samples waiting for one FilterBatch::eval call (padded to a multiple of 4).
struct Batch {
  alignas(16) float x[kBatch], y[kBatch], cx[kBatch], cy[kBatch];  ///< position, first pixel centre
  int at[kBatch];                                                   ///< first pixel's index in the band buffer
  int nx[kBatch], ny[kBatch];                                       ///< footprint columns and rows (<= n)
  F4 L[kBatch];                                                     ///< (r, g, b, 1)
};

/// A band buffer as a kernel sees it: `sums` of `width` per row, blocks of n x n pixels.
struct BandBuffer {
  Sum* sums;
  int width, n;
};

/// kernel(batch, count, w, band): the batch's first `count` samples added over their blocks in `band`.
using Kernel = void (*)(const Batch&, int, const float*, BandBuffer);
/// The kernel that adds a batch's samples over blocks of n x n pixels (weights w, or none: unitWeights):
/// unrolled for n <= 6, AVX2 + FMA when the CPU has them (core/cpu.h; splat_kernels.cpp).
Kernel pickKernel(int n);
/// pair(batch, count, w0, w1, band0, band1): kernel(batch, count, w0, band0) then kernel(batch, count, w1, band1)
/// to the bit, sample by sample in both (two weighted filters of one radius; a unit-weight box keeps its own
/// kernel: with its weights written out the pair was slower, results/study_speed.md).
using PairKernel = void (*)(const Batch&, int, const float*, const float*, BandBuffer, BandBuffer);
/// The pair kernel for n (AVX2 + FMA, 2 <= n <= 6), else null: the caller runs kernel twice.
PairKernel pickPairKernel(int n);

/// Per source row (the samples of one row of pixels): the least and greatest y (NaN ignored).
struct RowSpans {
  std::vector<float> ymin, ymax;
};

/// The fused pass for filters that share one radius (see splatAll; splat_pass.cpp).
void splatSameRadius(const SampleBuffer& samples, const RowSpans& spans, const SplatTargets& targets, int threads);

}  // namespace aliaslab::filmimpl
