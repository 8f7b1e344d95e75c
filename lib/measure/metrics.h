// Error metrics of one configuration (docs/science.md, "Metrics of one
// configuration" and "One target, four terms").
//
// Protocol: construct a MetricAccumulator with the reference G of the
// configuration's (filter, radius), the pixel-area reference A (box,
// r = 0.5) and the study's target T (by default T = A), add() the K images
// I_k rendered with independent seeds (any order), then result(). Per pixel
// and channel it keeps the running mean m and the sum of squared deviations
// (Welford, double). With s^2 the unbiased variance over the K images and
// every mean taken over pixels and channels:
//   mse        = mean over k of mean (I_k - G)^2
//   noise      = mean s^2
//   aliasing   = mean (m - G)^2  -  noise / K
//   mse_area   = mean over k of mean (I_k - A)^2
//   mse_target = mean over k of mean (I_k - T)^2
//   blur       = mean (G - T)^2                 (the references alone)
//   cross      = 2 mean (m - G)(G - T)
//   psnr       = 10 log10(1 / mse)
// Since mean_k (I_k - G)^2 = (m - G)^2 + (K-1)/K s^2 per value, mse =
// aliasing + noise, and since I_k - T = (I_k - m) + (m - G) + (G - T),
// mse_target = noise + aliasing + blur + cross; both hold up to rounding.
//
// Standard errors over the seeds (the seeds are the independent units; the
// pixels of one image are not independent of each other, since a sample
// lands in several pixels' footprints). With e_k = I_k - G and the K x K Gram
// matrix C_kl = sum over values of e_k e_l: mse = tr C / (N K) is a mean of
// per-seed terms, and so is mse_target: their *_se is the sd over seeds /
// sqrt(K) (= their jackknife). aliasing = mean over seed pairs of C_kl / N
// and noise = mean over pairs of (C_kk + C_ll - 2 C_kl) / (2N) are pair
// statistics: their *_se is the unbiased (Hoeffding) variance, floored by the
// jackknife scaled to a lower bound (metrics.cpp, docs/science.md "Standard
// errors"); they need K >= 4 (NaN otherwise). C needs every pair of seeds,
// so the accumulator keeps the K images (K float images per configuration in
// flight); no running state of fixed size gives all pair products.
#pragma once
#include <vector>

#include "core/image.h"

namespace aliaslab {

struct Metrics {
  double mse = 0;        ///< mean squared error against G, per pixel and channel
  double aliasing = 0;   ///< structured (seed-independent) part of mse
  double noise = 0;      ///< seed-to-seed part of mse: mean unbiased variance
  double mseArea = 0;    ///< mean squared error against the pixel-area reference A
  double mseTarget = 0;  ///< mean squared error against the study's target T
  double blur = 0;       ///< mean (G - T)^2: the filter's own deviation from the target
  double cross = 0;      ///< 2 mean (m - G)(G - T): mse_target - noise - aliasing - blur
  double psnr = 0;       ///< 10 log10(1 / mse), in dB (+inf when mse == 0)
  double mseSe = 0, noiseSe = 0, aliasingSe = 0, mseTargetSe = 0;  ///< jackknife standard errors over seeds
  int images = 0;        ///< K, the number of images added
};

class MetricAccumulator {
 public:
  /// `reference` = G, `areaReference` = A, `target` = T; all the same size.
  /// They are held by reference and must outlive the accumulator.
  MetricAccumulator(const Image& reference, const Image& areaReference, const Image& target);
  /// The target is the area reference (T = A).
  MetricAccumulator(const Image& reference, const Image& areaReference)
      : MetricAccumulator(reference, areaReference, areaReference) {}

  /// Adds one image I_k (same size as the references).
  void add(const Image& image);

  /// The metrics of the images added so far (needs at least 2).
  Metrics result() const;

  /// Per-pixel noise: s^2 averaged over the three channels (a grey image).
  Image noiseMap() const;

 private:
  const Image& reference_;
  const Image& area_;
  const Image& target_;
  int count_ = 0;
  std::vector<double> mean_, m2_;  ///< per pixel and channel
  double sseArea_ = 0;
  double blur_ = 0;                ///< sum of (G - T)^2
  std::vector<Image> images_;      ///< the K images (for the pair products of C)
  std::vector<std::vector<double>> gram_;  ///< gram_[k][l] = C_kl for l <= k
  std::vector<double> sseTarget_;  ///< per seed: sum of (I_k - T)^2
};

/// Metrics of K images in one call (convenience over MetricAccumulator).
Metrics computeMetrics(const std::vector<Image>& images, const Image& reference, const Image& areaReference);
Metrics computeMetrics(const std::vector<Image>& images, const Image& reference, const Image& areaReference,
                       const Image& target);

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
