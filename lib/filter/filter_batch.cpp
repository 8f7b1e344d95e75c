// FilterBatch: the kernel the filter's registry line names, else eval() sample by sample.
#include "filter/filter_batch.h"

#include "filter/filter_batch_impl.h"

namespace aliaslab {

FilterBatch::FilterBatch(const Filter& filter) : filter_(&filter) {
  if (const filterimpl::BatchMaker make = filterimpl::batchMaker(filter.name())) kernel_ = make(filter);
}

bool FilterBatch::unitWeights() const { return kernel_ && kernel_->unitWeights(); }

void FilterBatch::eval(int count, const float* x, const float* y, const float* cx, const float* cy, int n,
                       float* out) const {
  if (kernel_) return kernel_->eval(count, x, y, cx, cy, n, out);
  const int stride = FilterBatch::stride(count);
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a)
      for (int s = 0; s < stride; ++s)
        out[static_cast<size_t>(b * n + a) * stride + s] = filter_->eval(x[s] - (cx[s] + a), y[s] - (cy[s] + b));
}

}  // namespace aliaslab
