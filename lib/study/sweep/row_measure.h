// What one configuration measures: its K images against its own reference G and against every target T of the
// study, in one pass over the images.
//
// Protocol: construct with G and the targets (the study's targets in order, then the pixel area when it is not
// one of them, so mse_area is always there), add() the K images in seed order, result() once. The K images are
// held once for all targets (measure/metrics.h MetricAccumulator), and the spectra are taken once per image
// (measure/spectrum.h). Every mean square that holds a reference estimate has that reference's variance
// subtracted; see docs/science.md and measure/metrics.h for the algebra and the standard errors.
#pragma once
#include <memory>
#include <vector>

#include "core/image.h"
#include "measure/metrics.h"
#include "measure/spectrum.h"
#include "study/reference/reference.h"

namespace aliaslab {

/// A configuration's measures: against G and every target (metrics.targets[j], spectrum.targets[j] in the order
/// given to the constructor).
struct RowResult {
  Metrics metrics;
  SpectrumMetrics spectrum;
};

/// The spectra's side of G and the targets, as RowMeasure measures against them.
std::shared_ptr<const SpectrumReference> spectrumReference(const ReferenceImage& own,
                                                           const std::vector<const ReferenceImage*>& targets);

class RowMeasure {
 public:
  /// `own` = G and `targets` are held by pointer and must outlive this.
  RowMeasure(const ReferenceImage& own, const std::vector<const ReferenceImage*>& targets);
  /// The same with the spectra's side of G and the targets made once for every configuration of G
  /// (spectrumReference(own, targets), shared).
  RowMeasure(const ReferenceImage& own, const std::vector<const ReferenceImage*>& targets,
             std::shared_ptr<const SpectrumReference> spectrum);
  ~RowMeasure();
  void add(const Image& image);
  /// Needs at least 2 images.
  RowResult result() const;
  /// Per-pixel noise s^2 (measure/metrics.h).
  Image noiseMap() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace aliaslab
