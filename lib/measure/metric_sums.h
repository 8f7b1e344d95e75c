// Private to measure/metrics.cpp: the image-long sums of MetricAccumulator, written so that they run at the
// speed of the machine while every sum keeps its operations and their order (the same bits as a plain loop).
//
// A sum over the values of an image into one double waits for its previous addition at every value; taken one
// at a time, the sums of a configuration ran at that latency. Here independent sums share a pass over the image,
// side by side (two to a vector register, each lane one sum in the order of the values), and the sums are kept
// in locals (as members they were kept in memory, a store and a load on every addition).
#pragma once
#include <cstddef>
#include <vector>

namespace aliaslab::metricimpl {

/// This thread's image-sized buffer `slot` (0 or 1), n values long: reused from configuration to configuration
/// so that no call allocates and zero-fills whole images. The caller writes every value before reading it.
std::vector<double>& scratch(int slot, size_t n);

/// The factors of sum over i of (v_i - a_i)(b_i - a_i), in double: (I_k - T)^2 with a = T, b = I_k, and
/// (I_k - G)(I_l - G) with a = G, b = I_l.
struct Terms {
  const float *a, *b;
};

/// out[m] = sum over i < n, in the order of i, of (v_i - a_i)(b_i - a_i) for terms[m], four sums to a pass.
void productSums(const float* v, const std::vector<Terms>& terms, size_t n, double* out);

/// The sums of MetricAccumulator::targetMetrics over the n values, each in the order of i.
struct TargetSums {
  double blur, cross, varT, varDelta, covariance;
};

/// With gt = G - T and a, b the half-differences D_G, D_T (0 where null): the sums of gt^2, (m - G) gt, b^2,
/// (a - b)^2, a (a - b); xb[i] = 2 gt (a - b) when either has halves, xt[i] = 2 (m - T) b when dt does.
TargetSums targetSums(const double* mean, const float* g, const float* t, const float* dg, const float* dt,
                      size_t n, double* xb, double* xt);

}  // namespace aliaslab::metricimpl
