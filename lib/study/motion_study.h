// A study of aliasing in motion (docs/science.md, "Motion"; measure/motion.h): one scene, F frames of a
// camera moving by (dx, dy) pixels per frame (scene/camera.h frameScreenOffset), every configuration
// (sampler, spp, filter:radius) rendered with K seeds in every frame.
//
// Protocol: fill a MotionStudyConfig (validateMotionStudy() checks it before any work), runMotionStudy()
// renders, for each frame t, the references of every filter and of the pixel-area target T_t (box, r = 0.5)
// with the study's reference renderer (study/reference.h; cached under a content hash that adds the frame's
// camera offset when it is not zero, so frame 0 shares the still study's cache entries), then per
// (sampler, spp) and seed k and frame t one traced sample set, reconstructed with each filter (weighted
// average). Each configuration gives one MotionRow: the motion measures against T (computeMotionMetrics)
// and, per frame against its own G_t and T_t (computeMetrics), blur and noise averaged over the frames and
// frame 0's mse_target (the still image's); and the shimmer against the filter's own references G_t. motionCsv() writes the rows, one per configuration.
#pragma once
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "measure/motion.h"
#include "study/reference.h"
#include "study/study_scene.h"

namespace aliaslab {

struct MotionStudyConfig {
  std::string scene;                        ///< scene file
  int size = 0;                             ///< the longer side in pixels (0: the scene's render line)
  std::vector<std::string> samplers = {"jittered"};
  std::vector<int> spp = {16};
  std::vector<FilterSpec> filters = {{"box", 0.5}, {"gaussian", 1}, {"gaussian", 1.5}, {"gaussian", 2}};
  int seeds = 8;                            ///< K >= 2 (4 or more for shimmer's standard error)
  int frames = 8;                           ///< F >= 2
  double dx = 0.25, dy = 0;                 ///< motion in pixels per frame
  ReferenceOptions reference;               ///< reference renderer options (spp, sampler, threads)
  std::string cache;                        ///< reference cache folder ("" = none)
  int threads = 0;                          ///< 0 = all cores (results do not depend on it)
  bool progress = true;                     ///< progress lines on stderr
};

struct MotionRow {
  std::string scene, sampler, filter;
  int spp = 0;
  double radius = 0;
  MotionMetrics motion;           ///< against the pixel-area target T_t
  MotionMetrics motionFilter;     ///< against the filter's own references G_t (CSV: shimmer_filter, its aliasing in motion)
  double blur = 0, noise = 0;     ///< per frame (against G_t and T_t), averaged over the frames
  double mseTarget = 0, mseTargetSe = 0;  ///< frame 0 (the still image) against T_0
  double dx = 0, dy = 0;
};

/// Points `scene`'s tracer at frame t of a camera moving (dx, dy) pixels per frame: its camera becomes `base`
/// shifted by frameScreenOffset (base must outlive that use), and its content hash (the references' cache key)
/// `baseHash` with the offset added when it is not zero (frame 0 shares the still study's cache entries).
void setMotionFrame(StudyScene& scene, const Camera& base, uint64_t baseHash, int t, double dx, double dy);

/// "dx,dy" (two finite numbers of pixels per frame, at most 1e4 each) -> (dx, dy); OptionError("motion") otherwise.
std::pair<double, double> parseMotion(const std::string& text);

/// "name:radius" -> (name, radius), e.g. "gaussian:1.5"; OptionError("filter") for anything else or an
/// unknown filter name.
FilterSpec parseFilterSpec(const std::string& text);

/// Checks everything before any work (OptionError keyed "frames", "motion", "seeds", "spp", "size",
/// "sampler", "filter", "ref-spp"; InputError for the scene).
void validateMotionStudy(const MotionStudyConfig& config);

/// Runs the study; progress lines go to `log` when config.progress.
std::vector<MotionRow> runMotionStudy(const MotionStudyConfig& config, std::ostream& log);

/// The CSV: a header and one line per row (numbers in %.9g).
std::string motionCsv(const std::vector<MotionRow>& rows);

}  // namespace aliaslab
