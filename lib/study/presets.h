// The bundled studies, by name: a preset fills a StudyConfig, and whatever the
// caller sets afterwards (explicit options) overrides it.
//   default:   the quick study (README command (a)): every bundled scene at
//              most 48 px, course and modern samplers and five filters at
//              radii 0.5, 1, 2 and each filter's natural radius; results/study
//              with images (under about 15 minutes on 2 cores,
//              results/study_speed.md).
//   presented: the study results/index.html presents: every bundled scene
//              (the folder scenes/: the analytic patterns, the meshes, the
//              textures, reflection and refraction) at 256 px on the larger
//              side, every sampler and filter at radii 0.5, 1, 2 and each
//              filter's natural radius, no per-configuration images;
//              results/presented (over an hour on 2 cores; shard it,
//              experiments/run_presented_study.sh).
// Both: spp 4, 16, 64, 8 seeds, references at 4096 spp (64 x the highest spp),
// the fixed grid over 8 camera offsets with references at 256 spp
// (study/sweep/alignment.h), and three targets:
// area, gaussian:1.5 (sigma 0.5) and lanczos:3. The quick study is the
// presented one at 48 px with fewer samplers and filters, so the two can be
// reconciled row by row.
#pragma once
#include <string>
#include <vector>

#include "study/config.h"

namespace aliaslab {

/// The preset names, in the order of --help ("default", "presented").
std::vector<std::string> studyPresetNames();

/// What the preset `name` studies, in words computed from the preset itself (scenes and size, samplers,
/// filters, radii, spp, seeds, references, alignment, targets, images, output folder); "" for an unknown name.
std::string describeStudyPreset(const std::string& name);

/// Fills `config` with the preset `name`; returns false (config unchanged) for an unknown name.
bool applyStudyPreset(const std::string& name, StudyConfig& config);

}  // namespace aliaslab
