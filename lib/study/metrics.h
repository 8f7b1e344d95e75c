// Error metrics of one configuration (../shared/guide/SCIENCE.md, "Metrics
// of one configuration").
//
// Protocol: construct a MetricAccumulator with the reference G of the
// configuration's (filter, radius) and the pixel-area reference A (box,
// r = 0.5), add() the K images I_k rendered with independent seeds (any
// order), then result(). Per pixel and channel it keeps the running mean m
// and the sum of squared deviations (Welford, double), so memory does not
// grow with K. With s^2 the unbiased variance over the K images:
//   mse      = mean over k, pixels, channels of (I_k - G)^2
//   noise    = mean over pixels, channels of s^2
//   aliasing = mean over pixels, channels of (m - G)^2  -  noise / K
//   mse_area = mean over k, pixels, channels of (I_k - A)^2
//   psnr     = 10 log10(1 / mse)
// Since mean_k (I_k - G)^2 = (m - G)^2 + (K-1)/K s^2 per pixel, mse equals
// aliasing + noise up to rounding. K >= 2 is required for noise.
#pragma once
#include <vector>

#include "core/image.h"

namespace aliaslab {

struct Metrics {
  double mse = 0;       ///< mean squared error against G, per pixel and channel
  double aliasing = 0;  ///< structured (seed-independent) part of mse
  double noise = 0;     ///< seed-to-seed part of mse: mean unbiased variance
  double mseArea = 0;   ///< mean squared error against the pixel-area reference A
  double psnr = 0;      ///< 10 log10(1 / mse), in dB (+inf when mse == 0)
  int images = 0;       ///< K, the number of images added
};

class MetricAccumulator {
 public:
  /// `reference` = G, `areaReference` = A; both must have the same size.
  MetricAccumulator(const Image& reference, const Image& areaReference);

  /// Adds one image I_k (same size as the references).
  void add(const Image& image);

  /// The metrics of the images added so far (needs at least 2).
  Metrics result() const;

  /// Per-pixel noise: s^2 averaged over the three channels (a grey image).
  Image noiseMap() const;

 private:
  const Image& reference_;
  const Image& area_;
  int count_ = 0;
  std::vector<double> mean_, m2_;  ///< per pixel and channel
  double sseRef_ = 0, sseArea_ = 0;
};

/// Metrics of K images in one call (convenience over MetricAccumulator).
Metrics computeMetrics(const std::vector<Image>& images, const Image& reference, const Image& areaReference);

/// Mean over pixels and channels of (a - b)^2.
double meanSquaredDifference(const Image& a, const Image& b);

/// Error of a reference made as the mean of two independent halves a and b:
/// mean over pixels and channels of (a - b)^2 / 4, the variance of their mean.
double halvesError(const Image& a, const Image& b);

/// The per-pixel, per-channel mean (a + b) / 2.
Image averageImages(const Image& a, const Image& b);

}  // namespace aliaslab
