// Frames in the sweep: a study with F > 1 frames of a camera moving (dx, dy) pixels per frame
// (StudyConfig::frames, motionDx, motionDy; docs/science.md "Motion"; measure/motion.h for the measures).
// `sweep --frames F --motion dx,dy` is the one motion driver.
//
// Protocol, per scene: frameReferences() gives, for frames 1 .. F-1, the references of the study's targets,
// each frame cached under its own key (study/sweep/motion_frame.h setMotionFrame: the content hash gains the frame's
// camera offset; frame 0 is the still study's entry). Per group, after the still pass (study/sweep/sweep_group.h:
// frame 0 of every seed folded into the rows' RowMeasures exactly as in a still study, so the still columns are
// frame 0's, and kept in PendingRow::frame0), measureGroupMotion() renders every seed's frames 1 .. F-1 (sampler
// seed k in every frame; frame 0 is the still pass's, traced once), reconstructs each with every row's filter and mode (film/film.h reconstruct; importance rows trace
// their own), and gives each row its motion columns per target of the study (PendingRow::motion, study/records/csv.h
// MotionColumns): shimmer and the two flickers of the row's frames registered to the content (no target
// enters; the same in each target's line), and the target's own registered shimmer.
// Memory: a row holds its K x F images until its measures are taken (rows x K x F images per group), and every
// frame's target references are held for the scene; validateStudy adds both to the still pass's bound
// (sweep_memory.h). Threads: seeds and frames in order, each trace and reconstruction on every thread; no
// number depends on the thread count. The scene's camera and content hash are restored.
#pragma once
#include <vector>

#include "render/tracer.h"
#include "study/config.h"
#include "study/reference/reference.h"
#include "study/study_scene.h"
#include "study/sweep/sweep_rows.h"

namespace aliaslab {

/// The references of `specs` for frames 1 .. F-1 (element t-1 is frame t), from the cache or rendered.
std::vector<ReferenceSet> frameReferences(const StudyConfig& config, StudyScene& scene,
                                          const std::vector<StudyFilter>& specs, const ReferenceOptions& options);

/// Every target's references over the frames: targetShimmer[i] is target i's registered shimmer (measure/motion.h
/// targetShimmer), computed once per scene.
struct MotionReferences {
  std::vector<double> targetShimmer;
};

/// The targets' shimmer from frame 0's references (`still`, holding every target's) and the later frames' (`later`,
/// from frameReferences with the targets' filters).
MotionReferences motionReferences(const StudyConfig& config, const ReferenceSet& still,
                                  const std::vector<ReferenceSet>& later, const std::vector<Target>& targets);

/// The motion columns of each row of `group` (rows traced with `tracer`, which reads `scene`'s camera).
void measureGroupMotion(const StudyConfig& config, StudyScene& scene, const Tracer& tracer,
                        const SampleSetGroup& group, std::vector<PendingRow>& rows, const MotionReferences& refs,
                        const std::vector<Target>& targets, int threads);

}  // namespace aliaslab
