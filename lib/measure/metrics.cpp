#include "measure/metrics.h"

#include <cmath>
#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace aliaslab {

namespace {
using F4 = float __attribute__((vector_size(16)));
using D4 = double __attribute__((vector_size(32)));

size_t channelCount(const Image& image) { return static_cast<size_t>(image.width()) * image.height() * 3; }

void requireSameSize(const Image& a, const Image& b, const char* what) {
  if (a.width() != b.width() || a.height() != b.height())
    throw std::invalid_argument(std::string(what) + ": image sizes differ");
}
}  // namespace

MetricAccumulator::MetricAccumulator(const Image& reference, const Image& areaReference, const Image& target)
    : reference_(reference), area_(areaReference), target_(target) {
  requireSameSize(reference, areaReference, "MetricAccumulator");
  requireSameSize(reference, target, "MetricAccumulator (target)");
  mean_.assign(channelCount(reference), 0.0);
  m2_.assign(channelCount(reference), 0.0);
  const float* g = reference.data();
  const float* t = target.data();
  for (size_t i = 0; i < mean_.size(); ++i) {
    const double d = static_cast<double>(g[i]) - t[i];
    blur_ += d * d;
  }
}

void MetricAccumulator::add(const Image& image) {
  requireSameSize(image, reference_, "MetricAccumulator::add");
  ++count_;
  const float* v = image.data();
  const float* g = reference_.data();
  const float* a = area_.data();
  const size_t n = mean_.size();
  double* mean = mean_.data();
  double* m2 = m2_.data();
  // Welford update per channel, 4 channels at a time: the same operations per element as one at a time
  const double k = count_;
  auto update = [k](auto x, auto& m, auto& s) {
    const auto delta = x - m;
    m += delta / k;
    s += delta * (x - m);
  };
  size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    F4 x;
    D4 m, s;
    std::memcpy(&x, v + i, sizeof x), std::memcpy(&m, mean + i, sizeof m), std::memcpy(&s, m2 + i, sizeof s);
    update(__builtin_convertvector(x, D4), m, s);
    std::memcpy(mean + i, &m, sizeof m), std::memcpy(m2 + i, &s, sizeof s);
  }
  for (; i < n; ++i) update(static_cast<double>(v[i]), mean[i], m2[i]);
  // The squared errors against A and T, and the products of this image's error against G with every
  // earlier image's (row count_-1 of the Gram matrix C), summed in channel order. A loop of its own: the
  // running sums are serial and kept the Welford loop from vectorising.
  const float* t = target_.data();
  double sseArea = sseArea_, sseTarget = 0;
  for (size_t i = 0; i < n; ++i) {
    const double x = v[i];
    sseArea += (x - a[i]) * (x - a[i]);
    sseTarget += (x - t[i]) * (x - t[i]);
  }
  sseArea_ = sseArea;
  sseTarget_.push_back(sseTarget);
  images_.push_back(image);
  std::vector<double> row(images_.size(), 0.0);
  for (size_t l = 0; l < images_.size(); ++l) {
    const float* u = images_[l].data();
    double dot = 0;
    for (size_t i = 0; i < n; ++i) dot += (static_cast<double>(v[i]) - g[i]) * (static_cast<double>(u[i]) - g[i]);
    row[l] = dot;
  }
  gram_.push_back(std::move(row));
}

namespace {
// Jackknife standard error from the K leave-one-out values.
double jackknifeSe(const std::vector<double>& leaveOneOut) {
  const double k = static_cast<double>(leaveOneOut.size());
  double mean = 0;
  for (double v : leaveOneOut) mean += v / k;
  double ss = 0;
  for (double v : leaveOneOut) ss += (v - mean) * (v - mean);
  return std::sqrt((k - 1) / k * ss);
}

// Standard error of a degree-2 U-statistic U = mean over seed pairs k < l of h(k, l). Two estimates of Var(U):
// - unbiased (Hoeffding): Var(U) = E[U^2] - theta^2 and theta^2 = E[h(k, l) h(i, j)] for four distinct seeds, so
//   V = U^2 - (mean over pairs of disjoint pairs of h(k, l) h(i, j)), the disjoint sum being S^2 + Q - sum_j R_j^2
//   (S = sum of h over pairs, Q = sum of h^2, R_j = sum over l != j of h(j, l)). It can come out negative.
// - the leave-one-seed-out jackknife V_J, never negative, whose expectation lies between Var(U) and
//   2 (K-1) / (K-2) Var(U) (the upper end when the pair terms share no per-seed part, e.g. zero aliasing).
// The result is sqrt(max(V, V_J (K-2) / (2 (K-1)))): the unbiased value, floored by the jackknife scaled to a
// lower bound in expectation, so a chance negative V does not claim a zero error. h is centred on U first
// (V does not change) so no large terms cancel. Needs K >= 4 (NaN otherwise).
double pairStatisticSe(const std::vector<std::vector<double>>& h) {
  const int K = static_cast<int>(h.size());
  if (K < 4) return std::numeric_limits<double>::quiet_NaN();
  const double pairs = K * (K - 1) / 2.0;
  double u = 0;
  for (int a = 0; a < K; ++a)
    for (int b = 0; b < a; ++b) u += h[a][b] / pairs;
  double s = 0, q = 0, r2 = 0;
  std::vector<double> r(K, 0.0);
  for (int a = 0; a < K; ++a)
    for (int b = 0; b < a; ++b) {
      const double c = h[a][b] - u;
      s += c, q += c * c, r[a] += c, r[b] += c;
    }
  for (double v : r) r2 += v * v;
  const double disjoint = (s * s + q - r2) / (pairs * (K - 2) * (K - 3) / 2.0);
  const double mean = s / pairs;  // 0 up to rounding
  const double unbiased = mean * mean - disjoint;
  std::vector<double> leaveOneOut(K);
  for (int j = 0; j < K; ++j) leaveOneOut[j] = (s - r[j]) / (pairs - (K - 1));
  const double jack = jackknifeSe(leaveOneOut);
  return std::sqrt(std::max(unbiased, jack * jack * (K - 2) / (2.0 * (K - 1))));
}
}  // namespace

Metrics MetricAccumulator::result() const {
  if (count_ < 2) throw std::logic_error("MetricAccumulator::result: needs at least 2 images");
  const double n = static_cast<double>(mean_.size());
  const double k = count_;
  const float* g = reference_.data();
  const float* t = target_.data();
  double variance = 0, bias2 = 0, cross = 0;
  for (size_t i = 0; i < mean_.size(); ++i) {
    variance += m2_[i] / (count_ - 1);
    const double d = mean_[i] - g[i];
    bias2 += d * d;
    cross += d * (static_cast<double>(g[i]) - t[i]);
  }
  // The trace of the Gram matrix and the per-seed target sums.
  const int K = count_;
  double trace = 0, sseTarget = 0;
  for (int a = 0; a < K; ++a) trace += gram_[a][a], sseTarget += sseTarget_[a];
  Metrics m;
  m.images = count_;
  m.noise = variance / n;
  m.aliasing = bias2 / n - m.noise / count_;
  m.mse = trace / (n * k);
  m.mseArea = sseArea_ / (n * k);
  m.mseTarget = sseTarget / (n * k);
  m.blur = blur_ / n;
  m.cross = 2 * cross / n;
  m.psnr = m.mse > 0 ? 10.0 * std::log10(1.0 / m.mse) : std::numeric_limits<double>::infinity();

  // mse and mse_target are means of independent per-seed terms: their leave-one-out jackknife is the classic
  // sd over seeds / sqrt(K). noise and aliasing are means over seed pairs: the unbiased pair variance.
  std::vector<double> mseOut(K), targetOut(K);
  for (int j = 0; j < K; ++j) {
    mseOut[j] = (trace - gram_[j][j]) / (n * (k - 1));
    targetOut[j] = (sseTarget - sseTarget_[j]) / (n * (k - 1));
  }
  m.mseSe = jackknifeSe(mseOut);
  m.mseTargetSe = jackknifeSe(targetOut);
  // aliasing = mean over pairs of C_kl / N; noise = mean over pairs of |e_k - e_l|^2 / (2N) = (C_kk + C_ll - 2 C_kl) / (2N)
  std::vector<std::vector<double>> aliasingPairs(K), noisePairs(K);
  for (int a = 0; a < K; ++a)
    for (int b = 0; b < a; ++b) {
      aliasingPairs[a].push_back(gram_[a][b] / n);
      noisePairs[a].push_back((gram_[a][a] + gram_[b][b] - 2 * gram_[a][b]) / (2 * n));
    }
  m.aliasingSe = pairStatisticSe(aliasingPairs);
  m.noiseSe = pairStatisticSe(noisePairs);
  return m;
}

Image MetricAccumulator::noiseMap() const {
  Image out(reference_.width(), reference_.height());
  const double k = count_ > 1 ? count_ - 1 : 1;
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) {
      const size_t i = 3 * out.index(x, y);
      const float s2 = static_cast<float>((m2_[i] + m2_[i + 1] + m2_[i + 2]) / (3.0 * k));
      out.set(x, y, Color::Constant(s2));
    }
  return out;
}

Metrics computeMetrics(const std::vector<Image>& images, const Image& reference, const Image& areaReference) {
  MetricAccumulator acc(reference, areaReference);
  for (const Image& image : images) acc.add(image);
  return acc.result();
}

Metrics computeMetrics(const std::vector<Image>& images, const Image& reference, const Image& areaReference,
                       const Image& target) {
  MetricAccumulator acc(reference, areaReference, target);
  for (const Image& image : images) acc.add(image);
  return acc.result();
}

double meanSquaredDifference(const Image& a, const Image& b) {
  requireSameSize(a, b, "meanSquaredDifference");
  const size_t n = channelCount(a);
  double sum = 0;
  for (size_t i = 0; i < n; ++i) {
    const double d = static_cast<double>(a.data()[i]) - b.data()[i];
    sum += d * d;
  }
  return n ? sum / n : 0.0;
}

double halvesError(const Image& a, const Image& b) { return meanSquaredDifference(a, b) / 4.0; }

Image halfDifference(const Image& a, const Image& b) {
  requireSameSize(a, b, "halfDifference");
  Image out(a.width(), a.height());
  const size_t n = channelCount(a);
  for (size_t i = 0; i < n; ++i)
    out.data()[i] = static_cast<float>(0.5 * (static_cast<double>(a.data()[i]) - b.data()[i]));
  return out;
}

Image averageImages(const Image& a, const Image& b) {
  requireSameSize(a, b, "averageImages");
  Image out(a.width(), a.height());
  const size_t n = channelCount(a);
  for (size_t i = 0; i < n; ++i)
    out.data()[i] = static_cast<float>(0.5 * (static_cast<double>(a.data()[i]) + b.data()[i]));
  return out;
}

}  // namespace aliaslab
