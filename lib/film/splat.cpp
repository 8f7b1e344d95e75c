// The fast weighted average. Per output band of kBand rows (the parallel
// work item), the samples of every source row that can reach the band, in
// memory order, in batches: one FilterBatch::eval call per batch (vectorised
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
// filter cheap in a sweep or a reference. With AVX2 + FMA, two weighted
// filters of the pass accumulate together, sample by sample (the pair
// kernels): each sum's additions and their order are unchanged, but the
// update of a sum by the next sample, which waits for this sample's store,
// now alternates with the other filter's independent one (the kernels are
// bound by that wait, not by their arithmetic). Where the CPU has AVX2, the
// set-up (finiteness, range, footprint, batch entry) takes 8 samples at a
// time (setup8), the scalar loop's operations lane by lane; a group with
// any sample it does not handle (near the image's first rows and columns,
// partly outside the band, wider than a block, not finite) goes one by one.
//
// In this file: addPlainSums, splatAll (the passes per radius) and splatWeighted. The pass per radius and
// the 8-sample set-up are in splat_pass.cpp (its work spaces in splat_workspace.h), the accumulation
// kernels in splat_kernels.cpp, the band buffer's cells and the batch in splat_impl.h.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/parallel.h"
#include "film/splat_impl.h"

namespace aliaslab::filmimpl {

size_t addPlainSums(const SampleBuffer& samples, double* plain) {
  size_t skipped = 0;
  for (int j = 0; j < samples.height(); ++j)
    for (int i = 0; i < samples.width(); ++i) {
      const FilmSample* s = samples.pixel(i, j);
      double* p = plain + 4 * (static_cast<size_t>(j) * samples.width() + i);
      for (int k = 0, n = samples.count(i, j); k < n; ++k)
        if (finiteSample(s[k])) p[0] += s[k].L[0], p[1] += s[k].L[1], p[2] += s[k].L[2], p[3] += 1;
        else ++skipped;
    }
  return skipped;
}

void splatAll(const SampleBuffer& samples, const SplatTargets& targets, int threads) {
  const std::vector<const Filter*>& filters = targets.filters;
  const int H = samples.height();
  RowSpans spans{std::vector<float>(H), std::vector<float>(H)};
  parallelFor(H, threads, [&](int sj) {
    float ymin = kInf, ymax = -kInf;
    const FilmSample* row = samples.pixel(0, sj);
    for (size_t k = 0, rowSamples = samples.rowCount(sj); k < rowSamples; ++k)
      ymin = std::min(ymin, row[k].y), ymax = std::max(ymax, row[k].y);
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
        group.push_back(filters[k]), groupSums.push_back(targets.sums[k]), index.push_back(k), done[k] = true;
    std::vector<double> own(group.size(), 0.0);
    const double* ownSeconds = targets.ownSeconds;
    splatSameRadius(samples, spans, {group, groupSums, ownSeconds ? own.data() : nullptr, targets.overwrite}, threads);
    if (ownSeconds)
      for (size_t g = 0; g < group.size(); ++g) targets.ownSeconds[index[g]] += own[g];
  }
}

void splatWeighted(const SampleBuffer& samples, const Filter& filter, double* sums, int threads) {
  const std::vector<const Filter*> filters{&filter};
  const std::vector<double*> targets{sums};
  splatAll(samples, {filters, targets}, threads);
}

}  // namespace aliaslab::filmimpl
