// reference: high-sample ground truth of one scene for every filter x every
// radius plus the pixel-area reference (box r = 0.5), in one streamed pass
// (lib/study/reference/reference.h). Writes one EXR per filter and
// manifest.json into --out; with --cache the references are also looked up
// in / stored into the sweep's cache. Bad input (options, scene files)
// exits 2 before any work, like the sweep; a failure during work exits 1.
//
//   reference --scene scenes/zoneplate.txt --filters box,tent,gaussian --radii 0.5,1,2
//             --spp 4096 --out results/refs/zoneplate
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "common/cli.h"
#include "common/front_end.h"
#include "core/error.h"
#include "core/files.h"
#include "core/memory_limit.h"
#include "study/config.h"
#include "study/reference/manifest.h"
#include "study/reference/reference.h"
#include "study/validate.h"
#include "study/study_scene.h"

using namespace aliaslab;
namespace fs = std::filesystem;

namespace {
// The library's keys in this program's flags (the reference options are the sweep's ref-* ones).
const FrontEnd kReference{"reference",
                          {{"ref-spp", "--spp"},     {"ref-batch", "--batch"}, {"sampler", "--sampler"},
                           {"filter", "--filters"},  {"radius", "--radii"},    {"filter-param", "--filters"},
                           {"size", "--size"},       {"out", "--out"},         {"cache", "--cache"},
                           {"threads", "--threads"}, {"spp", "--spp"},      {"grid", "-grid"}}};
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"reference: streamed high-sample references with error estimates (aliaslab)"};
  setupCommandLine(app, "reference");
  std::string scenePath, out = "results/refs", cache;
  std::vector<std::string> filters = {"box", "tent", "gaussian"};
  std::vector<double> radii = {0.5, 1.0, 1.5};
  std::vector<int> size;
  ReferenceOptions o;  // spp: kDefaultReferenceSpp, as the sweep's --ref-spp
  app.add_option("--scene", scenePath, "scene file")->required();
  app.add_option("--filters", filters, "filter names")->delimiter(',')->capture_default_str();
  app.add_option("--radii", radii, "radii in pixels (every filter x every radius)")->delimiter(',')->capture_default_str();
  app.add_option("--size", size, "W H (default: the scene's # render: line)")->expected(2)->type_name("INT");
  app.add_option("--spp", o.spp, "samples per pixel in total: even, two halves of whole batches (the error estimate)")
      ->capture_default_str();
  app.add_option("--sampler", o.sampler, "scrambled low-discrepancy sampler")->capture_default_str();
  app.add_option("--seed", o.seed, "base seed of the batch scrambles")->check(kSeed)->capture_default_str();
  app.add_option("--batch", o.batchSpp, "samples per pixel per streamed batch")->capture_default_str();
  app.add_option("--threads", o.threads, "worker threads (0 = all cores)")->capture_default_str();
  app.add_option("--out", out, "output folder for EXR images and manifest.json")->capture_default_str();
  app.add_option("--cache", cache, "also use / fill this reference cache folder");
  if (const int rc = parseCommandLine(app, argc, argv, "reference"); rc >= 0) return rc;

  return runFrontEnd(kReference, [&] {
    // Validate everything before work (kReference names the keys by this program's options).
    validateReferenceOptions(o);
    if (o.threads < 0) throw OptionError("--threads", "must be >= 0");
    if (filters.empty()) throw OptionError("--filters", "needs at least one filter");
    if (radii.empty()) throw OptionError("--radii", "needs at least one radius");
    requireRegularFile(scenePath, "a scene is read from a regular file");
    if (!fs::is_regular_file(scenePath)) throw FileError(scenePath, "scene file not found");
    if (!size.empty() && (size[0] <= 0 || size[1] <= 0))
      throw OptionError("--size", "expected two positive numbers W H, found " + std::to_string(size[0]) + " " +
                                      std::to_string(size[1]) + " (leave --size out for the scene's own size)");
    FilterCache made;  // each (filter, radius) built once; the factory names the valid filters
    std::vector<StudyFilter> specs{made.get(kAreaSpec)};
    for (const std::string& f : filters)
      for (double r : radii) addFilterOnce(specs, made.get({f, r}));
    const auto scene = loadStudyScene(scenePath, size.empty() ? 0 : size[0], size.empty() ? 0 : size[1]);
    requireMemory(referenceMemoryBytes(scene->width, scene->height, specs.size(), o), "--size",
                  scene->stem + " at " + std::to_string(scene->width) + " x " + std::to_string(scene->height) + " with " +
                      std::to_string(specs.size()) + " references");
    // No output may be an input: the images and manifest must not replace the scene file.
    std::vector<OutputFile> outputs{{"--out", (fs::path(out) / "manifest.json").string()}};
    for (const StudyFilter& f : specs) {
      const FilterSpec& s = f.spec;
      char radius[32];
      std::snprintf(radius, sizeof radius, "%g", s.second);
      outputs.push_back({"--out", (fs::path(out) / (scene->stem + "-" + s.first + "-r" + radius + ".exr")).string()});
    }
    std::vector<std::string> inputs = scene->scene.dependencies;  // the scene file and its OBJ files
    inputs.push_back(scenePath);
    refuseOutputsOverInputs(outputs, inputs);
    std::vector<std::pair<std::string, std::string>> folders{{out, "out"}};
    if (!cache.empty()) folders.emplace_back(cache, "cache");
    requireOutputFolders(folders);

    // One pass (or the cache), then images and the manifest.
    const ReferenceSet set = cache.empty() ? renderReferences(*scene, specs, o) : cachedReferences(*scene, specs, o, cache);
    std::vector<std::string> names;
    for (const ReferenceImage& r : set.images) {
      char radius[32];
      std::snprintf(radius, sizeof radius, "%g", r.filter.second);
      names.push_back(scene->stem + "-" + r.filter.first + "-r" + radius + ".exr");
      writeImage((fs::path(out) / names.back()).string(), r.image);
      std::printf("%-40s ref_error %.3g\n", r.describe.c_str(), r.error);
    }
    writeTextFile((fs::path(out) / "manifest.json").string(), referenceManifest(*scene, set, names));
    std::printf("%zu references of %s at %dx%d, %d spp, in %.1f s (accumulators %.1f MB) -> %s\n", set.images.size(),
                scene->stem.c_str(), scene->width, scene->height, set.spp, set.seconds, set.accumulatorBytes / 1e6,
                out.c_str());
    return 0;
  });
}
