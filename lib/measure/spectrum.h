// Where the error sits on screen: power spectra of error images and the
// scalar measures made from them (docs/spectrum.md).
//
// Power spectrum of an image e (W x H, per channel c): with the DFT
// E_c(u, v) = sum_{x,y} e_c(x, y) exp(-2 pi i (u x / W + v y / H)),
//   P(u, v) = mean over channels of |E_c(u, v)|^2 / (W H)^2,
// normalised so that (Parseval) sum over all (u, v) of P = mean over pixels
// and channels of e^2. (u, v) is the frequency (u'/W, v'/H) in cycles per
// pixel with u' = u wrapped to [-W/2, W/2); its radius rho ranges from 0 to
// about 0.71 (Nyquist is 0.5 along each axis). The DC term (rho = 0) is the
// mean of e: a bias is error at the lowest frequency.
//
// Radial spectrum: frequencies binned by rho into bins of width 1/64 cycle
// per pixel (bin b holds b/64 <= rho < (b+1)/64; 46 bins reach the
// corners); per bin the energy (sum of P) and the count of frequencies, so
// energy / count is the radially averaged power and the energies sum to the
// mean square.
//
// Protocol of SpectrumAccumulator: construct with the reference G and the
// study's targets T_j (RefEstimates: mean and half-difference D), add() the
// K images I_k, result(). Per image it takes the spectrum of the error
// e_k = I_k - G and keeps, per frequency, sum_k E_k and sum_k |E_k|^2, so the
// noise spectrum (of I_k - m, m the mean of the K images) follows at the end
// without keeping the images:
//   errorSpectrum = mean_k P[e_k]                  (energies sum to the mse
//                                                   before the subtraction of
//                                                   mean D_G^2)
//   noiseSpectrum = sum_k P[e_k - mean_j e_j]/(K-1) (energies sum to noise,
//                                                   the unbiased variance)
//   reference     = P[D_G], the reference's own error spectrum (estimated)
//   lowfreq_error    = mean over k of f_k, f_k = the share of the error's
//                      energy at rho < kLowFrequencyCutoff (a quarter of
//                      Nyquist, 0.125 cycle per pixel; DC included), with
//                      the reference's share subtracted from both parts:
//                      f_k = (L_k - L_D) / (E_k - E_D), L the energy below
//                      the cutoff and E the total, of P[e_k] and of P[D_G];
//                      clamped to [0, 1]; 0 when E_k - E_D <= 0 (an error
//                      that cannot be told from the reference's, as an
//                      error-free image)
//   lowfreq_error_se = standard deviation of f_k over k / sqrt(K) (over the
//                      seeds, the reference held fixed)
//   blurred_mse      = mean over k of the mean square of e_k blurred by a
//                      Gaussian of sigma = kBlurSigma = 1 pixel, applied as
//                      the transfer function exp(-2 pi^2 sigma^2 rho^2) on
//                      the DFT (a circular convolution: the blur wraps at the
//                      image border), minus the same of D_G: blurred_mse =
//                      mean_k sum P[e_k] g(rho) - sum P[D_G] g(rho), g =
//                      exp(-4 pi^2 sigma^2 rho^2)
//   blur curve (against each target T only): for each sigma of kBlurCurve,
//                      blur_ratio = mean over k of r_k, r_k = (B_k - B_D) /
//                      (E_k - E_D), B the energy blurred by that sigma (as
//                      blurred_mse), E the total, of P[I_k - T] and P[D_T]
//                      (0 when E_k - E_D <= 0), with its standard error over
//                      the seeds. White noise gives mean over frequencies of
//                      g(rho) = sum of the squared weights of the blur's
//                      kernel (docs/science.md, "The blur curve").
// The same three against each target T, from the error I_k - T: by
// linearity its DFT is E_k + DFT(G - T), the latter computed once per target
// (no extra FFT per image), and D_T takes the place of D_G. With no halves
// (halfDiff == nullptr) nothing is subtracted.
// White noise has lowfreq_error = pi 0.125^2 = 0.049 (the disc's share of
// the frequency square); error pushed to high frequencies has less.
//
// Computed once per configuration's references: the side of G and the targets (the DFTs of G - T, the
// energies of the half-differences, the per-frequency gains) is a SpectrumReference, made once per (G,
// targets) and shared by every configuration measured against them. A real image's DFT is conjugate-symmetric,
// E(-f) = conj E(f), and every weight above depends on rho only, so the accumulator transforms and sums the
// half plane u = 0 .. W/2 with each frequency counted for itself and its mirror: the same sums as the full
// plane up to rounding, tolerance in docs/spectrum.md (SpectrumDefinition, measure/spectrum_definition.h, is
// the full-plane definition the tests hold it to).
//
// The study writes these spectra to per-scene CSV files: study/records/spectrum_files.h.
#pragma once
#include <array>
#include <complex>
#include <memory>
#include <vector>

#include "core/image.h"
#include "measure/metrics.h"  // RefEstimate

namespace aliaslab {

inline constexpr double kLowFrequencyCutoff = 0.125;  ///< cycles per pixel: a quarter of Nyquist
inline constexpr double kBlurSigma = 1.0;             ///< pixels: the blurred_mse Gaussian
inline constexpr std::array<double, 4> kBlurCurve = {0.5, 1.0, 2.0, 4.0};  ///< pixels: the blur curve's sigmas
inline constexpr double kSpectrumBinWidth = 1.0 / 64;  ///< cycles per pixel per radial bin
inline constexpr int kSpectrumBins = 46;               ///< bins up to rho = 46/64 > sqrt(2)/2

struct RadialSpectrum {
  std::vector<double> energy = std::vector<double>(kSpectrumBins, 0.0);  ///< sum of P in each bin
  std::vector<long> count = std::vector<long>(kSpectrumBins, 0);         ///< frequencies in each bin
  /// Radially averaged power of bin b (0 for an empty bin).
  double power(int b) const { return count[b] ? energy[b] / count[b] : 0.0; }
  /// Centre of bin b in cycles per pixel.
  static double frequency(int b) { return (b + 0.5) * kSpectrumBinWidth; }
  /// Sum of all energies (= the mean square of the image).
  double total() const;
};

/// The per-frequency power P(u, v) (row-major, v * W + u) of an image.
std::vector<double> powerSpectrum(const Image& image);
/// The radial spectrum of an image.
RadialSpectrum radialSpectrum(const Image& image);
/// Radius in cycles per pixel of DFT index (u, v) of a W x H image.
double frequencyRadius(int u, int v, int width, int height);

/// The measures against one target T (docs/science.md, "Where the error sits").
struct SpectrumTargetMetrics {
  double lowfreqError = 0, lowfreqErrorSe = 0, blurredMse = 0;
  std::array<double, kBlurCurve.size()> blurRatio{}, blurRatioSe{};  ///< the blur curve, per sigma of kBlurCurve
};

/// The energy gain of a Gaussian blur of `sigma` pixels at frequency rho (cycles per pixel): exp(-4 pi^2 s^2 rho^2).
double blurGain(double rho, double sigma);

struct SpectrumMetrics {
  double lowfreqError = 0, lowfreqErrorSe = 0, blurredMse = 0;  ///< against the own reference G
  std::vector<SpectrumTargetMetrics> targets;                   ///< against each target, in order
  RadialSpectrum error, noise;
  RadialSpectrum reference;  ///< P[D_G]: the own reference's error spectrum (zero without halves)
  int images = 0;
};

/// The references' side of SpectrumAccumulator, made once and read by any number of accumulators (and threads).
class SpectrumReference {
 public:
  /// G and the targets T_j, all the same size. The images are copied or reduced here: they need not outlive it.
  SpectrumReference(RefEstimate reference, std::vector<RefEstimate> targets);
  /// The energies of one error image, each frequency of the full plane counted once.
  struct Energies {
    double low = 0, total = 0, blurred = 0;
    std::array<double, kBlurCurve.size()> curve{};  ///< blurred by each sigma of kBlurCurve
  };
  /// Per frequency of the half plane (v * halfWidth + u): what its power counts for, itself and its mirror.
  struct Weights {
    double low = 0, total = 0, blurred = 0;          ///< multiplicity m (1 or 2) x [rho < cutoff], m, m x gain
    std::array<double, kBlurCurve.size()> curve{};  ///< m x gain per sigma of kBlurCurve
  };
  struct Target {
    std::vector<std::complex<double>> shift;  ///< per channel and half-plane frequency: DFT(G - T) / (W H)
    Energies halves;                          ///< of P[D_T]
  };
  const Image& image() const { return reference_; }
  int width() const { return width_; }
  int height() const { return height_; }
  size_t frequencies() const { return weights_.size(); }  ///< of the half plane
  const std::vector<Weights>& weights() const { return weights_; }
  const std::vector<int>& bins() const { return bins_; }  ///< radial bin per half-plane frequency
  const Energies& own() const { return own_; }            ///< of P[D_G]
  const RadialSpectrum& ownRadial() const { return ownRadial_; }
  const std::vector<Target>& targets() const { return targets_; }
  /// The energies of `image` (and its radial spectrum if `radial`).
  Energies energies(const Image& image, RadialSpectrum* radial) const;

 private:
  Image reference_;  ///< a copy (a temporary may be passed)
  int width_, height_;
  std::vector<Weights> weights_;
  std::vector<int> bins_;
  Energies own_;
  RadialSpectrum ownRadial_;
  std::vector<Target> targets_;
};

class SpectrumAccumulator {
 public:
  /// G and the targets T_j, all the same size, with a SpectrumReference of its own.
  SpectrumAccumulator(RefEstimate reference, std::vector<RefEstimate> targets);
  /// Against a shared reference side.
  explicit SpectrumAccumulator(std::shared_ptr<const SpectrumReference> reference);
  void add(const Image& image);
  /// Needs at least 2 images (for the noise spectrum and the standard error).
  SpectrumMetrics result() const;

 private:
  struct TargetSums {
    std::vector<double> lowFractions;                           ///< f_k against T
    double blurred = 0;                                         ///< sum over k of the blurred energy of I_k - T
    std::vector<std::array<double, kBlurCurve.size()>> ratios;  ///< r_k per sigma against T
  };
  std::shared_ptr<const SpectrumReference> ref_;
  /// per channel and half-plane frequency: sum_k E_k / (W H) as (re, im) pairs; allocated, not initialised, and
  /// written by the first add() (no zero fill per configuration)
  std::unique_ptr<double[]> sum_;
  std::unique_ptr<double[]> sumSquares_;  ///< per half-plane frequency: sum_k P[e_k] (channel mean)
  std::vector<double> lowFractions_;      ///< f_k
  double blurred_ = 0;
  std::vector<TargetSums> targets_;
  int count_ = 0;
};

}  // namespace aliaslab
