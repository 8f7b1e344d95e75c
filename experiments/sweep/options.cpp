#include "options.h"

#include "common/cli.h"
#include "study/presets.h"

namespace aliaslab {

void addSweepOptions(CLI::App& app, SweepArgs& a) {
  a.radii = studyRadiusTokens(a.c);
  app.set_config("--config", "", "read options from a TOML/INI file (keys = long option names)");
  std::string presets;
  for (const std::string& name : studyPresetNames())
    presets += (presets.empty() ? "'" : "; '") + name + "': " + describeStudyPreset(name);
  app.add_option("--preset", a.preset,
                 "a bundled study (docs/science.md \"The bundled studies\"), its options applied first so that "
                 "explicit options override them: " + presets + " (the presented study takes over an hour on 2 "
                 "cores: experiments/run_presented_study.sh shards it)")
      ->check(CLI::IsMember(studyPresetNames()));
  app.add_option("--scenes", a.c.scenes, "scene files or folders of *.txt")->delimiter(',');
  app.add_option("--samplers", a.c.samplers, "sampler names")->delimiter(',')->capture_default_str();
  app.add_option("--spp", a.c.spp, "samples per pixel list")->delimiter(',')->capture_default_str();
  app.add_option("--filters", a.c.filters, "filter names")->delimiter(',')->capture_default_str();
  app.add_option("--radii", a.radii,
                 "filter radii in pixels, and 'natural': every filter also at its own natural radius (box 0.5, "
                 "tent 1, gaussian 1.5, mitchell, catmullrom and blackmanharris 2, lanczos and hann 3), each "
                 "(filter, radius) once; box also gets its classic 0.5")
      ->delimiter(',')->capture_default_str();
  app.add_option("--reconstruction", a.c.reconstruction, "weighted|classic|importance|supersample")
      ->delimiter(',')->capture_default_str();
  app.add_option("--prefilter", a.c.prefilter,
                 "none|footprint: texture pre-filtering over each hit's pixel footprint, crossed with the rest "
                 "(references stay un-prefiltered; docs/prefiltering.md)")
      ->delimiter(',')->capture_default_str();
  app.add_option("--seeds", a.c.seeds, "K independent seeds per configuration (>= 2)")->capture_default_str();
  app.add_option("--ref-spp", a.c.refSpp, "reference samples per pixel")->capture_default_str();
  app.add_option("--ref-sampler", a.c.refSampler, "reference sampler")->capture_default_str();
  app.add_option("--size", a.size, "W H: image size for every scene (default: each scene's # render: line)")
      ->expected(2);
  app.add_option("--max-size", a.c.maxSize, "scale scenes down so the larger side is at most this (0 = off)")
      ->capture_default_str();
  app.add_option("--long-side", a.c.longSide,
                 "scale scenes up or down so the larger side is exactly this (0 = off; overrides --max-size)")
      ->capture_default_str();
  app.add_option("--target", a.c.targets,
                 "the targets T of mse_target, blur, cross, blurred_mse and lowfreq_error, a comma list (first = "
                 "primary; one CSV row per configuration and target): 'area' (the pixel-area reference, box r=0.5, "
                 "written box:0.5) or filter:radius, e.g. gaussian:1.5 or lanczos:3; each is another reference "
                 "rendered and cached with the others (definitions: docs/science.md)")
      ->delimiter(',')->capture_default_str();
  app.add_option("--frames", a.c.frames,
                 "F frames of a moving camera per configuration and seed (1: a still study; F > 1 adds the CSV's "
                 "motion columns: shimmer and flicker, docs/science.md \"Motion\")")
      ->capture_default_str();
  app.add_option("--motion", a.motion, "dx,dy: the camera's motion in pixels per frame (with --frames; default 0.25,0)");
  app.add_option("--align-offsets", a.c.alignOffsets,
                 "K: the fixed grid (sampler uniform) also measured over K seeded sub-pixel camera offsets, each "
                 "against the targets rendered at that offset (CSV columns align_*; 0 = off; docs/science.md \"The "
                 "grid and alignment\")")
      ->capture_default_str();
  app.add_option("--align-ref-spp", a.c.alignRefSpp, "samples per pixel of the references at each alignment offset")
      ->capture_default_str();
  app.add_option("--out", a.c.out, "output folder (CSV, images, reference manifests)")->capture_default_str();
  app.add_option("--csv", a.c.csv, "CSV path (default OUT/study.csv, or OUT/study.csv.gz when only that exists, or "
                 "OUT/study.shard-i-of-N.csv); a name ending in .gz is written gzipped");
  app.add_option("--cache", a.c.cache, "reference cache folder")->capture_default_str();
  app.add_option("--threads", a.c.threads, "worker threads (0 = all cores)")->capture_default_str();
  app.add_flag("--images", a.imagesOn, "write images (default: when the study has at most 200 configurations)");
  app.add_flag("--no-images", a.imagesOff, "write no images");
  app.add_option("--shard", a.shard, "i/N, i = 0..N-1: run the groups g with g mod N == i");
  app.add_flag("--refs-only", a.c.refsOnly, "render and cache the references, then stop");
  app.add_flag("--quiet", a.quiet, "no progress output");
  app.add_option("--merge", a.merge, "merge the shard CSVs IN1 IN2 ... into OUT in canonical order, then stop")
      ->expected(2, -1)->option_text("OUT IN1 [IN2 ...]");
}

std::string commandLinePreset(int argc, char** argv) {
  CLI::App app;
  SweepArgs probe;
  setupCommandLine(app, "sweep");
  addSweepOptions(app, probe);
  if (!commandLineConfigProblem(app, argc, argv).empty()) return {};  // (a FIFO would block): the real parse says
  try {
    app.parse(argc, argv);
  } catch (const CLI::Error&) {  // --help, --version or a mistake: the real parse answers; the preset is read
  }                              // before CLI11 acts on help or on options left over (its callbacks run first)
  return probe.preset;
}

}  // namespace aliaslab
