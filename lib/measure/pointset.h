// Measures of a 2-D point set in the unit square (docs/science.md, "Point-set
// measures"): how uniformly it covers [0,1)^2 (L2-star discrepancy), how
// close its closest pair is (minimum toroidal distance) and how its energy is
// spread over frequencies (periodogram and its radial average).
//
// Protocol: every function takes the points of one set (e.g. one pixel's
// Sampler::generate output) and is a pure function of them. Averages over
// many independent sets are made by the caller: accumulate periodograms with
// Periodogram::add, then read the mean with radialSpectrum (pointset_study.h
// does so for every sampler and count, and makes the experiment's tables).
#pragma once
#include <string>
#include <vector>

#include "core/image.h"
#include "core/math.h"

namespace aliaslab {

/// Squared L2-star discrepancy by Warnock's closed form, O(N^2):
///   D^2 = 1/9 - (2/N) sum_i prod_d (1 - x_id^2) / 2
///             + (1/N^2) sum_i sum_j prod_d (1 - max(x_id, x_jd)).
/// It equals the integral over anchors a in [0,1]^2 of
/// (#{x_i in [0,a)} / N - a_x a_y)^2. Returns 0 for an empty set.
double l2StarDiscrepancySquared(const std::vector<Vec2>& points);
/// sqrt of l2StarDiscrepancySquared (the usual reported value).
double l2StarDiscrepancy(const std::vector<Vec2>& points);

/// Smallest distance between two points of the set on the unit torus (each
/// coordinate difference wrapped to min(|d|, 1 - |d|)); O(N^2). Returns
/// +infinity for fewer than two points.
double minToroidalDistance(const std::vector<Vec2>& points);

/// Distance between neighbours of the densest packing of n points on the
/// unit torus (hexagonal lattice): sqrt(2 / (sqrt(3) n)). Dividing
/// minToroidalDistance by it gives a normalised value in (0, ~1].
double idealPackingDistance(int n);

/// Periodogram on integer frequencies k = (kx, ky), |kx|, |ky| <= half
/// (cycles per unit length): P(k) = |sum_j exp(-2 pi i k . x_j)|^2 / N,
/// averaged over every set add()ed. P(0) = N; for independent uniform
/// points E P(k) = 1 at every k != 0.
class Periodogram {
 public:
  /// half: largest |frequency| per axis (>= 1).
  explicit Periodogram(int half);

  /// Adds one set (evaluated as a complex matrix product with Eigen).
  void add(const std::vector<Vec2>& points);

  int half() const { return half_; }
  int size() const { return 2 * half_ + 1; }
  /// Mean power at frequency (kx, ky), |kx|, |ky| <= half.
  double at(int kx, int ky) const { return sets_ ? sum_[index(kx, ky)] / sets_ : 0.0; }

 private:
  size_t index(int kx, int ky) const { return static_cast<size_t>(ky + half_) * size() + (kx + half_); }
  int half_;
  int sets_ = 0;
  std::vector<double> sum_;
};

/// Radial average of a periodogram: entry r (r = 1 .. half) is the mean of
/// P(k) over the integer frequencies with r - 0.5 <= |k| < r + 0.5; entry 0
/// is P(0). Frequencies beyond |k| = half (the square's corners) are left out.
std::vector<double> radialSpectrum(const Periodogram& periodogram);

/// Point plot for the eye: black dots on white inside a grey frame of the
/// unit square, y up; `size` pixels square.
Image plotPointSet(const std::vector<Vec2>& points, int size);

/// The mean periodogram as a grey image, DC at the centre (drawn white),
/// each frequency a block of about 384 / (2 half + 1) pixels; grey =
/// 0.5 + 0.25 log2 P clamped to [0, 1], so white noise (P = 1) is mid-grey,
/// P >= 4 white and P <= 1/4 black. Values are display values for the 8-bit
/// writer (no gamma applied).
Image plotPeriodogram(const Periodogram& periodogram);

}  // namespace aliaslab
