#include "study/presets.h"

#include "aliaslab_paths.h"
#include "filter/filter.h"
#include "sampling/sampler.h"

namespace aliaslab {

namespace {
// References at 64 x the highest spp of the study (64 spp): what remains of their error is subtracted
// (measure/metrics.h) and enters the standard errors. The rule that chooses it (docs/science.md, "Choosing the
// reference spp"): the smallest power of two at which, among the highest-spp rows, three in four have a
// reference part of se^2 at most a quarter of the seed part. On the presented study 4096 gives 0.745 (2048:
// 0.67), so it is not lowered (tests/bench/ref_spp_rule.py prints the shares of a study).
constexpr int kRefSpp = 4096;
// The targets of both studies: the pixel area, the Gaussian at its natural width (sigma = r/3 = 0.5) and the
// band-limited Lanczos-windowed sinc whose sinc zeros fall on integer pixels (r = 3).
const std::vector<std::string> kTargets = {"area", "gaussian:1.5", "lanczos:3"};

void applyDefaultPreset(StudyConfig& c) {
  c.scenes = {std::string(ALIASLAB_SOURCE_DIR) + "/scenes"};
  c.samplers = {"random",  "uniform", "uniform-shifted", "jittered",
                "sobol",   "pmj02",   "bluenoise",
                "zsobol",  "bluenoise-dither:random", "adaptive-contrast:jittered"};
  c.spp = {4, 16, 64};
  c.filters = {"box", "tent", "gaussian", "mitchell", "lanczos"};
  c.radii = {0.5, 1.0, 2.0};
  c.reconstruction = {"weighted"};
  c.seeds = 8;
  c.refSpp = kRefSpp;
  c.targets = kTargets;
  c.maxSize = 48;
  c.out = "results/study";
  c.images = true;
}

void applyFullPreset(StudyConfig& c) {
  c.scenes = {std::string(ALIASLAB_SOURCE_DIR) + "/scenes"};
  c.samplers = samplerNames();
  c.spp = {4, 16, 64};
  c.filters = filterNames();
  c.radii = {0.5, 1.0, 1.5, 2.0};
  c.reconstruction = {"weighted"};
  c.seeds = 8;
  c.refSpp = kRefSpp;
  c.targets = kTargets;
  c.longSide = 256;
  c.out = "results/study_full";
  // No per-configuration images: 10 scenes x ~2000 configurations at 256 px would be gigabytes, and the report
  // picks its images after the run (best and worst per scene); it says so where they are missing.
  c.images = false;
}

// The study results/index.html presents: the full study's samplers, filters, spp, seeds, references and targets
// at 256 px, on the five scenes whose content is the question (zone plate, Siemens star, checkerboard to the
// horizon, fence, and the band-limited sinc as the control), at radii 0.5, 1, 2. Its cost is the reconstruction
// (every sample splatted into 24 (filter, radius) pairs at 64 spp), about 8 minutes per scene on 2 cores
// (results/study_speed.md); the full preset runs all ten scenes at four radii.
void applyPresentedPreset(StudyConfig& c) {
  applyFullPreset(c);
  const std::string s = std::string(ALIASLAB_SOURCE_DIR) + "/scenes/";
  c.scenes = {s + "zoneplate.txt", s + "siemens.txt", s + "checker_horizon.txt", s + "fence.txt", s + "sinc.txt"};
  c.radii = {0.5, 1.0, 2.0};
  c.out = "results/presented";
}
}  // namespace

std::vector<std::string> studyPresetNames() { return {"default", "presented", "full"}; }

bool applyStudyPreset(const std::string& name, StudyConfig& config) {
  if (name == "default") applyDefaultPreset(config);
  else if (name == "presented") applyPresentedPreset(config);
  else if (name == "full") applyFullPreset(config);
  else return false;
  return true;
}

}  // namespace aliaslab
