// Standard-error building blocks of the metrics (docs/science.md, "Standard errors").
//
// Two sources of error enter a metric: the K seeds (the images), and the references' own error (G and T are
// estimates made of two independent halves). The seed part is taken over seeds with the references held
// fixed: jackknifeSe for means of per-seed terms, pairStatisticSe for means over seed pairs. The reference
// part is taken over spatial windows of the image with the seeds held fixed: windowSumVariance.
#pragma once
#include <vector>

namespace aliaslab {

/// Jackknife standard error from the K leave-one-out values (for a mean of per-seed terms: sd / sqrt(K)).
double jackknifeSe(const std::vector<double>& leaveOneOut);

/// Standard error of a degree-2 U-statistic U = mean over seed pairs k < l of h[k][l] (h[k] holds l < k):
/// the unbiased (Hoeffding) variance floored by the jackknife scaled to a lower bound. NaN when K < 4.
double pairStatisticSe(const std::vector<std::vector<double>>& h);

/// The largest pixel lag (along each axis) at which the errors of a reference with filter radius r can be
/// correlated: pixels share samples only when their footprints overlap, less than 2 r apart, so ceil(2 r) - 1.
int correlationLag(double radius);

/// Estimate of Var(sum over values of x_i) when x_i = w_i D_i, D a half-difference (E[D_i D_j] = Cov(delta_i,
/// delta_j), delta the reference's error, zero beyond `lag` pixels along either axis) and w fixed: the sum of
/// x_i x_j over every pair of values whose pixels are at most `lag` apart along both axes (all channels of a
/// pixel included), i.e. sum over pixels p of s_p times the sum of s over the (2 lag + 1)^2 window around p,
/// s_p the sum of x over p's channels. Floored at 0. `x` is interleaved RGB, width x height pixels.
double windowSumVariance(const std::vector<double>& x, int width, int height, int lag);

}  // namespace aliaslab
