// The image-long sums of MetricAccumulator (measure/metric_sums.h).
#include "measure/metric_sums.h"

#include <algorithm>

namespace aliaslab::metricimpl {

std::vector<double>& scratch(int slot, size_t n) {
  thread_local std::vector<double> buffers[2];
  buffers[slot].resize(n);
  return buffers[slot];
}

namespace {
using D2 = double __attribute__((vector_size(16)));

/// The values i of two arrays as one pair of doubles (lane 0 from p, lane 1 from q).
inline D2 pairAt(const float* p, const float* q, size_t i) { return D2{p[i], q[i]}; }

/// Four sums of such products over the same v, two to a vector: each lane is one sum, taken in the order of i
/// with the same operations as alone (the sums are independent, so four of them share a pass over v and their
/// additions overlap instead of waiting for each other).
void fourSums(const float* v, const Terms* t, size_t n, double* out) {
  D2 lo = {0.0, 0.0}, hi = {0.0, 0.0};
  for (size_t i = 0; i < n; ++i) {
    const double x = v[i];
    const D2 xx = {x, x};
    const D2 a01 = pairAt(t[0].a, t[1].a, i), a23 = pairAt(t[2].a, t[3].a, i);
    lo += (xx - a01) * (pairAt(t[0].b, t[1].b, i) - a01);
    hi += (xx - a23) * (pairAt(t[2].b, t[3].b, i) - a23);
  }
  out[0] = lo[0], out[1] = lo[1], out[2] = hi[0], out[3] = hi[1];
}

}  // namespace

/// Every sum of `terms` over the n values, four to a pass (a last pass short of four repeats its last term).
void productSums(const float* v, const std::vector<Terms>& terms, size_t n, double* out) {
  for (size_t m = 0; m < terms.size(); m += 4) {
    Terms four[4];
    double sums[4];
    for (size_t q = 0; q < 4; ++q) four[q] = terms[std::min(m + q, terms.size() - 1)];
    fourSums(v, four, n, sums);
    for (size_t q = 0; q < 4 && m + q < terms.size(); ++q) out[m + q] = sums[q];
  }
}

namespace {
/// One loop per case of halves, with no test per value.
template <bool DG, bool DT>
TargetSums targetSumsOf(const double* mean, const float* g, const float* t, const float* dg, const float* dt,
                        size_t N, double* xb, double* xt) {
  double blur = 0, cross = 0, varT = 0, varDelta = 0, covariance = 0;
  for (size_t i = 0; i < N; ++i) {
    const double gt = static_cast<double>(g[i]) - t[i];
    blur += gt * gt;
    cross += (mean[i] - g[i]) * gt;
    if constexpr (DG || DT) {
      const double a = DG ? static_cast<double>(dg[i]) : 0.0, b = DT ? static_cast<double>(dt[i]) : 0.0;
      varT += b * b, varDelta += (a - b) * (a - b), covariance += a * (a - b);
      xb[i] = 2 * gt * (a - b);
      if constexpr (DT) xt[i] = 2 * (mean[i] - t[i]) * b;
    }
  }
  return {blur, cross, varT, varDelta, covariance};
}
}  // namespace

TargetSums targetSums(const double* mean, const float* g, const float* t, const float* dg, const float* dt,
                      size_t n, double* xb, double* xt) {
  if (dg) return dt ? targetSumsOf<true, true>(mean, g, t, dg, dt, n, xb, xt)
                    : targetSumsOf<true, false>(mean, g, t, dg, dt, n, xb, xt);
  return dt ? targetSumsOf<false, true>(mean, g, t, dg, dt, n, xb, xt)
            : targetSumsOf<false, false>(mean, g, t, dg, dt, n, xb, xt);
}

}  // namespace aliaslab::metricimpl
