// The film's fast path beside a filter: its weights for a whole batch of
// samples in one call, vectorised across them (4 lanes, or 8 where the CPU
// has AVX2, with the same bits).
//
// For sample s < count at film position (x[s], y[s]) and the centres of the
// n x n pixels whose first centre is (cx[s], cy[s]) (a pixel centre: column
// + 0.5, row + 0.5):
//   out[(b * n + a) * stride + s] = filter.eval(x[s] - (cx[s] + a), y[s] - (cy[s] + b)),
// stride = FilterBatch::stride(count); every input holds `stride` entries
// (the padding is evaluated and ignored). Bit for bit eval() (Lanczos and
// Hann: sin and cos by the filters' own code, shared by both), except
// Blackman-Harris (Eigen's vectorised cos: a few float ulps) and the
// Gaussian (per-axis exponentials: a few ulps per unit of the exponent).
// A filter without vectorised code is evaluated sample by sample (eval()).
//
// Protocol: built once from a finished Filter, which must outlive it;
// immutable, cheap to copy, safe to use from many threads at once.
#pragma once
#include <memory>

#include "filter/filter.h"

namespace aliaslab {

namespace filterimpl {
class BatchKernel;
}

class FilterBatch {
 public:
  explicit FilterBatch(const Filter& filter);

  const Filter& filter() const { return *filter_; }
  /// The weights of a batch (see above).
  void eval(int count, const float* x, const float* y, const float* cx, const float* cy, int n, float* out) const;
  /// Entries per weight of eval's output: count rounded up to a multiple of 4.
  static int stride(int count) { return (count + 3) & ~3; }
  /// True when eval() is exactly 1 on the whole support (the box): the film then skips the weights.
  bool unitWeights() const;

 private:
  const Filter* filter_;
  std::shared_ptr<const filterimpl::BatchKernel> kernel_;  ///< null: sample by sample
};

}  // namespace aliaslab
