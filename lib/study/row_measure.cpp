#include "study/row_measure.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace aliaslab {

// Interim (until measure/metrics.h takes RefEstimates): the per-target terms from one MetricAccumulator against G
// and the area, per-seed sums against each target, one SpectrumAccumulator per distinct reference; the point
// estimates corrected by the references' variance from their half-differences (mean D^2, and mean (D_G - D_T)^2
// for blur); the standard errors are the seeds' only, blur_se NaN.
struct RowMeasure::State {
  const ReferenceImage& own;
  std::vector<const ReferenceImage*> targets;
  MetricAccumulator metrics;
  SpectrumAccumulator spectrum;
  std::vector<std::unique_ptr<SpectrumAccumulator>> targetSpectra;  ///< null where T is G
  std::vector<std::vector<double>> perSeed;                          ///< [target][k]: mean (I_k - T)^2
  Image first;
  bool identical = true;
  int count = 0;

  State(const ReferenceImage& g, const std::vector<const ReferenceImage*>& t, const ReferenceImage& area)
      : own(g), targets(t), metrics(g.image, area.image), spectrum(g.image), perSeed(t.size()) {
    for (const ReferenceImage* r : t)
      targetSpectra.push_back(r == &g ? nullptr : std::make_unique<SpectrumAccumulator>(r->image));
  }
};

namespace {
// mean over values of (a - b)^2 (b null: of a^2), in double.
double meanSquare(const Image& a, const Image* b = nullptr) {
  const size_t n = size_t(a.width()) * a.height() * 3;
  double sum = 0;
  for (size_t i = 0; i < n; ++i) {
    const double d = double(a.data()[i]) - (b ? double(b->data()[i]) : 0.0);
    sum += d * d;
  }
  return n ? sum / double(n) : 0.0;
}

const ReferenceImage& areaOf(const std::vector<const ReferenceImage*>& targets) {
  for (const ReferenceImage* r : targets)
    if (r->filter == FilterSpec{"box", 0.5}) return *r;
  return *targets.front();
}
}  // namespace

RowMeasure::RowMeasure(const ReferenceImage& own, const std::vector<const ReferenceImage*>& targets)
    : s_(std::make_unique<State>(own, targets, areaOf(targets))) {}

RowMeasure::~RowMeasure() = default;

void RowMeasure::add(const Image& image) {
  State& s = *s_;
  s.metrics.add(image);
  s.spectrum.add(image);
  for (size_t j = 0; j < s.targets.size(); ++j) {
    s.perSeed[j].push_back(meanSquaredDifference(image, s.targets[j]->image));
    if (s.targetSpectra[j]) s.targetSpectra[j]->add(image);
  }
  if (s.count++ == 0) s.first = image;
  else if (s.identical)
    s.identical = image.width() == s.first.width() && image.height() == s.first.height() &&
                  std::memcmp(image.data(), s.first.data(), size_t(image.width()) * image.height() * 3 * sizeof(float)) == 0;
}

RowResult RowMeasure::result() const {
  const State& s = *s_;
  const Metrics m = s.metrics.result();
  RowResult r;
  r.refVar = meanSquare(s.own.halfDiff);
  r.mse = m.mse - r.refVar, r.mseSe = m.mseSe;
  r.aliasing = m.aliasing - r.refVar, r.aliasingSe = m.aliasingSe;
  r.noise = m.noise, r.noiseSe = m.noiseSe;
  r.psnr = r.mse > 0 ? 10 * std::log10(1 / r.mse) : std::numeric_limits<double>::infinity();
  r.deterministic = s.identical;
  r.spectrum = s.spectrum.result();
  const int K = s.count;
  for (size_t j = 0; j < s.targets.size(); ++j) {
    const ReferenceImage& t = *s.targets[j];
    RowTargetResult x;
    x.refVar = meanSquare(t.halfDiff);
    double sum = 0, sq = 0;
    for (double v : s.perSeed[j]) {
      x.perSeed.push_back(v - x.refVar);
      sum += v - x.refVar;
    }
    x.mseTarget = sum / K;
    for (double v : x.perSeed) sq += (v - x.mseTarget) * (v - x.mseTarget);
    x.mseTargetSe = s.identical ? 0.0 : K > 1 ? std::sqrt(sq / (K - 1) / K) : std::numeric_limits<double>::quiet_NaN();
    const bool same = &t == &s.own;
    x.blur = same ? 0.0 : meanSquaredDifference(s.own.image, t.image) - meanSquare(s.own.halfDiff, &t.halfDiff);
    x.blurSe = same ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    x.cross = same ? 0.0 : x.mseTarget - r.noise - r.aliasing - x.blur;
    const SpectrumMetrics sm = s.targetSpectra[j] ? s.targetSpectra[j]->result() : r.spectrum;
    x.blurredMse = sm.blurredMse, x.lowfreqError = sm.lowfreqError, x.lowfreqErrorSe = sm.lowfreqErrorSe;
    r.targets.push_back(std::move(x));
  }
  return r;
}

Image RowMeasure::noiseMap() const { return s_->metrics.noiseMap(); }

}  // namespace aliaslab
