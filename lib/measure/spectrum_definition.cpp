// The definition of SpectrumAccumulator's measures (measure/spectrum.h): the accumulator as it was up to the
// shared references and the half-plane transforms, kept for the tests and the benchmark. Every frequency of
// the full W x H plane, one complex FFT per channel and image, and each configuration computing its own
// references' side (the DFTs of G - T and the energies of the half-differences).
#include "measure/spectrum_definition.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "measure/spectrum_dft.h"

namespace aliaslab {

using spectrumimpl::Complex;
using spectrumimpl::dft2;
using spectrumimpl::binOf;
using spectrumimpl::meanAndSe;

SpectrumDefinition::SpectrumDefinition(RefEstimate reference, std::vector<RefEstimate> targets)
    : reference_(reference.mean ? *reference.mean
                                : throw std::invalid_argument("SpectrumDefinition: no reference image")),
      width_(reference_.width()),
      height_(reference_.height()) {
  const size_t n = static_cast<size_t>(width_) * height_;
  radius_.resize(n);
  for (int v = 0; v < height_; ++v)
    for (int u = 0; u < width_; ++u)
      radius_[static_cast<size_t>(v) * width_ + u] = frequencyRadius(u, v, width_, height_);
  gain_.resize(n);
  for (size_t i = 0; i < n; ++i) gain_[i] = blurGain(radius_[i], kBlurSigma);
  curveGain_.resize(n);
  for (size_t i = 0; i < n; ++i)
    for (size_t s = 0; s < kBlurCurve.size(); ++s) curveGain_[i][s] = blurGain(radius_[i], kBlurCurve[s]);
  sum_.assign(3 * n, Complex(0, 0));
  sumSquares_.assign(n, 0.0);
  auto sameSize = [&](const Image* im) {
    if (im && (im->width() != width_ || im->height() != height_))
      throw std::invalid_argument("SpectrumDefinition: reference sizes differ");
  };
  sameSize(reference.halfDiff);
  if (reference.halfDiff) own_ = energies(*reference.halfDiff, &ownRadial_);
  for (const RefEstimate& t : targets) {
    if (!t.mean) throw std::invalid_argument("SpectrumDefinition: no target image");
    sameSize(t.mean), sameSize(t.halfDiff);
    TargetState state;
    state.shift.resize(3 * n);
    std::vector<Complex> e;
    const double inv = 1.0 / static_cast<double>(n);
    for (int c = 0; c < 3; ++c) {  // DFT(G - T) = -DFT(T - G)
      dft2(*t.mean, &reference_, c, e);
      for (size_t i = 0; i < n; ++i) state.shift[c * n + i] = -e[i] * inv;
    }
    if (t.halfDiff) state.halves = energies(*t.halfDiff, nullptr);
    targets_.push_back(std::move(state));
  }
}

SpectrumDefinition::Energies SpectrumDefinition::energies(const Image& image, RadialSpectrum* radial) const {
  const auto p = powerSpectrum(image);
  Energies out;
  for (size_t i = 0; i < p.size(); ++i) {
    out.total += p[i];
    if (radius_[i] < kLowFrequencyCutoff) out.low += p[i];
    out.blurred += p[i] * gain_[i];
    for (size_t s = 0; s < kBlurCurve.size(); ++s) out.curve[s] += p[i] * curveGain_[i][s];
    if (radial) radial->energy[binOf(radius_[i])] += p[i], ++radial->count[binOf(radius_[i])];
  }
  return out;
}

double SpectrumDefinition::share(double low, double total, const Energies& ref) const {
  const double t = total - ref.total;
  return t > 0 ? std::clamp((low - ref.low) / t, 0.0, 1.0) : 0.0;
}

void SpectrumDefinition::add(const Image& image) {
  if (image.width() != width_ || image.height() != height_)
    throw std::invalid_argument("SpectrumDefinition::add: image size differs from the reference");
  const size_t n = static_cast<size_t>(width_) * height_;
  const double inv = 1.0 / static_cast<double>(n);
  double low = 0, total = 0, blurred = 0;
  std::vector<double> lowT(targets_.size(), 0.0), totalT(targets_.size(), 0.0), blurredT(targets_.size(), 0.0);
  std::vector<std::array<double, kBlurCurve.size()>> curveT(targets_.size());
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
    for (size_t j = 0; j < targets_.size(); ++j) {  // I_k - T = e_k + (G - T)
      const Complex* shift = targets_[j].shift.data() + c * n;
      double l = 0, t = 0, b = 0;
      std::array<double, kBlurCurve.size()> cb{};
      for (size_t i = 0; i < n; ++i) {
        const double p = std::norm(e[i] * inv + shift[i]) / 3.0;
        t += p, b += p * gain_[i];
        for (size_t s = 0; s < kBlurCurve.size(); ++s) cb[s] += p * curveGain_[i][s];
        if (radius_[i] < kLowFrequencyCutoff) l += p;
      }
      lowT[j] += l, totalT[j] += t, blurredT[j] += b;
      for (size_t s = 0; s < kBlurCurve.size(); ++s) curveT[j][s] += cb[s];
    }
  }
  lowFractions_.push_back(share(low, total, own_));
  blurred_ += blurred;
  for (size_t j = 0; j < targets_.size(); ++j) {
    targets_[j].lowFractions.push_back(share(lowT[j], totalT[j], targets_[j].halves));
    targets_[j].blurred += blurredT[j];
    const Energies& ref = targets_[j].halves;
    const double t = totalT[j] - ref.total;
    std::array<double, kBlurCurve.size()> r{};
    for (size_t s = 0; s < kBlurCurve.size(); ++s) r[s] = t > 0 ? (curveT[j][s] - ref.curve[s]) / t : 0.0;
    targets_[j].ratios.push_back(r);
  }
  ++count_;
}


SpectrumMetrics SpectrumDefinition::result() const {
  if (count_ < 2) throw std::logic_error("SpectrumDefinition::result needs at least 2 images");
  SpectrumMetrics m;
  m.images = count_;
  const double k = count_;
  std::tie(m.lowfreqError, m.lowfreqErrorSe) = meanAndSe(lowFractions_);
  m.blurredMse = blurred_ / k - own_.blurred;
  for (const TargetState& t : targets_) {
    SpectrumTargetMetrics tm;
    std::tie(tm.lowfreqError, tm.lowfreqErrorSe) = meanAndSe(t.lowFractions);
    tm.blurredMse = t.blurred / k - t.halves.blurred;
    for (size_t s = 0; s < kBlurCurve.size(); ++s) {
      std::vector<double> r;
      for (const auto& x : t.ratios) r.push_back(x[s]);
      std::tie(tm.blurRatio[s], tm.blurRatioSe[s]) = meanAndSe(r);
    }
    m.targets.push_back(tm);
  }
  m.reference = ownRadial_;
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
