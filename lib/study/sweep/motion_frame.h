// A study's frames (study/sweep/sweep_motion.h, docs/science.md "Motion"): the camera of frame t and the motion
// option's value.
#pragma once
#include <cstdint>
#include <string>
#include <utility>

#include "scene/camera.h"
#include "study/study_scene.h"

namespace aliaslab {

/// Points `scene`'s tracer at frame t of a camera moving (dx, dy) pixels per frame: its camera becomes `base`
/// shifted by frameScreenOffset (base must outlive that use), and its content hash (the references' cache key)
/// `baseHash` with the offset added when it is not zero (frame 0 shares the still study's cache entries).
void setMotionFrame(StudyScene& scene, const Camera& base, uint64_t baseHash, int t, double dx, double dy);

/// "dx,dy" (two finite numbers of pixels per frame, at most 1e4 each) -> (dx, dy); OptionError("motion") otherwise.
std::pair<double, double> parseMotion(const std::string& text);

}  // namespace aliaslab
