// The bundled studies, by name: a preset fills a StudyConfig, and whatever the
// caller sets afterwards (explicit options) overrides it.
//   default: the quick study (README command (a)): every bundled scene at most
//            48 px, course and modern samplers and filters, radii 0.5, 1, 2,
//            spp 4, 16, 64, 8 seeds, references at 4096 spp (64 x the highest
//            spp), images on; results/study (under 15 minutes on 2 cores,
//            results/study_speed.md).
//   presented: the study results/index.html presents: `full` on 5 scenes
//            (zoneplate, siemens, checker_horizon, fence, sinc) at radii 0.5,
//            1, 2; results/presented; about 45 minutes on 2 cores.
//   full:    every scene at 256 px on the larger side, every sampler and
//            filter (uniform-shifted among them), radii 0.5, 1, 1.5, 2, spp 4,
//            16, 64, 8 seeds, references at 4096 spp, no per-configuration
//            images; results/study_full. Hours on 2 cores: run it sharded.
// Both measure against three targets: area, gaussian:1.5 (sigma 0.5) and lanczos:3.
#pragma once
#include <string>
#include <vector>

#include "study/config.h"

namespace aliaslab {

/// The preset names, in the order of --help ("default", "presented", "full").
std::vector<std::string> studyPresetNames();

/// Fills `config` with the preset `name`; returns false (config unchanged) for an unknown name.
bool applyStudyPreset(const std::string& name, StudyConfig& config);

}  // namespace aliaslab
