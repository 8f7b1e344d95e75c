// One scene of the sweep: the references its rows need, and each row's start.
//
// Protocol: for the rows planRows left to measure (study/sweep_rows.h), sceneReferences loads the references of
// their (filter, radius), of the pixel area and of the target from the cache or renders the missing ones in one
// pass (study/reference.h), then writes the scene's reference manifest and, with images on, reference-area.png
// (with refsOnly it stops after the cache). RowReferences is that set as the rows look it up, with the target
// prepared once for the flip column (read-only, shared by every (seed, row) task). startRows gives each row of a
// group its reference (the area for supersample rows) and its metric and spectrum accumulators, one task per row.
#pragma once
#include <map>
#include <vector>

#include "core/stopwatch.h"
#include "study/config.h"
#include "measure/flip.h"
#include "study/reference.h"
#include "study/study_scene.h"
#include "study/sweep_rows.h"

namespace aliaslab {

/// The references of `specs` (specs[0] the area): cache or one pass, their manifest and reference-area.png.
ReferenceSet sceneReferences(const StudyConfig& config, const StudyScene& scene, const std::vector<FilterSpec>& specs,
                             const ReferenceOptions& options, bool images);

class RowReferences {
 public:
  /// `set` holds the references of `specs` (in that order, kAreaSpec and `target` among them) and outlives this.
  RowReferences(const ReferenceSet& set, const std::vector<FilterSpec>& specs, const FilterSpec& target);
  RowReferences(const RowReferences&) = delete;
  RowReferences& operator=(const RowReferences&) = delete;

  const ReferenceImage& of(const FilterSpec& spec) const { return *of_.at(spec); }
  const ReferenceImage& area() const { return area_; }
  const ReferenceImage& target() const { return target_; }
  const FlipReference& flipTarget() const { return flip_; }

 private:
  std::map<FilterSpec, const ReferenceImage*> of_;
  const ReferenceImage& area_;
  const ReferenceImage& target_;
  const FlipReference flip_;
};

/// Each row's reference and accumulators, one task per row on `threads` threads; returns the phase's time.
PhaseTime startRows(std::vector<PendingRow>& rows, const RowReferences& refs, int threads);

}  // namespace aliaslab
