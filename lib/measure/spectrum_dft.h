// Private to lib/measure's spectra (spectrum*.cpp): the 2-D DFTs of one channel of an image, and two helpers.
//
// dft2 is the full W x H transform, the definition's: a complex FFT of every row, then of every column.
// halfDft2 is the same transform of a real image on the half plane u = 0 .. W/2 (halfWidth(W) columns; the
// rest follows from E(W - u, H - v) = conj E(u, v)): rows are transformed two at a time as one complex FFT of
// (row y) + i (row y + 1) and separated, then only the half plane's columns are transformed: about half the
// work, the same values up to rounding (spectrum.h states the tolerance).
#pragma once
#include <algorithm>
#include <cmath>
#include <complex>
#include <utility>
#include <vector>

#include "core/image.h"
#include "measure/spectrum.h"

namespace aliaslab::spectrumimpl {

using Complex = std::complex<double>;

/// The radial bin of frequency radius rho (the last bin takes the corners).
inline int binOf(double rho) { return std::min(kSpectrumBins - 1, static_cast<int>(rho / kSpectrumBinWidth)); }

/// The mean of per-seed values and its standard error over the seeds.
inline std::pair<double, double> meanAndSe(const std::vector<double>& f) {
  const double k = static_cast<double>(f.size());
  double mean = 0;
  for (double v : f) mean += v / k;
  double var = 0;
  for (double v : f) var += (v - mean) * (v - mean) / (k - 1);
  return {mean, std::sqrt(var / k)};
}

/// Columns of the half plane of a W-wide transform: W / 2 + 1.
inline int halfWidth(int width) { return width / 2 + 1; }

/// The unnormalised DFT of channel c of `image` (minus `subtract` when given), row-major v * W + u, into `out`.
void dft2(const Image& image, const Image* subtract, int c, std::vector<Complex>& out);

/// The same on the half plane: out[v * halfWidth(W) + u] for u = 0 .. W / 2.
void halfDft2(const Image& image, const Image* subtract, int c, std::vector<Complex>& out);

}  // namespace aliaslab::spectrumimpl
