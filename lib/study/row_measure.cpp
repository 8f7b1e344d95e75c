#include "study/row_measure.h"

namespace aliaslab {

namespace {
// A reference as the measures take it: its mean, its half-difference (none: exact) and its filter's radius.
RefEstimate estimate(const ReferenceImage& r) {
  return {&r.image, r.halfDiff.width() > 0 ? &r.halfDiff : nullptr, r.filter.second};
}

std::vector<RefEstimate> estimates(const std::vector<const ReferenceImage*>& refs) {
  std::vector<RefEstimate> out;
  for (const ReferenceImage* r : refs) out.push_back(estimate(*r));
  return out;
}
}  // namespace

struct RowMeasure::State {
  MetricAccumulator metrics;
  SpectrumAccumulator spectrum;
  State(const ReferenceImage& g, const std::vector<const ReferenceImage*>& t)
      : metrics(estimate(g), estimates(t)), spectrum(estimate(g), estimates(t)) {}
};

RowMeasure::RowMeasure(const ReferenceImage& own, const std::vector<const ReferenceImage*>& targets)
    : s_(std::make_unique<State>(own, targets)) {}

RowMeasure::~RowMeasure() = default;

void RowMeasure::add(const Image& image) {
  s_->metrics.add(image);
  s_->spectrum.add(image);
}

RowResult RowMeasure::result() const {
  const Metrics m = s_->metrics.result();
  RowResult r;
  r.mse = m.mse, r.mseSe = m.mseSe, r.aliasing = m.aliasing, r.aliasingSe = m.aliasingSe;
  r.noise = m.noise, r.noiseSe = m.noiseSe, r.psnr = m.psnr, r.refVar = m.refVar;
  r.deterministic = m.deterministic;
  r.spectrum = s_->spectrum.result();
  for (size_t j = 0; j < m.targets.size(); ++j) {
    const TargetMetrics& t = m.targets[j];
    const SpectrumTargetMetrics& st = r.spectrum.targets[j];
    RowTargetResult x;
    x.mseTarget = t.mseTarget, x.mseTargetSe = t.mseTargetSe, x.blur = t.blur, x.blurSe = t.blurSe;
    x.cross = t.cross, x.refVar = t.refVar, x.perSeed = t.perSeed;
    x.blurredMse = st.blurredMse, x.lowfreqError = st.lowfreqError, x.lowfreqErrorSe = st.lowfreqErrorSe;
    r.targets.push_back(std::move(x));
  }
  return r;
}

Image RowMeasure::noiseMap() const { return s_->metrics.noiseMap(); }

}  // namespace aliaslab
