#include "study/presets.h"

#include "aliaslab_paths.h"
#include "filter/filter.h"
#include "sampling/sampler.h"

namespace aliaslab {

namespace {
constexpr int kFullRefSpp = 8192;

void applyDefaultPreset(StudyConfig& c) {
  c.scenes = {std::string(ALIASLAB_SOURCE_DIR) + "/scenes"};
  c.samplers = {"random",  "uniform", "jittered",
                "sobol",   "pmj02",   "bluenoise",
                "zsobol",  "bluenoise-dither:random", "adaptive-contrast:jittered"};
  c.spp = {4, 16, 64};
  c.filters = {"box", "tent", "gaussian", "mitchell", "lanczos"};
  c.radii = {0.5, 1.0, 2.0};
  c.reconstruction = {"weighted"};
  c.seeds = 8;
  c.refSpp = 512;
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
  c.refSpp = kFullRefSpp;
  c.longSide = 256;
  c.out = "results/study_full";
  c.images = false;
}
}  // namespace

std::vector<std::string> studyPresetNames() { return {"default", "full"}; }

bool applyStudyPreset(const std::string& name, StudyConfig& config) {
  if (name == "default") applyDefaultPreset(config);
  else if (name == "full") applyFullPreset(config);
  else return false;
  return true;
}

}  // namespace aliaslab
