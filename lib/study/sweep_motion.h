// Frames in the sweep: a study with F > 1 frames of a camera moving (dx, dy) pixels per frame
// (StudyConfig::frames, motionDx, motionDy; docs/science.md "Motion"; measure/motion.h for the measures).
//
// Protocol, per scene: frameReferences() gives, for frames 1 .. F-1, the references of the same (filter, radius)
// list as the scene's still references (frame 0), each frame cached under its own key (study/motion_study.h
// setMotionFrame: the content hash gains the frame's camera offset; frame 0 is the still study's entry).
// Per group, after the still pass (study/sweep_group.h: frame 0 of every seed folded into the rows' RowMeasures
// exactly as in a still study, so the still columns are frame 0's), measureGroupMotion() renders every seed's F
// frames (sampler seed k in every frame; frame 0 again), reconstructs each with every row's filter and mode
// (film/film.h reconstruct; importance rows trace their own), and gives each row its motion columns per target
// of the study (PendingRow::motion, study/csv.h MotionColumns): shimmer and the two flickers against that
// target's T_t, shimmer_filter against the row's own references G_t (the pixel area for supersample rows).
// Memory: a row holds its K x F images until its measures are taken (rows x K x F images per group), and every
// frame's references are held for the scene; validateStudy adds both to the still pass's bound (sweep_memory.h). Threads: seeds and frames in order, each trace and reconstruction
// on every thread; no number depends on the thread count. The scene's camera and content hash are restored.
#pragma once
#include <vector>

#include "render/tracer.h"
#include "study/config.h"
#include "study/reference.h"
#include "study/study_scene.h"
#include "study/sweep_rows.h"

namespace aliaslab {

/// The references of `specs` for frames 1 .. F-1 (element t-1 is frame t), from the cache or rendered.
std::vector<ReferenceSet> frameReferences(const StudyConfig& config, StudyScene& scene,
                                          const std::vector<FilterSpec>& specs, const ReferenceOptions& options);

/// Every frame's references of one scene: `perFrame[t]` (t = 0 .. F-1) holds the references of `specs` in order.
struct MotionReferences {
  std::vector<const ReferenceSet*> perFrame;
  const std::vector<FilterSpec>* specs = nullptr;
};

/// The motion columns of each row of `group` (rows traced with `tracer`, which reads `scene`'s camera).
void measureGroupMotion(const StudyConfig& config, StudyScene& scene, const Tracer& tracer,
                        const SampleSetGroup& group, std::vector<PendingRow>& rows, const MotionReferences& refs,
                        const std::vector<Target>& targets, int threads);

}  // namespace aliaslab
