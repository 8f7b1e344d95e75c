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
#include "study/reference.h"

namespace aliaslab {

/// The terms against one target T.
struct RowTargetResult {
  double mseTarget = 0, mseTargetSe = 0;  ///< corrected: mean_k mean (I_k - T)^2 - mean Var T
  double blur = 0, blurSe = 0;            ///< mean (G - T)^2 - mean Var(G - T)
  double cross = 0;                       ///< mse_target - noise - aliasing - blur
  double refVar = 0;                      ///< mean Var T (target_ref_error)
  std::vector<double> perSeed;            ///< per seed: corrected mse_target of image k (mean = mseTarget)
  double blurredMse = 0, lowfreqError = 0, lowfreqErrorSe = 0;  ///< spectrum measures of I_k - T
};

struct RowResult {
  double mse = 0, mseSe = 0, aliasing = 0, aliasingSe = 0, noise = 0, noiseSe = 0, psnr = 0;  ///< against G
  double refVar = 0;          ///< mean Var G (ref_error)
  bool deterministic = false;  ///< the K images identical bit for bit
  std::vector<RowTargetResult> targets;  ///< in the order given to the constructor
  SpectrumMetrics spectrum;   ///< against G (the spectrum files; lowfreq/blurred _own)
};

class RowMeasure {
 public:
  /// `own` = G and `targets` are held by pointer and must outlive this.
  RowMeasure(const ReferenceImage& own, const std::vector<const ReferenceImage*>& targets);
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
