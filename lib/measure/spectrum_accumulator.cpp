// SpectrumReference and SpectrumAccumulator (measure/spectrum.h): the spectra's measures on the half plane of
// the DFT, the references' side made once and shared.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "measure/spectrum.h"
#include "measure/spectrum_dft.h"

namespace aliaslab {

using spectrumimpl::binOf;
using spectrumimpl::Complex;
using spectrumimpl::halfDft2;
using spectrumimpl::halfWidth;
using spectrumimpl::meanAndSe;

namespace {
/// P / 3 of one channel's normalised coefficient z, added to the energies with the frequency's weights.
inline void addPower(double p, const SpectrumReference::Weights& w, SpectrumReference::Energies& e) {
  e.total += p * w.total, e.low += p * w.low, e.blurred += p * w.blurred;
  for (size_t s = 0; s < kBlurCurve.size(); ++s) e.curve[s] += p * w.curve[s];
}

/// One channel's coefficients e (unnormalised) into the sums of SpectrumAccumulator::add: per frequency z = e /
/// (W H) into the channel's sum of z (set by the first image: SetSum) and P = |z|^2 / 3 into the sum of P (set
/// by the first image's first channel: SetSquares), and P with the frequency's weights into `own`'s total, low
/// and blurred energies. The operations of std::complex written out on the parts (z = (e_re inv, e_im inv),
/// |z|^2 = z_re^2 + z_im^2, sums part by part), the three energies in locals: as std::complex values and
/// members the compiler kept them in memory, a store and a load on every addition.
template <bool SetSum, bool SetSquares>
void ownChannel(const Complex* e, size_t nh, double inv, const SpectrumReference::Weights* w, Complex* channelSum,
                double* squares, SpectrumReference::Energies& own) {
  double total = own.total, low = own.low, blurred = own.blurred;
  double* sum = reinterpret_cast<double*>(channelSum);  // (re, im) pairs, as std::complex is laid out
  for (size_t i = 0; i < nh; ++i) {
    const double zr = e[i].real() * inv, zi = e[i].imag() * inv;
    const double p = (zr * zr + zi * zi) / 3.0;
    sum[2 * i] = SetSum ? zr : sum[2 * i] + zr;
    sum[2 * i + 1] = SetSum ? zi : sum[2 * i + 1] + zi;
    squares[i] = SetSquares ? p : squares[i] + p;
    total += p * w[i].total, low += p * w[i].low, blurred += p * w[i].blurred;
  }
  own.total = total, own.low = low, own.blurred = blurred;
}

double share(double low, double total, const SpectrumReference::Energies& ref) {
  const double t = total - ref.total;
  return t > 0 ? std::clamp((low - ref.low) / t, 0.0, 1.0) : 0.0;
}
}  // namespace

SpectrumReference::SpectrumReference(RefEstimate reference, std::vector<RefEstimate> targets)
    : reference_(reference.mean ? *reference.mean
                                : throw std::invalid_argument("SpectrumAccumulator: no reference image")),
      width_(reference_.width()),
      height_(reference_.height()) {
  const int hw = halfWidth(width_);
  const size_t nh = static_cast<size_t>(hw) * height_;
  weights_.resize(nh), bins_.resize(nh);
  for (int v = 0; v < height_; ++v)
    for (int u = 0; u < hw; ++u) {
      // (u, v) and its mirror (W - u, H - v) are one frequency when u = 0 or u = W / 2 (W even): the mirror is
      // in the half plane itself
      const double m = (u == 0 || 2 * u == width_) ? 1.0 : 2.0;
      const double rho = frequencyRadius(u, v, width_, height_);
      Weights& w = weights_[static_cast<size_t>(v) * hw + u];
      w.total = m, w.low = rho < kLowFrequencyCutoff ? m : 0.0, w.blurred = m * blurGain(rho, kBlurSigma);
      for (size_t s = 0; s < kBlurCurve.size(); ++s) w.curve[s] = m * blurGain(rho, kBlurCurve[s]);
      bins_[static_cast<size_t>(v) * hw + u] = binOf(rho);
    }
  auto sameSize = [&](const Image* im) {
    if (im && (im->width() != width_ || im->height() != height_))
      throw std::invalid_argument("SpectrumAccumulator: reference sizes differ");
  };
  sameSize(reference.halfDiff);
  if (reference.halfDiff) own_ = energies(*reference.halfDiff, &ownRadial_);
  const double inv = 1.0 / (static_cast<double>(width_) * height_);
  for (const RefEstimate& t : targets) {
    if (!t.mean) throw std::invalid_argument("SpectrumAccumulator: no target image");
    sameSize(t.mean), sameSize(t.halfDiff);
    Target state;
    state.shift.resize(3 * nh);
    std::vector<Complex> e;
    for (int c = 0; c < 3; ++c) {  // DFT(G - T) = -DFT(T - G)
      halfDft2(*t.mean, &reference_, c, e);
      for (size_t i = 0; i < nh; ++i) state.shift[c * nh + i] = -e[i] * inv;
    }
    if (t.halfDiff) state.halves = energies(*t.halfDiff, nullptr);
    targets_.push_back(std::move(state));
  }
}

SpectrumReference::Energies SpectrumReference::energies(const Image& image, RadialSpectrum* radial) const {
  const size_t nh = weights_.size();
  const double scale = 1.0 / (3.0 * static_cast<double>(width_) * height_ * static_cast<double>(width_) * height_);
  std::vector<double> p(nh, 0.0);
  std::vector<Complex> e;
  for (int c = 0; c < 3; ++c) {
    halfDft2(image, nullptr, c, e);
    for (size_t i = 0; i < nh; ++i) p[i] += std::norm(e[i]) * scale;
  }
  Energies out;
  for (size_t i = 0; i < nh; ++i) {
    addPower(p[i], weights_[i], out);
    if (radial) radial->energy[bins_[i]] += p[i] * weights_[i].total, radial->count[bins_[i]] += std::lround(weights_[i].total);
  }
  return out;
}

SpectrumAccumulator::SpectrumAccumulator(RefEstimate reference, std::vector<RefEstimate> targets)
    : SpectrumAccumulator(std::make_shared<const SpectrumReference>(reference, std::move(targets))) {}

SpectrumAccumulator::SpectrumAccumulator(std::shared_ptr<const SpectrumReference> reference)
    : ref_(std::move(reference)), targets_(ref_->targets().size()) {}

void SpectrumAccumulator::add(const Image& image) {
  const SpectrumReference& ref = *ref_;
  if (image.width() != ref.width() || image.height() != ref.height())
    throw std::invalid_argument("SpectrumAccumulator::add: image size differs from the reference");
  const size_t nh = ref.frequencies(), T = targets_.size();
  const double inv = 1.0 / (static_cast<double>(ref.width()) * ref.height());
  if (!sum_) sum_.reset(new double[6 * nh]), sumSquares_.reset(new double[nh]);  // written below (count_ == 0)
  const bool first = count_ == 0;
  Complex* sum = reinterpret_cast<Complex*>(sum_.get());
  double* squares = sumSquares_.get();
  const SpectrumReference::Weights* w = ref.weights().data();
  SpectrumReference::Energies own;
  std::vector<SpectrumReference::Energies> against(T);
  thread_local std::vector<Complex> e;  // reused image after image
  for (int c = 0; c < 3; ++c) {
    halfDft2(image, &ref.image(), c, e);
    Complex* channelSum = sum + c * nh;
    if (!first) ownChannel<false, false>(e.data(), nh, inv, w, channelSum, squares, own);
    else if (c == 0) ownChannel<true, true>(e.data(), nh, inv, w, channelSum, squares, own);
    else ownChannel<true, false>(e.data(), nh, inv, w, channelSum, squares, own);
    for (size_t j = 0; j < T; ++j) {  // I_k - T = e_k + (G - T)
      const Complex* shift = ref.targets()[j].shift.data() + c * nh;
      SpectrumReference::Energies t;
      for (size_t i = 0; i < nh; ++i) addPower(std::norm(e[i] * inv + shift[i]) / 3.0, w[i], t);
      SpectrumReference::Energies& a = against[j];
      a.total += t.total, a.low += t.low, a.blurred += t.blurred;
      for (size_t s = 0; s < kBlurCurve.size(); ++s) a.curve[s] += t.curve[s];
    }
  }
  lowFractions_.push_back(share(own.low, own.total, ref.own()));
  blurred_ += own.blurred;
  for (size_t j = 0; j < T; ++j) {
    const SpectrumReference::Energies& halves = ref.targets()[j].halves;
    targets_[j].lowFractions.push_back(share(against[j].low, against[j].total, halves));
    targets_[j].blurred += against[j].blurred;
    const double t = against[j].total - halves.total;
    std::array<double, kBlurCurve.size()> r{};
    for (size_t s = 0; s < kBlurCurve.size(); ++s) r[s] = t > 0 ? (against[j].curve[s] - halves.curve[s]) / t : 0.0;
    targets_[j].ratios.push_back(r);
  }
  ++count_;
}

SpectrumMetrics SpectrumAccumulator::result() const {
  if (count_ < 2) throw std::logic_error("SpectrumAccumulator::result needs at least 2 images");
  const SpectrumReference& ref = *ref_;
  SpectrumMetrics m;
  m.images = count_;
  const double k = count_;
  std::tie(m.lowfreqError, m.lowfreqErrorSe) = meanAndSe(lowFractions_);
  m.blurredMse = blurred_ / k - ref.own().blurred;
  for (size_t j = 0; j < targets_.size(); ++j) {
    const TargetSums& t = targets_[j];
    const SpectrumReference::Energies& halves = ref.targets()[j].halves;
    SpectrumTargetMetrics tm;
    std::tie(tm.lowfreqError, tm.lowfreqErrorSe) = meanAndSe(t.lowFractions);
    tm.blurredMse = t.blurred / k - halves.blurred;
    for (size_t s = 0; s < kBlurCurve.size(); ++s) {
      std::vector<double> r;
      for (const auto& x : t.ratios) r.push_back(x[s]);
      std::tie(tm.blurRatio[s], tm.blurRatioSe[s]) = meanAndSe(r);
    }
    m.targets.push_back(tm);
  }
  m.reference = ref.ownRadial();
  const size_t nh = ref.frequencies();
  const Complex* sum = reinterpret_cast<const Complex*>(sum_.get());
  for (size_t i = 0; i < nh; ++i) {
    const int b = ref.bins()[i];
    const double mult = ref.weights()[i].total;
    // per channel sum_k |z_k - mean z|^2 = sum_k |z_k|^2 - |sum_k z_k|^2 / K; P takes the channel mean (/3)
    double spread = sumSquares_[i];
    for (int c = 0; c < 3; ++c) spread -= std::norm(sum[c * nh + i]) / 3.0 / k;
    m.error.energy[b] += mult * sumSquares_[i] / k;
    m.noise.energy[b] += mult * std::max(0.0, spread) / (k - 1);
    m.error.count[b] += std::lround(mult), m.noise.count[b] += std::lround(mult);
  }
  return m;
}

}  // namespace aliaslab
