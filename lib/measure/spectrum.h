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
// The study writes these spectra to per-scene CSV files: study/spectrum_files.h.
#pragma once
#include <array>
#include <complex>
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

class SpectrumAccumulator {
 public:
  /// G and the targets T_j, all the same size. The images are copied or reduced on construction: they need not
  /// outlive it.
  SpectrumAccumulator(RefEstimate reference, std::vector<RefEstimate> targets);
  void add(const Image& image);
  /// Needs at least 2 images (for the noise spectrum and the standard error).
  SpectrumMetrics result() const;

 private:
  /// What one error's share and blurred energy need: the energies of a reference's half-difference.
  struct Energies {
    double low = 0, total = 0, blurred = 0;
    std::array<double, kBlurCurve.size()> curve{};  ///< blurred by each sigma of kBlurCurve
  };
  struct TargetState {
    std::vector<std::complex<double>> shift;  ///< per channel and frequency: DFT(G - T) / (W H)
    Energies halves;                          ///< of P[D_T]
    std::vector<double> lowFractions;         ///< f_k against T
    double blurred = 0;                       ///< sum over k of the blurred energy of I_k - T
    std::vector<std::array<double, kBlurCurve.size()>> ratios;  ///< r_k per sigma against T
  };
  Energies energies(const Image& image, RadialSpectrum* radial) const;
  double share(double low, double total, const Energies& ref) const;

  Image reference_;  ///< a copy (a temporary may be passed)
  int width_, height_;
  std::vector<double> radius_;                      ///< rho per frequency
  std::vector<double> gain_;                        ///< blurGain(rho) per frequency (computed once)
  std::vector<std::array<double, kBlurCurve.size()>> curveGain_;  ///< per frequency, per sigma of kBlurCurve
  std::vector<std::complex<double>> sum_;           ///< per channel and frequency: sum_k E_k / (W H)
  std::vector<double> sumSquares_;                  ///< per frequency: sum_k P[e_k] (channel mean)
  std::vector<double> lowFractions_;                ///< f_k
  double blurred_ = 0;
  Energies own_;                                    ///< of P[D_G]
  RadialSpectrum ownRadial_;                        ///< P[D_G] binned
  std::vector<TargetState> targets_;
  int count_ = 0;
};

}  // namespace aliaslab
