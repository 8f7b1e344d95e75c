// Error metrics of one configuration (docs/science.md, "Metrics of one configuration", "One target, four
// terms", "The references' own error" and "Standard errors").
//
// Protocol: construct a MetricAccumulator with the reference G of the configuration's (filter, radius) and the
// study's targets T_j, each a RefEstimate (the mean of two independent halves and their half-difference D),
// add() the K images I_k rendered with independent seeds (any order), then result(). Per pixel and channel it
// keeps the running mean m and the sum of squared deviations (Welford, double). With s^2 the unbiased variance
// over the K images, every mean taken over pixels and channels, and Var X estimated by mean D_X^2:
//   mse        = mean over k of mean (I_k - G)^2  -  mean D_G^2
//   noise      = mean s^2
//   aliasing   = mean (m - G)^2  -  noise / K  -  mean D_G^2
//   psnr       = 10 log10(1 / mse)
// and per target T:
//   mse_target = mean over k of mean (I_k - T)^2  -  mean D_T^2
//   blur       = mean (G - T)^2  -  mean (D_G - D_T)^2        (the references alone)
//   cross      = 2 mean (m - G)(G - T)  +  2 mean D_G (D_G - D_T)
// so that mse = aliasing + noise and mse_target = noise + aliasing + blur + cross still hold up to rounding. A
// reference without halves (halfDiff == nullptr) is exact: nothing is subtracted (the metrics of before).
//
// Standard errors: se^2 = seed part + reference part. The seed part is taken over the seeds with G and T held
// fixed (the seeds are the independent units; pixels of one image are not): with e_k = I_k - G and the K x K
// Gram matrix C_kl = sum over values of e_k e_l, mse = tr C / (N K) and mse_target are means of per-seed terms
// (sd over seeds / sqrt(K)); aliasing and noise are means over seed pairs (measure/standard_errors.h
// pairStatisticSe; NaN when K < 4). The reference part is taken over spatial windows with the images held fixed:
// for a statistic mean (w - delta)^2 - mean D^2 (w the residual against the true reference), it is
// 4 windowSumVariance(w D) / N^2 with w = m - G (aliasing, mse), m - T (mse_target), G - T (blur). C needs every
// pair of seeds, so the accumulator keeps the K images (K float images per configuration in flight).
#pragma once
#include <vector>

#include "core/huge_pages.h"
#include "core/image.h"

namespace aliaslab {

/// A reference estimate made of two independent halves a and b (study/reference/reference.h): mean = (a + b) / 2,
/// halfDiff = (a - b) / 2. Per value, halfDiff^2 is an unbiased estimate of Var(mean); for two references
/// made from the same samples (same batches in the same halves), the product of their halfDiffs is an
/// unbiased estimate of their covariance. halfDiff == nullptr: an exact reference (variance 0).
/// radius: the reference filter's radius in pixels; its errors are correlated only between pixels less than
/// 2 radius apart (they share no sample otherwise), which the standard errors' reference part uses. The default,
/// 4, is the largest radius of the studies: safe for any filter up to it, only noisier for narrower ones.
struct RefEstimate {
  const Image* mean = nullptr;
  const Image* halfDiff = nullptr;
  double radius = 4;
};

/// The terms against one target T (all with the references' variance subtracted; see docs/science.md).
struct TargetMetrics {
  double mseTarget = 0, mseTargetSe = 0;  ///< mean_k mean (I_k - T)^2 - mean Var T
  double blur = 0, blurSe = 0;            ///< mean (G - T)^2 - mean Var(G - T)
  double cross = 0;                       ///< mse_target - noise - aliasing - blur (corrected terms)
  double refVar = 0;                      ///< mean Var T, the estimate subtracted (the target's ref_error)
  std::vector<double> perSeed;            ///< per seed k: mean (I_k - T)^2 - mean Var T (mean = mseTarget)
};

struct Metrics {
  double mse = 0, mseSe = 0;            ///< mean_k mean (I_k - G)^2 - mean Var G
  double aliasing = 0, aliasingSe = 0;  ///< mean (m - G)^2 - noise / K - mean Var G
  double noise = 0, noiseSe = 0;        ///< mean s^2 (unchanged: the reference does not enter it)
  double psnr = 0;                      ///< 10 log10(1 / mse), mse the corrected one (+inf when <= 0)
  double refVar = 0;                    ///< mean Var G (= the reference's ref_error)
  bool deterministic = false;           ///< all K images identical bit for bit (the seeds change nothing)
  std::vector<TargetMetrics> targets;   ///< in the order given to the accumulator
  int images = 0;                       ///< K, the number of images added
};

class MetricAccumulator {
 public:
  /// G and the targets T_j, all the same size; images held by pointer, must outlive the accumulator.
  MetricAccumulator(RefEstimate reference, std::vector<RefEstimate> targets);

  /// Adds one image I_k (same size as the references).
  void add(const Image& image);

  /// The metrics of the images added so far (needs at least 2).
  Metrics result() const;

  /// Per-pixel noise: s^2 averaged over the three channels (a grey image).
  Image noiseMap() const;

 private:
  /// Target j's terms (mse_target, blur, cross) and their standard errors, for result().
  TargetMetrics targetMetrics(size_t j) const;

  RefEstimate reference_;
  std::vector<RefEstimate> targets_;
  int count_ = 0;
  bool identical_ = true;                  ///< every image so far equals the first bit for bit
  /// per pixel and channel; not initialised until the first add() sets them (m = 0 + I_1, m2 = 0: Welford's
  /// first step bit for bit), so a configuration's start fills no image-sized buffer
  std::vector<double, UninitializedAllocator<double>> mean_, m2_;
  std::vector<Image> images_;              ///< the K images (for the pair products of C)
  std::vector<std::vector<double>> gram_;  ///< gram_[k][l] = C_kl for l <= k
  std::vector<std::vector<double>> sseTarget_;  ///< [target][seed]: sum of (I_k - T)^2
};

/// Metrics of K images in one call (convenience over MetricAccumulator).
Metrics computeMetrics(const std::vector<Image>& images, RefEstimate reference, std::vector<RefEstimate> targets);

/// Mean over pixels and channels of (a - b)^2.
double meanSquaredDifference(const Image& a, const Image& b);

/// Error of a reference made as the mean of two independent halves a and b:
/// mean over pixels and channels of (a - b)^2 / 4, the variance of their mean.
double halvesError(const Image& a, const Image& b);

/// The per-pixel, per-channel half-difference (a - b) / 2 of two independent halves: its square estimates the
/// variance of their mean (averageImages) without bias.
Image halfDifference(const Image& a, const Image& b);

/// The per-pixel, per-channel mean (a + b) / 2.
Image averageImages(const Image& a, const Image& b);

}  // namespace aliaslab
