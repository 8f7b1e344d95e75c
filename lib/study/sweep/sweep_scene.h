// One scene of the sweep: the references its rows need, and each row's start.
//
// Protocol: for the rows planRows left to measure (study/sweep/sweep_rows.h), sceneReferences loads the references of
// their (filter, radius), of the pixel area and of every target from the cache or renders the missing ones in one
// pass (study/reference/reference.h), then writes the scene's reference manifest and, with images on, reference-area.png
// (with refsOnly it stops after the cache). RowReferences is that set as the rows look it up, with each target
// prepared once for the flip column and each G once for the spectra (read-only, shared by every (seed, row) task). startRows gives each
// configuration of a group its reference (the area for supersample rows) and its RowMeasure against the
// measured list (the targets in order, then the area when it is not a target), one task per configuration.
#pragma once
#include <map>
#include <memory>
#include <vector>

#include "core/stopwatch.h"
#include "study/config.h"
#include "measure/flip/flip.h"
#include "study/reference/reference.h"
#include "study/study_scene.h"
#include "study/sweep/sweep_rows.h"

namespace aliaslab {

/// The references of `specs` (specs[0] the area): cache or one pass, their manifest and reference-area.png.
ReferenceSet sceneReferences(const StudyConfig& config, const StudyScene& scene, const std::vector<StudyFilter>& specs,
                             const ReferenceOptions& options, bool images);

/// Writes the manifest of `refs` (rendered for `scene` as it stands) to OUT/references/`name`.
void writeSceneManifest(const StudyConfig& config, const StudyScene& scene, const ReferenceSet& refs,
                        const std::string& name);

class RowReferences {
 public:
  /// `set` holds the references of the area (kAreaSpec) and every target among others, and outlives this.
  RowReferences(const ReferenceSet& set, const std::vector<Target>& targets);
  RowReferences(const RowReferences&) = delete;
  RowReferences& operator=(const RowReferences&) = delete;

  const ReferenceImage& of(const FilterSpec& spec) const { return *of_.at(spec); }
  const ReferenceImage& area() const { return *of_.at(kAreaSpec); }
  /// The targets in order, then the area when it is not one of them: what every RowMeasure measures against.
  const std::vector<const ReferenceImage*>& measured() const { return measured_; }
  /// The area's position in measured().
  size_t areaIndex() const { return areaIndex_; }
  /// Target j prepared for the flip column.
  const FlipReference& flipTarget(size_t j) const { return *flip_[j]; }
  size_t targets() const { return flip_.size(); }
  /// Makes the spectra's side (study/sweep/row_measure.h spectrumReference) of each of `own` not made yet, on `threads`
  /// threads (returns the time it took); called by one thread at a time.
  PhaseTime prepareSpectra(const std::vector<const ReferenceImage*>& own, int threads) const;
  /// The spectra's side of `own` against measured(), made by prepareSpectra (shared by its configurations).
  std::shared_ptr<const SpectrumReference> spectrum(const ReferenceImage& own) const { return spectra_.at(&own); }

 private:
  std::map<FilterSpec, const ReferenceImage*> of_;
  std::vector<const ReferenceImage*> measured_;
  size_t areaIndex_ = 0;
  std::vector<std::unique_ptr<FlipReference>> flip_;
  /// per G: the spectra's side, made once for every group of the scene (prepareSpectra)
  mutable std::map<const ReferenceImage*, std::shared_ptr<const SpectrumReference>> spectra_;
};

/// Each configuration's reference and measures, one task per row on `threads` threads; returns the phase's time.
PhaseTime startRows(std::vector<PendingRow>& rows, const RowReferences& refs, int threads);

}  // namespace aliaslab
