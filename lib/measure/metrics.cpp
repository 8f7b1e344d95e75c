#include "measure/metrics.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "measure/metric_sums.h"
#include "measure/standard_errors.h"

namespace aliaslab {

using metricimpl::productSums;
using metricimpl::scratch;
using metricimpl::TargetSums;
using metricimpl::targetSums;
using metricimpl::Terms;

namespace {
using F4 = float __attribute__((vector_size(16)));
using D4 = double __attribute__((vector_size(32)));

size_t channelCount(const Image& image) { return static_cast<size_t>(image.width()) * image.height() * 3; }

void requireSameSize(const Image& a, const Image& b, const char* what) {
  if (a.width() != b.width() || a.height() != b.height())
    throw std::invalid_argument(std::string(what) + ": image sizes differ");
}

void requireEstimate(const RefEstimate& e, const Image& like, const char* what) {
  if (!e.mean) throw std::invalid_argument(std::string(what) + ": no reference image");
  requireSameSize(*e.mean, like, what);
  if (e.halfDiff) requireSameSize(*e.halfDiff, like, what);
}

/// The value i of a half-difference (0 for an exact reference).
inline double half(const float* d, size_t i) { return d ? static_cast<double>(d[i]) : 0.0; }

/// 4 windowSumVariance(w D) / N^2 as a variance of the mean: x already holds 2 w D.
double referencePart(const std::vector<double>& x, const Image& like, double n, double radius) {
  return windowSumVariance(x, like.width(), like.height(), correlationLag(radius)) / (n * n);
}
}  // namespace

MetricAccumulator::MetricAccumulator(RefEstimate reference, std::vector<RefEstimate> targets)
    : reference_(reference), targets_(std::move(targets)) {
  if (!reference_.mean) throw std::invalid_argument("MetricAccumulator: no reference image");
  requireEstimate(reference_, *reference_.mean, "MetricAccumulator");
  for (const RefEstimate& t : targets_) requireEstimate(t, *reference_.mean, "MetricAccumulator (target)");
  mean_.resize(channelCount(*reference_.mean)), m2_.resize(channelCount(*reference_.mean));  // (uninitialised)
  sseTarget_.resize(targets_.size());
}

void MetricAccumulator::add(const Image& image) {
  requireSameSize(image, *reference_.mean, "MetricAccumulator::add");
  ++count_;
  const float* v = image.data();
  const float* g = reference_.mean->data();
  const size_t n = mean_.size();
  double* mean = mean_.data();
  double* m2 = m2_.data();
  // Welford update per channel, 4 channels at a time: the same operations per element as one at a time. The
  // first image's step from m = m2 = 0 (the buffers are not initialised) is written out: the same operations.
  const double k = count_;
  if (count_ == 1) {
    for (size_t i = 0; i < n; ++i) {
      const double x = v[i], delta = x - 0.0;
      mean[i] = 0.0 + delta / k, m2[i] = 0.0 + delta * (x - mean[i]);
    }
  }
  auto update = [k](auto x, auto& m, auto& s) {
    const auto delta = x - m;
    m += delta / k;
    s += delta * (x - m);
  };
  size_t i = count_ == 1 ? n : 0;
  for (; i + 4 <= n; i += 4) {
    F4 x;
    D4 m, s;
    std::memcpy(&x, v + i, sizeof x), std::memcpy(&m, mean + i, sizeof m), std::memcpy(&s, m2 + i, sizeof s);
    update(__builtin_convertvector(x, D4), m, s);
    std::memcpy(mean + i, &m, sizeof m), std::memcpy(m2 + i, &s, sizeof s);
  }
  for (; i < n; ++i) update(static_cast<double>(v[i]), mean[i], m2[i]);
  // The squared errors against each target, and the products of this image's error against G with every
  // earlier image's (row count_-1 of the Gram matrix C), summed in channel order: one pass over the image for
  // up to four of these sums at a time, each still its own sum in channel order (the same bits).
  std::vector<Terms> terms;
  for (const RefEstimate& t : targets_) terms.push_back({t.mean->data(), v});
  if (!images_.empty()) identical_ = identical_ && std::memcmp(v, images_[0].data(), n * sizeof(float)) == 0;
  images_.push_back(image);
  for (const Image& earlier : images_) terms.push_back({g, earlier.data()});
  std::vector<double> sums(terms.size());
  productSums(v, terms, n, sums.data());
  for (size_t j = 0; j < targets_.size(); ++j) sseTarget_[j].push_back(sums[j]);
  std::vector<double> row(sums.begin() + static_cast<std::ptrdiff_t>(targets_.size()), sums.end());
  gram_.push_back(std::move(row));
}

TargetMetrics MetricAccumulator::targetMetrics(size_t j) const {
  const size_t N = mean_.size();
  const double n = static_cast<double>(N);
  const double k = count_;
  const int K = count_;
  const float* g = reference_.mean->data();
  const float* dg = reference_.halfDiff ? reference_.halfDiff->data() : nullptr;
  const Image& T = *targets_[j].mean;
  const float* t = T.data();
  const float* dt = targets_[j].halfDiff ? targets_[j].halfDiff->data() : nullptr;
  const bool halves = dg || dt;
  // 2 (m - T) D_T and 2 (G - T)(D_G - D_T): reference parts of mse_target, blur (every value written below)
  std::vector<double>& xt = scratch(0, dt ? N : 0);
  std::vector<double>& xb = scratch(1, halves ? N : 0);
  const TargetSums sums = targetSums(mean_.data(), g, t, dg, dt, N, xb.data(), xt.data());
  const double blur = sums.blur, cross = sums.cross, varT = sums.varT, varDelta = sums.varDelta,
               covariance = sums.covariance;
  TargetMetrics tm;
  tm.refVar = varT / n;
  const std::vector<double>& sse = sseTarget_[j];
  double sseSum = 0;
  for (int a = 0; a < K; ++a) sseSum += sse[a];
  tm.mseTarget = sseSum / (n * k) - tm.refVar;
  for (int a = 0; a < K; ++a) tm.perSeed.push_back(sse[a] / n - tm.refVar);
  tm.blur = blur / n - varDelta / n;
  tm.cross = 2 * cross / n + 2 * covariance / n;
  std::vector<double> targetOut(K);
  for (int a = 0; a < K; ++a) targetOut[a] = (sseSum - sse[a]) / (n * (k - 1));
  const double targetSeed = jackknifeSe(targetOut);
  const double refT = dt ? referencePart(xt, T, n, targets_[j].radius) : 0.0;
  tm.mseTargetSe = std::sqrt(targetSeed * targetSeed + refT);
  tm.blurSe = halves ? std::sqrt(referencePart(xb, T, n, std::max(reference_.radius, targets_[j].radius))) : 0.0;
  return tm;
}

Metrics MetricAccumulator::result() const {
  if (count_ < 2) throw std::logic_error("MetricAccumulator::result: needs at least 2 images");
  const size_t N = mean_.size();
  const double n = static_cast<double>(N);
  const double k = count_;
  const int K = count_;
  const Image& G = *reference_.mean;
  const float* g = G.data();
  const float* dg = reference_.halfDiff ? reference_.halfDiff->data() : nullptr;
  double variance = 0, bias2 = 0, varG = 0;
  std::vector<double>& x = scratch(0, dg ? N : 0);  // 2 (m - G) D_G: the reference part of aliasing and mse
  // (locals for the buffers and one loop per case: as members the sums were kept in memory, see metric_sums.h)
  const double* mean = mean_.data();
  const double* m2 = m2_.data();
  double* xs = x.data();
  const double divisor = count_ - 1;
  auto sums = [&](auto withHalves) {
    double s2 = 0, b2 = 0, vg = 0;
    for (size_t i = 0; i < N; ++i) {
      s2 += m2[i] / divisor;
      const double d = mean[i] - g[i];
      b2 += d * d;
      if constexpr (decltype(withHalves)::value) vg += half(dg, i) * half(dg, i), xs[i] = 2 * d * dg[i];
    }
    variance = s2, bias2 = b2, varG = vg;
  };
  if (dg) sums(std::true_type{});
  else sums(std::false_type{});
  const double refG = dg ? referencePart(x, G, n, reference_.radius) : 0.0;
  double trace = 0;
  for (int a = 0; a < K; ++a) trace += gram_[a][a];
  Metrics m;
  m.images = count_;
  m.deterministic = identical_;
  m.refVar = varG / n;
  m.noise = variance / n;
  m.aliasing = bias2 / n - m.noise / count_ - m.refVar;
  m.mse = trace / (n * k) - m.refVar;
  m.psnr = m.mse > 0 ? 10.0 * std::log10(1.0 / m.mse) : std::numeric_limits<double>::infinity();

  // Seed parts. mse is a mean of independent per-seed terms: its leave-one-out jackknife is the classic sd over
  // seeds / sqrt(K). noise and aliasing are means over seed pairs: aliasing = mean over pairs of C_kl / N, noise =
  // mean over pairs of |e_k - e_l|^2 / (2N) = (C_kk + C_ll - 2 C_kl) / (2N).
  std::vector<double> mseOut(K);
  for (int j = 0; j < K; ++j) mseOut[j] = (trace - gram_[j][j]) / (n * (k - 1));
  std::vector<std::vector<double>> aliasingPairs(K), noisePairs(K);
  for (int a = 0; a < K; ++a)
    for (int b = 0; b < a; ++b) {
      aliasingPairs[a].push_back(gram_[a][b] / n);
      noisePairs[a].push_back((gram_[a][a] + gram_[b][b] - 2 * gram_[a][b]) / (2 * n));
    }
  const double mseSeed = jackknifeSe(mseOut), aliasingSeed = pairStatisticSe(aliasingPairs);
  m.mseSe = std::sqrt(mseSeed * mseSeed + refG);
  m.aliasingSe = std::sqrt(aliasingSeed * aliasingSeed + refG);  // NaN stays NaN (K < 4)
  m.noiseSe = pairStatisticSe(noisePairs);

  for (size_t j = 0; j < targets_.size(); ++j) m.targets.push_back(targetMetrics(j));
  return m;
}

Image MetricAccumulator::noiseMap() const {
  Image out(reference_.mean->width(), reference_.mean->height());
  const double k = count_ > 1 ? count_ - 1 : 1;
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) {
      const size_t i = 3 * out.index(x, y);
      const float s2 = static_cast<float>((m2_[i] + m2_[i + 1] + m2_[i + 2]) / (3.0 * k));
      out.set(x, y, Color::Constant(s2));
    }
  return out;
}

Metrics computeMetrics(const std::vector<Image>& images, RefEstimate reference, std::vector<RefEstimate> targets) {
  MetricAccumulator acc(reference, std::move(targets));
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
