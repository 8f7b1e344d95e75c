#include "study/metrics.h"

#include <cmath>
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

MetricAccumulator::MetricAccumulator(const Image& reference, const Image& areaReference)
    : reference_(reference), area_(areaReference) {
  requireSameSize(reference, areaReference, "MetricAccumulator");
  mean_.assign(channelCount(reference), 0.0);
  m2_.assign(channelCount(reference), 0.0);
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
  // the squared errors against G and A, summed in channel order (a loop of its own: the running sums
  // are serial and kept the Welford loop from vectorising)
  double sseRef = sseRef_, sseArea = sseArea_;
  for (size_t i = 0; i < n; ++i) {
    const double x = v[i];
    sseRef += (x - g[i]) * (x - g[i]);
    sseArea += (x - a[i]) * (x - a[i]);
  }
  sseRef_ = sseRef, sseArea_ = sseArea;
}

Metrics MetricAccumulator::result() const {
  if (count_ < 2) throw std::logic_error("MetricAccumulator::result: needs at least 2 images");
  const double n = static_cast<double>(mean_.size());
  const float* g = reference_.data();
  double variance = 0, bias2 = 0;
  for (size_t i = 0; i < mean_.size(); ++i) {
    variance += m2_[i] / (count_ - 1);
    const double d = mean_[i] - g[i];
    bias2 += d * d;
  }
  Metrics m;
  m.images = count_;
  m.noise = variance / n;
  m.aliasing = bias2 / n - m.noise / count_;
  m.mse = sseRef_ / (n * count_);
  m.mseArea = sseArea_ / (n * count_);
  m.psnr = m.mse > 0 ? 10.0 * std::log10(1.0 / m.mse) : std::numeric_limits<double>::infinity();
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

Image averageImages(const Image& a, const Image& b) {
  requireSameSize(a, b, "averageImages");
  Image out(a.width(), a.height());
  const size_t n = channelCount(a);
  for (size_t i = 0; i < n; ++i)
    out.data()[i] = static_cast<float>(0.5 * (static_cast<double>(a.data()[i]) + b.data()[i]));
  return out;
}

}  // namespace aliaslab
