#include "measure/spectrum.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unsupported/Eigen/FFT>

namespace aliaslab {

namespace {
using Complex = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;

/// The unnormalised 2-D DFT of channel c of `image` (minus `subtract` when given), row-major v * W + u, into
/// `out`: a 1-D FFT of every row, then of every column. Columns go through in blocks of kColumns adjacent
/// ones, gathered and scattered a row of the block at a time (whole cache lines instead of one value per
/// line); every FFT sees the same input as a column-by-column loop would give it, so the same bits.
void dft2(const Image& image, const Image* subtract, int c, std::vector<Complex>& out) {
  constexpr int kColumns = 8;
  const int w = image.width(), h = image.height();
  thread_local Eigen::FFT<double> fft;  // keeps its plans (twiddles) per length between calls
  thread_local std::vector<Complex> line, block, blockOut;
  out.resize(static_cast<size_t>(w) * h);
  line.resize(w), block.resize(static_cast<size_t>(kColumns) * h), blockOut.resize(static_cast<size_t>(kColumns) * h);
  const float* a = image.data();
  const float* b = subtract ? subtract->data() : nullptr;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = 3 * (static_cast<size_t>(y) * w + x) + c;
      line[x] = Complex(static_cast<double>(a[i]) - (b ? static_cast<double>(b[i]) : 0.0), 0.0);
    }
    fft.fwd(out.data() + static_cast<size_t>(y) * w, line.data(), w);
  }
  for (int u0 = 0; u0 < w; u0 += kColumns) {
    const int m = std::min(kColumns, w - u0);
    for (int y = 0; y < h; ++y)
      for (int k = 0; k < m; ++k) block[static_cast<size_t>(k) * h + y] = out[static_cast<size_t>(y) * w + u0 + k];
    for (int k = 0; k < m; ++k) fft.fwd(blockOut.data() + static_cast<size_t>(k) * h, block.data() + static_cast<size_t>(k) * h, h);
    for (int v = 0; v < h; ++v)
      for (int k = 0; k < m; ++k) out[static_cast<size_t>(v) * w + u0 + k] = blockOut[static_cast<size_t>(k) * h + v];
  }
}

int binOf(double rho) { return std::min(kSpectrumBins - 1, static_cast<int>(rho / kSpectrumBinWidth)); }

double blurGain(double rho) { return std::exp(-4 * kPi * kPi * kBlurSigma * kBlurSigma * rho * rho); }
}  // namespace

double frequencyRadius(int u, int v, int width, int height) {
  const double fu = (u < (width + 1) / 2 ? u : u - width) / static_cast<double>(width);
  const double fv = (v < (height + 1) / 2 ? v : v - height) / static_cast<double>(height);
  return std::hypot(fu, fv);
}

double RadialSpectrum::total() const {
  double t = 0;
  for (double e : energy) t += e;
  return t;
}

std::vector<double> powerSpectrum(const Image& image) {
  const size_t n = static_cast<size_t>(image.width()) * image.height();
  const double scale = 1.0 / (3.0 * static_cast<double>(n) * static_cast<double>(n));
  std::vector<double> p(n, 0.0);
  std::vector<Complex> e;
  for (int c = 0; c < 3; ++c) {
    dft2(image, nullptr, c, e);
    for (size_t i = 0; i < n; ++i) p[i] += std::norm(e[i]) * scale;
  }
  return p;
}

RadialSpectrum radialSpectrum(const Image& image) {
  RadialSpectrum r;
  const auto p = powerSpectrum(image);
  const int w = image.width(), h = image.height();
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      const int b = binOf(frequencyRadius(u, v, w, h));
      r.energy[b] += p[static_cast<size_t>(v) * w + u], ++r.count[b];
    }
  return r;
}

SpectrumAccumulator::SpectrumAccumulator(const Image& reference)
    : reference_(reference), width_(reference.width()), height_(reference.height()) {
  const size_t n = static_cast<size_t>(width_) * height_;
  radius_.resize(n);
  for (int v = 0; v < height_; ++v)
    for (int u = 0; u < width_; ++u) radius_[static_cast<size_t>(v) * width_ + u] = frequencyRadius(u, v, width_, height_);
  gain_.resize(n);
  for (size_t i = 0; i < n; ++i) gain_[i] = blurGain(radius_[i]);
  sum_.assign(3 * n, Complex(0, 0));
  sumSquares_.assign(n, 0.0);
}

void SpectrumAccumulator::add(const Image& image) {
  if (image.width() != width_ || image.height() != height_)
    throw std::invalid_argument("SpectrumAccumulator::add: image size differs from the reference");
  const size_t n = static_cast<size_t>(width_) * height_;
  const double inv = 1.0 / static_cast<double>(n);
  double low = 0, total = 0, blurred = 0;
  thread_local std::vector<Complex> e;  // reused image after image
  for (int c = 0; c < 3; ++c) {
    dft2(image, &reference_, c, e);
    for (size_t i = 0; i < n; ++i) {
      const Complex z = e[i] * inv;  // P = |z|^2 / 3 for this channel
      const double p = std::norm(z) / 3.0;
      sum_[c * n + i] += z;
      sumSquares_[i] += p;
      total += p;
      if (radius_[i] < kLowFrequencyCutoff) low += p;
      blurred += p * gain_[i];
    }
  }
  lowFractions_.push_back(total > 0 ? low / total : 0.0);
  blurred_ += blurred;
  ++count_;
}

SpectrumMetrics SpectrumAccumulator::result() const {
  if (count_ < 2) throw std::logic_error("SpectrumAccumulator::result needs at least 2 images");
  SpectrumMetrics m;
  m.images = count_;
  const double k = count_;
  double mean = 0;
  for (double f : lowFractions_) mean += f / k;
  double var = 0;
  for (double f : lowFractions_) var += (f - mean) * (f - mean) / (k - 1);
  m.lowfreqError = mean, m.lowfreqErrorSe = std::sqrt(var / k);
  m.blurredMse = blurred_ / k;
  const size_t n = static_cast<size_t>(width_) * height_;
  for (size_t i = 0; i < n; ++i) {
    const int b = binOf(radius_[i]);
    // per channel sum_k |z_k - mean z|^2 = sum_k |z_k|^2 - |sum_k z_k|^2 / K; P takes the channel mean (/3)
    double spread = sumSquares_[i];
    for (int c = 0; c < 3; ++c) spread -= std::norm(sum_[c * n + i]) / 3.0 / k;
    m.error.energy[b] += sumSquares_[i] / k;
    m.noise.energy[b] += std::max(0.0, spread) / (k - 1);
    ++m.error.count[b], ++m.noise.count[b];
  }
  return m;
}

}  // namespace aliaslab
