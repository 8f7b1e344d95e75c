// The definition of the spectra's measures (the slow path the tests and spectrum_bench compare
// SpectrumAccumulator with; docs/spectrum.md, "How it is computed, and its tolerance"): the same protocol and
// results as SpectrumAccumulator (measure/spectrum.h), computed on every frequency of the full plane with one
// complex FFT per channel, each accumulator making its own references' side.
#pragma once
#include <array>
#include <complex>
#include <vector>

#include "measure/spectrum.h"

namespace aliaslab {

class SpectrumDefinition {
 public:
  SpectrumDefinition(RefEstimate reference, std::vector<RefEstimate> targets);
  void add(const Image& image);
  SpectrumMetrics result() const;

 private:
  struct Energies {
    double low = 0, total = 0, blurred = 0;
    std::array<double, kBlurCurve.size()> curve{};
  };
  struct TargetState {
    std::vector<std::complex<double>> shift;
    Energies halves;
    std::vector<double> lowFractions;
    double blurred = 0;
    std::vector<std::array<double, kBlurCurve.size()>> ratios;
  };
  Energies energies(const Image& image, RadialSpectrum* radial) const;
  double share(double low, double total, const Energies& ref) const;

  Image reference_;
  int width_, height_;
  std::vector<double> radius_, gain_;
  std::vector<std::array<double, kBlurCurve.size()>> curveGain_;
  std::vector<std::complex<double>> sum_;
  std::vector<double> sumSquares_;
  std::vector<double> lowFractions_;
  double blurred_ = 0;
  Energies own_;
  RadialSpectrum ownRadial_;
  std::vector<TargetState> targets_;
  int count_ = 0;
};

}  // namespace aliaslab
