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

// The fixed grid over 8 seeded sub-pixel camera offsets (as many as the seeds), each judged against the targets
// rendered there at kAlignRefSpp samples per pixel (docs/science.md "The grid and alignment" says why that many).
constexpr int kAlignOffsets = 8;
constexpr int kAlignRefSpp = 256;

// What both studies share: the bundled scenes (the folder), spp, seeds, references, targets, the radii 0.5, 1, 2
// and each filter's natural radius, the grid's alignment.
void applyCommon(StudyConfig& c) {
  c.scenes = {std::string(ALIASLAB_SOURCE_DIR) + "/scenes"};
  c.spp = {4, 16, 64};
  c.radii = {0.5, 1.0, 2.0};
  c.naturalRadii = true;
  c.reconstruction = {"weighted"};
  c.seeds = 8;
  c.refSpp = kRefSpp;
  c.targets = kTargets;
  c.alignOffsets = kAlignOffsets;
  c.alignRefSpp = kAlignRefSpp;
}

void applyDefaultPreset(StudyConfig& c) {
  applyCommon(c);
  c.samplers = {"random",  "uniform", "uniform-shifted", "jittered",
                "sobol",   "pmj02",   "bluenoise",
                "zsobol",  "bluenoise-dither:random", "adaptive-contrast:jittered"};
  c.filters = {"box", "tent", "gaussian", "mitchell", "lanczos"};
  c.maxSize = 48;
  c.out = "results/study";
  c.images = true;
}

// The study results/index.html presents: every bundled scene at 256 px on the larger side, every per-pixel sampler
// and every study filter. No per-configuration images: 10 scenes x ~1,000 configurations at 256 px would be
// gigabytes, and the report picks its images after the run (the viewer renders them, analysis/viewer).
void applyPresentedPreset(StudyConfig& c) {
  applyCommon(c);
  c.samplers = samplerNames();
  c.filters = filterNames();
  c.longSide = 256;
  c.out = "results/presented";
  c.images = false;
}
}  // namespace

std::vector<std::string> studyPresetNames() { return {"default", "presented"}; }

std::string describeStudyPreset(const std::string& name) {
  StudyConfig c;
  if (!applyStudyPreset(name, c)) return {};
  auto list = [](const std::vector<std::string>& values) {
    std::string s;
    for (const std::string& v : values) s += (s.empty() ? "" : ",") + v;
    return s;
  };
  std::vector<std::string> spp;
  for (int n : c.spp) spp.push_back(std::to_string(n));
  const bool allSamplers = c.samplers == samplerNames(), allFilters = c.filters == filterNames();
  const std::string size = c.longSide > 0 ? "at " + std::to_string(c.longSide) + " px on the larger side"
                                          : "scaled to at most " + std::to_string(c.maxSize) + " px on the larger side";
  return "every bundled scene " + size + ", " +
         (allSamplers ? "every sampler (" + std::to_string(c.samplers.size()) + ")" : "the samplers " + list(c.samplers)) +
         ", " + (allFilters ? "every filter (" + std::to_string(c.filters.size()) + ")" : "the filters " + list(c.filters)) +
         " at radii " + list(studyRadiusTokens(c)) + ", spp " + list(spp) + ", " + std::to_string(c.seeds) +
         " seeds, references at " + std::to_string(c.refSpp) + " spp, the fixed grid at " +
         std::to_string(c.alignOffsets) + " camera offsets (references at " + std::to_string(c.alignRefSpp) +
         " spp), the targets " + list(c.targets) + ", " + (c.images.value_or(false) ? "with" : "no") +
         " per-configuration images, into " + c.out;
}

bool applyStudyPreset(const std::string& name, StudyConfig& config) {
  if (name == "default") applyDefaultPreset(config);
  else if (name == "presented") applyPresentedPreset(config);
  else return false;
  return true;
}

}  // namespace aliaslab
