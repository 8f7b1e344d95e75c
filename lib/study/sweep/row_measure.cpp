#include "study/sweep/row_measure.h"

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
  State(const ReferenceImage& g, const std::vector<const ReferenceImage*>& t,
        std::shared_ptr<const SpectrumReference> s)
      : metrics(estimate(g), estimates(t)), spectrum(std::move(s)) {}
};

std::shared_ptr<const SpectrumReference> spectrumReference(const ReferenceImage& own,
                                                           const std::vector<const ReferenceImage*>& targets) {
  return std::make_shared<const SpectrumReference>(estimate(own), estimates(targets));
}

RowMeasure::RowMeasure(const ReferenceImage& own, const std::vector<const ReferenceImage*>& targets)
    : RowMeasure(own, targets, spectrumReference(own, targets)) {}

RowMeasure::RowMeasure(const ReferenceImage& own, const std::vector<const ReferenceImage*>& targets,
                       std::shared_ptr<const SpectrumReference> spectrum)
    : s_(std::make_unique<State>(own, targets, std::move(spectrum))) {}

RowMeasure::~RowMeasure() = default;

void RowMeasure::add(const Image& image) {
  s_->metrics.add(image);
  s_->spectrum.add(image);
}

RowResult RowMeasure::result() const { return {s_->metrics.result(), s_->spectrum.result()}; }

Image RowMeasure::noiseMap() const { return s_->metrics.noiseMap(); }

}  // namespace aliaslab
